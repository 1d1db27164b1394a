// Writes the cut surface targets from a depth s at this pixel (every strategy ends here):
// RGBA32F normal (world space, facing the cut camera) + depth, and RGBA32F world position.
uniform mat4 inverse_cut_view;
uniform vec2 projection_scale;   // P[0][0], P[1][1] of the cut camera
uniform vec2 cut_size;           // pixels

layout(location = 0) out vec4 out_cut;
layout(location = 1) out vec4 out_position;

vec3 cut_world_position(vec2 window, float s) {
    vec2 ndc = window / cut_size * 2.0 - 1.0;
    vec3 eye = vec3(ndc / projection_scale * s, -s);
    return (inverse_cut_view * vec4(eye, 1.0)).xyz;
}

void write_cut(float s) {
    vec3 world = cut_world_position(gl_FragCoord.xy, s);
    vec3 normal = cross(dFdx(world), dFdy(world));
    vec3 camera = (inverse_cut_view * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    normal = dot(normal, normal) > 0.0 ? normalize(normal) : normalize(camera - world);
    if (dot(normal, camera - world) < 0.0) normal = -normal;
    out_cut = vec4(normal, s);
    out_position = vec4(world, 1.0);
}
