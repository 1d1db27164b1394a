// The paper's ray-cast border test: the plane of the face seen at a pixel, followed to the 4
// pixels at distance w (up, down, left, right); if the cut would clip the plane at any of them,
// the pixel lies within w of the border. Needs cut_lookup.glsl.
// The model camera: ViewCamera (inverse_view_projection, viewport_size, inverse_view, projection_scale).
#include "common/cameras.glsl"
uniform float border_width;            // w, pixels
// Variant CUT_CAMERA_IS_VIEW (the view is not frozen, so the cut was made from the model camera
// itself): the ray through a neighbour meets the cut image at that neighbour's own pixel, and the
// plane's depth along the ray is all the test needs (no projection into another camera). A
// compile-time variant, not a uniform branch: llvmpipe runs both sides of a branch.

// Point where the model camera's ray through window position `window` meets the plane.
vec3 ray_plane_hit(vec2 window, vec3 plane_point, vec3 plane_normal, out bool hit) {
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    vec4 near_point = inverse_view_projection * vec4(ndc, -1.0, 1.0);
    vec4 far_point = inverse_view_projection * vec4(ndc, 1.0, 1.0);
    vec3 origin = near_point.xyz / near_point.w;
    vec3 direction = far_point.xyz / far_point.w - origin;
    float denominator = dot(direction, plane_normal);
    hit = abs(denominator) > 1e-12;
    float t = hit ? dot(plane_point - origin, plane_normal) / denominator : 0.0;
    return origin + t * direction;
}

// The same test when the cut camera is the model camera: the ray through a window position
// (a unit step along the view axis is one unit of depth) meets the plane at depth
// dot(plane_point - eye, n) / dot(ray, n), compared with the cut at that position's own pixel.
// The ray is affine in the window position, so the 4 neighbours' rays are the pixel's own plus or
// minus w times its change per pixel along x or y: one dot product and a division each.
bool raycast_border_of_view(vec2 window, vec3 plane_point, vec3 plane_normal) {
    mat3 to_world = mat3(inverse_view);
    vec3 eye = inverse_view[3].xyz;
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    vec3 ray = to_world * vec3(ndc / projection_scale, -1.0);
    vec2 ndc_per_px = 2.0 / (viewport_size * projection_scale);
    vec3 ray_step[2] = vec3[](border_width * ndc_per_px.x * to_world[0], border_width * ndc_per_px.y * to_world[1]);
    float along = dot(plane_point - eye, plane_normal);
    const vec2 offsets[4] = vec2[](vec2(1.0, 0.0), vec2(-1.0, 0.0), vec2(0.0, 1.0), vec2(0.0, -1.0));
    bool border = false;
    for (int n = 0; n < 4; ++n) {
        vec3 neighbour_ray = ray + offsets[n][n / 2] * ray_step[n / 2];
        float denominator = dot(neighbour_ray, plane_normal);
        float depth = along / denominator;
        ivec2 texel = ivec2(floor(window + border_width * offsets[n]));
        CutSample there = cut_at_texel(texel, depth, true);  // behind the eye, depth < 0 is clipped as by cut_at
        border = border || (abs(denominator) > 1e-12 && clipped(there, eye + depth * neighbour_ray, texel) && !cut_is_rear_shell(texel));
    }
    return border;
}

bool raycast_border(vec2 window, vec3 plane_point, vec3 plane_normal) {
#ifdef CUT_CAMERA_IS_VIEW
    return raycast_border_of_view(window, plane_point, plane_normal);
#else
    const vec2 offsets[4] = vec2[](vec2(1.0, 0.0), vec2(-1.0, 0.0), vec2(0.0, 1.0), vec2(0.0, -1.0));
    for (int n = 0; n < 4; ++n) {
        vec2 neighbour = window + border_width * offsets[n];
        bool hit;
        vec3 point = ray_plane_hit(neighbour, plane_point, plane_normal, hit);
        if (!hit) continue;
        CutSample there = cut_at(point);
        if (clipped(there, point, ivec2(floor(neighbour))) && !cut_is_rear_shell(there.texel)) return true;
    }
    return false;
#endif
}
