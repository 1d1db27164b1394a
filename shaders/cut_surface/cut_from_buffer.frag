#version 450 core
// Jump flooding's cut (jump_flood.comp CUT_OUT: stored depth t in [0, 1] per pixel, rows bottom to
// top, in an R32F image buffer, gl/float_image_buffer.h) into the cut depth image, on devices
// where this pass is cheaper than a pixel transfer from the buffer (BufferedCutWrite,
// src/cutaway/cut_surface/gpu_cone_transform.h: NVIDIA's driver, not llvmpipe).
layout(r32f, binding = 0) uniform readonly imageBuffer cut_in;
uniform int width;  // pixels per row

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    gl_FragDepth = imageLoad(cut_in, p.y * width + p.x).r;
}
