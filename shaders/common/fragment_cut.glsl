// The cut sample of the fragment being drawn (fragment shaders; needs common/cut_lookup.glsl),
// from its interpolated clip position and depth in the cut camera (common/face_varyings.glsl).
// Variant CUT_CAMERA_IS_VIEW (the cut was made from the model camera, a perspective one): the
// fragment's cut texel is its own pixel and its depth along the camera's axis is its clip w, so
// neither varying is read and the linker drops them with the world position (8 fewer floats to
// set up per triangle and to interpolate per fragment: stage 2 noticeably faster on sapphire at
// 1920x1080, alternating runs). Every stage-2 program decides the cut the same way, so the
// visible and all-faces paths still keep the same fragments.
CutSample fragment_cut(vec4 cut_clip, float cut_eye_depth) {
#ifdef CUT_CAMERA_IS_VIEW
    return cut_at_texel(ivec2(gl_FragCoord.xy), 1.0 / gl_FragCoord.w, true);
#else
    return cut_from_clip(cut_clip, cut_eye_depth);
#endif
}
