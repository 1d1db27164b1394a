// Members of the FaceVaryings block the face vertex shader hands to the fragment shaders.
vec3 world_position;               // render space
flat vec3 face_normal;             // outward, render space, unit
flat uint compact_cell;            // index into the per-active-cell buffers
flat uint face_info;               // bits 0-1 face class, bit 2 back-facing (seen from inside)
noperspective vec4 edge_distance;  // window pixels to the quad's 4 edges
#ifndef PLAIN_FRAME  // the plain frame reads no cut: fewer varyings to set up per triangle
vec4 cut_clip;                     // clip position in the cut camera (affine in world: exact)
float cut_eye_depth;               // depth along the cut camera's view axis
flat uint face_index;              // 1 + the face's index in the drawn face buffer (secondary/nearest_face.frag)
#endif
