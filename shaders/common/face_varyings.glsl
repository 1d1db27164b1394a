// Members of the FaceVaryings block the face vertex shader hands to the fragment shaders. Each
// member llvmpipe interpolates costs set-up work for every triangle, which is most of stage 2's
// cost per face (with the rasteriser switched off the vertex shader alone took 4 of the 12-18 ms
// of petra's nearest-face pass at 320x180), so the variants leave out what their fragments do not
// read: PLAIN_FRAME (no cut), NEAREST_FACE_ONLY (secondary/nearest_face.frag: the face index, and
// the point only for VIEW_REAR_SHELL), CUT_CAMERA_IS_VIEW (the cut's pixel and depth are the
// fragment's own: common/cut_of_fragment.glsl).
#if !defined(NEAREST_FACE_ONLY) || defined(VIEW_REAR_SHELL)
vec3 world_position;               // render space
#endif
#ifndef NEAREST_FACE_ONLY
flat vec3 face_normal;             // outward, render space, unit
flat uint compact_cell;            // index into the per-active-cell buffers
flat uint face_info;               // bits 0-1 face class, bit 2 back-facing (seen from inside)
noperspective vec4 edge_distance;  // window pixels to the quad's 4 edges
#endif
#ifndef PLAIN_FRAME  // the plain frame reads no cut
#ifndef CUT_CAMERA_IS_VIEW
vec4 cut_clip;                     // clip position in the cut camera (affine in world: exact)
float cut_eye_depth;               // depth along the cut camera's view axis
#endif
flat uint face_index;              // 1 + the face's index in the drawn face buffer (secondary/nearest_face.frag)
#endif
