#version 450 core
// Cut surface targets from a strategy's depth image: the world normal (facing the camera) and
// depth s per pixel, and where the cut is clamped in front of the rear shell unless the frame is
// see-through (src/cutaway/rear_shell_depth.h). A compute pass over image buffers
// (gl/float_image_buffer.h, src/cutaway/cut_surface/cut_resolve.cpp). The normal comes from the
// neighbours' world positions on the smoother side of each axis, so a wall's edge does not bend it.
layout(local_size_x = 64, local_size_y = 4) in;

layout(r32f, binding = 0) uniform readonly imageBuffer cut_depth;         // (s - near) / (far - near), 0 = nothing cut
layout(r32f, binding = 1) uniform readonly imageBuffer rear_shell_depth;  // the same encoding: the farthest shell face, 0 = none
layout(rgba32f, binding = 2) uniform writeonly image2D surface;           // world normal, depth s (0: no cut)
layout(r8, binding = 3) uniform writeonly image2D rear_clamp;             // 1: clamped at the rear shell
uniform bool clamp_to_rear_shell;
uniform float rear_margin;       // render units in front of the rear shell
// The cut camera's ray through window position w, scaled to unit depth along its axis, in world
// space: ray_origin + w.x * ray_per_px[0] + w.y * ray_per_px[1] (affine in w). A point at depth s
// on it lies at the camera's position + s * ray: a few multiply-adds where the inverse view matrix
// and two divisions per point took most of this pass (on llvmpipe, sapphire at 1920x1080: 18-20
// ms against 25-26; 16-17 once pixels without a cut were no longer stored).
uniform vec3 ray_origin;
uniform vec3 ray_per_px[2];
uniform ivec2 cut_size;          // pixels
uniform float cut_near;          // cut camera near plane
uniform float cut_far;           // cut camera far plane

vec3 cut_ray(vec2 window) { return ray_origin + window.x * ray_per_px[0] + window.y * ray_per_px[1]; }

float stored_to_depth(float stored) { return stored > 0.0 ? cut_near + stored * (cut_far - cut_near) : 0.0; }

int index_of(ivec2 texel) { return texel.y * cut_size.x + texel.x; }

float strategy_depth(ivec2 texel) { return stored_to_depth(imageLoad(cut_depth, index_of(texel)).r); }

/// The cut's depth s at a texel, kept rear_margin in front of the rear shell; 0 outside the image.
float depth_of(ivec2 texel) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, cut_size))) return 0.0;
    float s = strategy_depth(texel);
    if (clamp_to_rear_shell && s > 0.0) {
        float rear = stored_to_depth(imageLoad(rear_shell_depth, index_of(texel)).r);
        if (rear > 0.0) s = min(s, rear - rear_margin);
    }
    return s;
}

// One pixel's targets from the clamped depths around it: its own `s` and its neighbours ahead and
// behind along x and y (0: none), and the strategy's own depth there (for the clamp flag).
void resolve_pixel(ivec2 texel, float s, float x_ahead, float x_behind, float y_ahead, float y_behind, float strategy) {
    if (s <= 0.0) return;  // CutTargets::clear left 0 in both targets (cut_resolve.h)
    vec3 ray = cut_ray(vec2(texel) + 0.5);
    vec3 tangent[2];
    for (int axis = 0; axis < 2; ++axis) {
        float ahead = axis == 0 ? x_ahead : y_ahead, behind = axis == 0 ? x_behind : y_behind;
        bool use_ahead = ahead > 0.0 && (behind <= 0.0 || abs(ahead - s) <= abs(behind - s));
        float other = use_ahead ? ahead : behind;
        float direction = use_ahead ? 1.0 : -1.0;
        // The neighbour's point minus this one (the camera position cancels), towards +axis.
        vec3 other_ray = ray + direction * ray_per_px[axis];
        tangent[axis] = other > 0.0 ? (other * other_ray - s * ray) * direction : vec3(0.0);
    }
    vec3 normal = cross(tangent[0], tangent[1]);
    normal = dot(normal, normal) > 0.0 ? normalize(normal) : normalize(-ray);  // towards the camera
    if (dot(normal, ray) > 0.0) normal = -normal;  // facing the camera
    imageStore(surface, texel, vec4(normal, s));
    // The cut here is the clamp at the rear shell, not the strategy's surface (stage 2 draws no
    // border lines against it: common/cut_lookup.glsl).
    imageStore(rear_clamp, texel, vec4(s < strategy ? 1.0 : 0.0));
}

#ifdef QUADS
// 4 horizontally adjacent pixels per invocation, the depth images read through their rgba32f
// views (gl::FloatImageBuffer::bind_quad_image; the width a multiple of 4): 10 image loads for 4
// pixels instead of 44, the same arithmetic per pixel.
layout(rgba32f, binding = 4) uniform readonly imageBuffer cut_depth_quads;
layout(rgba32f, binding = 5) uniform readonly imageBuffer rear_shell_quads;

vec4 stored_to_depth(vec4 stored) {
    return vec4(stored_to_depth(stored.x), stored_to_depth(stored.y), stored_to_depth(stored.z), stored_to_depth(stored.w));
}

// depth_of for the 4 pixels of quad `quad` (x: which 4 pixels of row y); `strategy`: their
// strategy depths.
vec4 quad_depth_of(ivec2 quad, out vec4 strategy) {
    int quads = cut_size.x / 4;
    bool inside = quad.x >= 0 && quad.x < quads && quad.y >= 0 && quad.y < cut_size.y;
    int index = clamp(quad.y, 0, cut_size.y - 1) * quads + clamp(quad.x, 0, quads - 1);
    strategy = stored_to_depth(imageLoad(cut_depth_quads, index));
    vec4 s = strategy;
    if (clamp_to_rear_shell) {
        vec4 rear = stored_to_depth(imageLoad(rear_shell_quads, index));
        for (int i = 0; i < 4; ++i)
            if (s[i] > 0.0 && rear[i] > 0.0) s[i] = min(s[i], rear[i] - rear_margin);
    }
    return inside ? s : vec4(0.0);
}

void main() {
    ivec2 quad = ivec2(gl_GlobalInvocationID.xy);
    if (quad.x >= cut_size.x / 4 || quad.y >= cut_size.y) return;
    vec4 strategy, unused;
    vec4 row = quad_depth_of(quad, strategy);
    vec4 left = quad_depth_of(quad - ivec2(1, 0), unused), right = quad_depth_of(quad + ivec2(1, 0), unused);
    vec4 above = quad_depth_of(quad + ivec2(0, 1), unused), below = quad_depth_of(quad - ivec2(0, 1), unused);
    for (int i = 0; i < 4; ++i)
        resolve_pixel(ivec2(4 * quad.x + i, quad.y), row[i], i < 3 ? row[i + 1] : right.x, i > 0 ? row[i - 1] : left.w,
                      above[i], below[i], strategy[i]);
}
#else
void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, cut_size))) return;
    resolve_pixel(texel, depth_of(texel), depth_of(texel + ivec2(1, 0)), depth_of(texel - ivec2(1, 0)),
                  depth_of(texel + ivec2(0, 1)), depth_of(texel - ivec2(0, 1)), strategy_depth(texel));
}
#endif
