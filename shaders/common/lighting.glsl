// The scene's headlight, shared by cells (common/shading.glsl) and well tubes (primary/well.frag).
#include "common/cameras.glsl"  // the headlight: at eye_position, the model camera

vec3 lit(vec3 colour, vec3 normal, vec3 world) {
    vec3 to_light = normalize(eye_position - world);
    float diffuse = abs(dot(normalize(normal), to_light));
    return colour * (0.35 + 0.65 * diffuse);
}
