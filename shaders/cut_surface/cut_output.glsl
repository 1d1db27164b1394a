// The cut surface from its depth image (every strategy writes depth (s - near) / (far - near)
// along the cut camera's axis, 0 = nothing cut): the normal from the neighbours' world positions
// on the smoother side of each axis (so a wall's edge does not bend it), and whether the cut is
// clamped at the rear shell (0 here; cut_surface/resolve.frag sets it).
uniform mat4 inverse_cut_view;
uniform vec2 projection_scale;   // P[0][0], P[1][1] of the cut camera
uniform vec2 cut_size;           // pixels
uniform float cut_near;          // cut camera near plane
uniform float cut_far;           // cut camera far plane

layout(location = 0) out vec4 out_cut;       // world normal (facing the camera), depth s (0: no cut)
layout(location = 1) out float out_rear_clamp;  // 1: clamped at the rear shell

vec3 cut_world_position(vec2 window, float s) {
    vec2 ndc = window / cut_size * 2.0 - 1.0;
    vec3 eye = vec3(ndc / projection_scale * s, -s);
    return (inverse_cut_view * vec4(eye, 1.0)).xyz;
}

float stored_to_depth(float stored) { return stored > 0.0 ? cut_near + stored * (cut_far - cut_near) : 0.0; }

/// Writes both targets at this pixel from the depth image `depth_of(texel)` (a function each
/// user defines before including this file).
void write_cut(ivec2 texel, float s) {
    if (s <= 0.0) {
        out_cut = vec4(0.0);
        out_rear_clamp = 0.0;
        return;
    }
    vec3 world = cut_world_position(vec2(texel) + 0.5, s);
    vec3 tangent[2];
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        float ahead = depth_of(texel + step), behind = depth_of(texel - step);
        bool use_ahead = ahead > 0.0 && (behind <= 0.0 || abs(ahead - s) <= abs(behind - s));
        float other = use_ahead ? ahead : behind;
        ivec2 other_texel = use_ahead ? texel + step : texel - step;
        tangent[axis] = other > 0.0 ? (cut_world_position(vec2(other_texel) + 0.5, other) - world) * (use_ahead ? 1.0 : -1.0)
                                    : vec3(0.0);
    }
    vec3 camera = (inverse_cut_view * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    vec3 normal = cross(tangent[0], tangent[1]);
    normal = dot(normal, normal) > 0.0 ? normalize(normal) : normalize(camera - world);
    if (dot(normal, camera - world) < 0.0) normal = -normal;
    out_cut = vec4(normal, s);
    out_rear_clamp = 0.0;
}
