#version 450 core
// Screen-space ambient occlusion in the style of Shanmugam & Arikan 2007: SAMPLES points in a
// disc of world radius `radius` around each pixel, rebuilt from linear depth; each occludes by
// how much it lies above the pixel's tangent plane, with distance falloff. Works on every
// surface of the frame, the cut fill included (its normals are the cut surface's).
uniform sampler2D normal_depth;  // eye-space normal, linear depth (0 = background)
uniform vec2 projection_scale;   // P[0][0], P[1][1]
uniform vec2 viewport_size;
uniform float radius;            // render units
uniform float strength;

layout(location = 0) out float out_ambient;

vec3 eye_position(vec2 window, float depth) {
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    return vec3(ndc / projection_scale * depth, -depth);
}

void main() {
    vec4 here = texelFetch(normal_depth, ivec2(gl_FragCoord.xy), 0);
    if (here.a <= 0.0) { out_ambient = 1.0; return; }
    vec3 position = eye_position(gl_FragCoord.xy, here.a);
    vec3 normal = normalize(here.xyz);
    float radius_px = radius * projection_scale.y * 0.5 * viewport_size.y / here.a;
    // Per-pixel rotation of a fixed spiral (interleaved gradient noise) hides banding.
    float angle0 = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    float occlusion = 0.0;
    for (int k = 0; k < SAMPLES; ++k) {
        float t = (float(k) + 0.5) / float(SAMPLES);
        float angle = angle0 + 2.3999632 * float(k);  // golden angle spiral
        vec2 offset = radius_px * sqrt(t) * vec2(cos(angle), sin(angle));
        ivec2 texel = ivec2(gl_FragCoord.xy + offset);
        if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(viewport_size)))) continue;
        float depth = texelFetch(normal_depth, texel, 0).a;
        if (depth <= 0.0) continue;
        vec3 d = eye_position(vec2(texel) + 0.5, depth) - position;
        float distance2 = dot(d, d);
        occlusion += max(dot(normal, d) / sqrt(distance2 + 1e-12) - 0.05, 0.0) / (1.0 + distance2 / (radius * radius));
    }
    out_ambient = clamp(1.0 - strength * occlusion / float(SAMPLES), 0.0, 1.0);
}
