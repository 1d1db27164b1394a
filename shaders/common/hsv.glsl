// RGB <-> HSV (Sam Hocevar's branch-free form) and a saturation scale: the saturation contrast
// (post/composite.comp) and the colour bar's halves under it (post/colour_bar.frag).
#ifndef CUTAWAY_HSV_GLSL
#define CUTAWAY_HSV_GLSL
vec3 rgb_to_hsv(vec3 c) {
    vec4 K = vec4(0.0, -1.0 / 3.0, 2.0 / 3.0, -1.0);
    vec4 p = mix(vec4(c.bg, K.wz), vec4(c.gb, K.xy), step(c.b, c.g));
    vec4 q = mix(vec4(p.xyw, c.r), vec4(c.r, p.yzx), step(p.x, c.r));
    float d = q.x - min(q.w, q.y);
    return vec3(abs(q.z + (q.w - q.y) / (6.0 * d + 1e-10)), d / (q.x + 1e-10), q.x);
}

vec3 hsv_to_rgb(vec3 c) {
    vec3 p = abs(fract(c.xxx + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
    return c.z * mix(vec3(1.0), clamp(p - 1.0, 0.0, 1.0), c.y);
}

// `colour` with its saturation times `factor` (clamped to 1).
vec3 scale_saturation(vec3 colour, float factor) {
    vec3 hsv = rgb_to_hsv(colour);
    hsv.y = clamp(hsv.y * factor, 0.0, 1.0);
    return hsv_to_rgb(hsv);
}
#endif
