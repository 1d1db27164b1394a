#version 450 core
// Final image: ambient occlusion, saturation contrast (HSV), primary silhouette, shell contours.
// Each is a #define variant: SSAO, SATURATION, SILHOUETTE, CONTOURS. A compute pass with image
// loads (as post/ssao.comp; src/cutaway/post/composite.cpp). Workgroups of one row of 128 pixels:
// faster than 64 x 4 (sapphire 1080p, half-resolution SSAO, contours; 6 alternating runs, the
// same image); the mean filter, resolve, deferred shading and border passes gained nothing so
// and stay 64 x 4.
layout(local_size_x = 128, local_size_y = 1) in;
#include "common/shared_constants.h"

layout(rgba8, binding = img_scene_colour) uniform readonly image2D scene_colour;
layout(rg32f, binding = img_post_ambient) uniform readonly image2D ambient;      // factor, linear depth (post/ssao.comp)
layout(rg32ui, binding = img_scene_id) uniform readonly uimage2D scene_id;  // compact cell + 1, flags
layout(r32f, binding = img_post_shell_depth) uniform readonly image2D shell_depth;  // linear depth of the uncut shell (0 = background)
layout(rgba8, binding = img_post_final_colour) uniform writeonly image2D final_colour;
layout(rg32ui, binding = img_scene_normal_depth) uniform readonly uimage2D normal_depth;  // eye normal, linear depth (0 = background; common/packed_normal.glsl)
uniform vec2 viewport_size;
uniform float saturation_primary;    // factor on primaries' saturation
uniform float saturation_secondary;  // factor on secondaries' saturation
uniform int silhouette_width;        // pixels
uniform vec3 silhouette_colour;     // not the shell-cut lines' red
uniform vec3 contour_colour;
uniform float contour_jump;          // relative depth jump that makes a fold contour
uniform vec3 background;

#include "common/packed_normal.glsl"

#include "common/hsv.glsl"

#ifdef SSAO
#ifdef HALF_AMBIENT
// Joint bilateral upsampling of the half-resolution factors (Kopf et al. 2007): ambient texel t
// holds pixel 2t's factor, so a pixel lies on one sample (both coordinates even), midway between
// two or in the middle of four. Those 1, 2 or 4 samples are equally far (their bilinear weights are
// equal), so each is weighted by the inverse of its depth difference from the pixel alone: a factor
// does not bleed across a depth edge (a primary's outline, the cut's rim). The 1e-3 relative floor
// keeps samples on the same smooth surface equal partners; 1e-20 keeps a zero depth from dividing
// by zero.
float ambient_at(ivec2 texel) {
    float depth = packed_value(imageLoad(normal_depth, texel).rg);
    ivec2 low = texel >> 1, odd = texel & 1;
    ivec2 last = (ivec2(viewport_size) - 1) >> 1;
    float weight_sum = 0.0, sum = 0.0;
    for (int dy = 0; dy <= odd.y; ++dy)
        for (int dx = 0; dx <= odd.x; ++dx) {
            vec2 sample_ = imageLoad(ambient, min(low + ivec2(dx, dy), last)).rg;
            float weight = 1.0 / (abs(sample_.g - depth) + 1e-3 * depth + 1e-20);
            weight_sum += weight;
            sum += weight * sample_.r;
        }
    return sum / weight_sum;
}
#else
float ambient_at(ivec2 texel) { return imageLoad(ambient, texel).r; }
#endif
#endif

bool is_primary(ivec2 texel) { return (imageLoad(scene_id, texel).g & flag_primary) != 0u; }

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(viewport_size)))) return;
    uvec2 id = imageLoad(scene_id, texel).rg;
    // A well tube shows no cell but covers the pixel; it keeps its colour as primaries do
    // (saturation), and no silhouette or contour line crosses it.
    bool well = (id.g & flag_well) != 0u;
    bool covered = id.r != 0u || well;
    bool primary = (id.g & flag_primary) != 0u;
    vec3 colour = covered ? imageLoad(scene_colour, texel).rgb : background;
#ifdef SSAO
    if (covered) colour *= ambient_at(texel);
#endif
#ifdef SATURATION
    if (covered) colour = scale_saturation(colour, primary || well ? saturation_primary : saturation_secondary);
#endif
#ifdef SILHOUETTE
    // A doubled line in its own colour (the red of the shell-cut lines means something else): the
    // pixels next to the primaries and the band's outermost pixels, the scene showing between.
    if (!primary && !well) {
        ivec2 last = ivec2(viewport_size) - 1;
        int nearest = silhouette_width * silhouette_width + 1;  // squared pixel distance to a primary
        for (int dy = -silhouette_width; dy <= silhouette_width; ++dy)
            for (int dx = -silhouette_width; dx <= silhouette_width; ++dx)
                if (dx * dx + dy * dy < nearest && is_primary(clamp(texel + ivec2(dx, dy), ivec2(0), last)))
                    nearest = dx * dx + dy * dy;
        float distance = sqrt(float(nearest));
        bool inner = distance < 1.6, outer = distance > float(silhouette_width) - 1.1;
        if (distance <= float(silhouette_width) && (inner || outer)) colour = silhouette_colour;
    }
#endif
#ifdef CONTOURS
    // Outline of the uncut shell and its folds: a 1-pixel line where the shell's depth jumps.
    float depth = imageLoad(shell_depth, texel).r;
    ivec2 last_texel = ivec2(viewport_size) - 1;
    const ivec2 neighbours[4] = ivec2[](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    bool outline = false, fold = false;
    for (int n = 0; n < 4; ++n) {
        float other = imageLoad(shell_depth, clamp(texel + neighbours[n], ivec2(0), last_texel)).r;
        // Only the nearer side of a jump draws, so the line is one pixel wide.
        outline = outline || (depth > 0.0 && other == 0.0);
        fold = fold || (depth > 0.0 && other > 0.0 && other - depth > contour_jump * depth);
    }
    // A fold belongs to the shell: where the frame shows something else there (the cut floor
    // behind the cut-away shell, or nothing with --only primaries) it would float as a stray
    // jagged line. The outline always draws: it keeps the model's extent in view.
    float shown = packed_value(imageLoad(normal_depth, texel).rg);
    bool shell_shown = shown > 0.0 && abs(shown - depth) <= contour_jump * depth;
    if ((outline || (fold && shell_shown)) && !primary && !well) colour = contour_colour;
#endif
    imageStore(final_colour, texel, vec4(colour, 1.0));
}
