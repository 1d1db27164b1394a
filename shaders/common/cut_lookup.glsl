// The cut surface as stage 2 reads it: R32F depth along the cut camera's view axis (0 = nothing
// cut), src/cutaway/frame_targets.h CutTargets::surface. The cut camera is the model camera
// unless the view is frozen, so every fragment is projected into the cut camera's image (as in
// shadow mapping). The cut's normal is rebuilt from the depths where a pixel shows cut fill
// (cut_normal_at), not stored: stage 2's per-fragment test reads a 4-byte texel instead of 16.
// Variant CUT_IMAGES (compute passes): the cut surface and its rear-clamp mask read as images,
// whose loads cost less than texel fetches on llvmpipe (deferred shading with ray-cast borders,
// sapphire at 1920x1080, alternating runs, the same image).
#include "common/shared_constants.h"
#ifdef CUT_IMAGES
layout(r32f, binding = img_cut_surface) uniform readonly image2D cut_surface_image;
float cut_surface_depth(ivec2 texel) { return imageLoad(cut_surface_image, texel).r; }
#else
uniform sampler2D cut_surface;   // R32F, cut camera's image
float cut_surface_depth(ivec2 texel) { return texelFetch(cut_surface, texel, 0).r; }
#endif
#include "common/cameras.glsl"  // CutCamera: cut_view, cut_projection, cut_size, cut rays

struct CutSample {
    ivec2 texel;            // cut image pixel (may be outside the image)
    float fragment_depth;   // depth of the point along the cut camera's view axis
    float cut_depth;        // the cut surface's depth at that pixel (0: no cut)
};

// A point at depth `eye_depth` along the cut camera's axis seen at cut pixel `texel`; `in_front`:
// the point is in front of the cut camera (a point behind it meets no cut).
CutSample cut_at_texel(ivec2 texel, float eye_depth, bool in_front) {
    CutSample s;
    s.fragment_depth = eye_depth;
    s.texel = texel;
    bool inside = in_front && all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(cut_size)));
    s.cut_depth = inside ? cut_surface_depth(texel) : 0.0;
    return s;
}

// From the point's clip position and depth in the cut camera (interpolated per fragment).
CutSample cut_from_clip(vec4 clip, float eye_depth) {
    return cut_at_texel(ivec2(floor((clip.xy / clip.w * 0.5 + 0.5) * cut_size)), eye_depth, clip.w > 0.0);
}

CutSample cut_at(vec3 world) {
    vec4 eye = cut_view * vec4(world, 1.0);
    return cut_from_clip(cut_projection * eye, -eye.z);
}

#ifdef STORED_CUT_NORMALS
// Stage 2's one-pass shading reads the normals cut_surface/cut_normals.comp stored per cut pixel.
uniform sampler2D cut_normals;  // RGBA32F: world normal at each cut pixel
vec3 cut_normal_at(ivec2 texel) { return texelFetch(cut_normals, texel, 0).rgb; }
#else
// The cut camera's ray through window position w (common/cameras.glsl cut_ray_origin,
// cut_ray_per_px): a point at depth s on it lies at the camera's position + s * ray.
float cut_depth_or_none(ivec2 texel) {
    return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(cut_size))) ? cut_surface_depth(texel) : 0.0;
}

// The cut's world normal at a cut pixel, facing the cut camera: from the neighbours' points on the
// smoother side of each axis, so a wall's edge does not bend it (the points rebuilt from the
// depths along the pixels' rays).
vec3 cut_normal_at(ivec2 texel) {
    float s = cut_depth_or_none(texel);
    vec3 ray = cut_ray_origin + (float(texel.x) + 0.5) * cut_ray_per_px[0] + (float(texel.y) + 0.5) * cut_ray_per_px[1];
    vec3 tangent[2];
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        float ahead = cut_depth_or_none(texel + step), behind = cut_depth_or_none(texel - step);
        bool use_ahead = ahead > 0.0 && (behind <= 0.0 || abs(ahead - s) <= abs(behind - s));
        float other = use_ahead ? ahead : behind;
        float direction = use_ahead ? 1.0 : -1.0;
        // The neighbour's point minus this one (the camera position cancels), towards +axis.
        vec3 other_ray = ray + direction * cut_ray_per_px[axis];
        tangent[axis] = other > 0.0 ? (other * other_ray - s * ray) * direction : vec3(0.0);
    }
    vec3 normal = cross(tangent[0], tangent[1]);
    normal = dot(normal, normal) > 0.0 ? normalize(normal) : normalize(-ray);  // towards the camera
    return dot(normal, ray) > 0.0 ? -normal : normal;  // facing the camera
}
#endif

// Whether the cut at `texel` is the clamp just in front of the rear shell (the strategy's cut
// went past the model there, cut_surface/resolve.frag): the shell behind it shows as cut fill,
// and no border line is drawn against it.
#ifdef CUT_IMAGES
layout(r8, binding = img_cut_rear_clamp) uniform readonly image2D cut_rear_clamp_image;
float cut_rear_clamp_texel(ivec2 texel) { return imageLoad(cut_rear_clamp_image, texel).r; }
#else
uniform sampler2D cut_rear_clamp;  // R8: 1 where the cut is clamped at the rear shell, else 0
float cut_rear_clamp_texel(ivec2 texel) { return texelFetch(cut_rear_clamp, texel, 0).r; }
#endif
bool cut_is_rear_shell(ivec2 texel) {
    return all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(cut_size))) &&
           cut_rear_clamp_texel(texel) > 0.5;
}

// Freeze view: the cut is another camera's, so its rear-shell clamp follows that camera's rays and
// a moved model camera would look past it (through the cut's sides, and between the clamp's
// texels where the rear shell is seen at a slant). The model camera's own rear shell
// (src/cutaway/rear_shell_depth.h, drawn from the model camera each frame) is kept instead: a
// point at most rear_margin in front of it is never clipped, so the rear shows as cut fill.
// Variant VIEW_REAR_SHELL (set only while the view is frozen; a compile-time variant because
// llvmpipe would run the test's texture fetch for every fragment behind a false uniform).
#ifdef VIEW_REAR_SHELL
uniform sampler2D view_rear_shell;  // DEPTH32F, model camera: (s - near) / (far - near), 0 = none
uniform mat4 view_rear_view;        // model camera view matrix
uniform vec2 view_rear_range;       // model camera near, far planes
uniform float view_rear_margin;     // render units

// Whether `world`, seen at model-camera pixel `pixel`, lies on the model camera's rear shell.
bool at_view_rear_shell(vec3 world, ivec2 pixel) {
    if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, textureSize(view_rear_shell, 0))))
        return false;
    float stored = texelFetch(view_rear_shell, pixel, 0).r;
    float rear = view_rear_range.x + stored * (view_rear_range.y - view_rear_range.x);
    return stored > 0.0 && -(view_rear_view * vec4(world, 1.0)).z >= rear - view_rear_margin;
}
#else
bool at_view_rear_shell(vec3 world, ivec2 pixel) { return false; }
#endif

// Whether stage 2 discards the point `world` seen at model-camera pixel `pixel` (its sample `s`).
bool clipped(CutSample s, vec3 world, ivec2 pixel) {
    return s.fragment_depth < s.cut_depth && !at_view_rear_shell(world, pixel);
}
