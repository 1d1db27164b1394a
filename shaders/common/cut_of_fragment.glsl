// The cut sample (common/cut_lookup.glsl) of a face fragment of stage 2; include after the
// FaceVaryings block `v_in`. Variant CUT_CAMERA_IS_VIEW (the view is not frozen): the cut camera
// is the model camera, so the fragment's cut pixel is its own and its depth along the view axis
// is the clip w, 1 / gl_FragCoord.w, with no varyings to interpolate.
CutSample cut_of_fragment() {
#ifdef CUT_CAMERA_IS_VIEW
    CutSample s;
    s.texel = ivec2(gl_FragCoord.xy);
    s.fragment_depth = 1.0 / gl_FragCoord.w;
    s.cut_depth = texelFetch(cut_surface, s.texel, 0).a;
    return s;
#else
    return cut_from_clip(v_in.cut_clip, v_in.cut_eye_depth);
#endif
}
