#version 450 core
// The cut's world normal at each cut pixel (common/cut_lookup.glsl cut_normal_at), stored for
// stage 2's one-pass shading (the paper's path, --draw all-faces, and --stage2-passes 1 or 2),
// whose fragment shader would otherwise rebuild it for every fragment seen from inside its cell:
// sapphire's all-faces stage 2 at 1920x1080 was slower so than with the normals read
// (src/cutaway/secondary_pass.cpp). The deferred shading rebuilds it once per
// pixel instead. Pixels without a cut are left as they were: nothing reads them.
layout(local_size_x = 64, local_size_y = 4) in;
#define CUT_IMAGES
#include "common/cut_lookup.glsl"

layout(rgba32f, binding = img_cut_normals) uniform writeonly image2D cut_normals;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(cut_size))) || cut_surface_depth(texel) <= 0.0) return;
    imageStore(cut_normals, texel, vec4(cut_normal_at(texel), 0.0));
}
