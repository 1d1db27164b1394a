// The paper's ray-cast border test: the plane of the face seen at a pixel, followed to the 4
// pixels at distance w (up, down, left, right); if the cut would clip the plane at any of them,
// the pixel lies within w of the border. Needs cut_lookup.glsl.
uniform mat4 inverse_view_projection;  // model camera
uniform vec2 viewport_size;
uniform float border_width;            // w, pixels

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

bool raycast_border(vec2 window, vec3 plane_point, vec3 plane_normal) {
    const vec2 offsets[4] = vec2[](vec2(1.0, 0.0), vec2(-1.0, 0.0), vec2(0.0, 1.0), vec2(0.0, -1.0));
    for (int n = 0; n < 4; ++n) {
        bool hit;
        vec2 neighbour = window + border_width * offsets[n];
        vec3 point = ray_plane_hit(neighbour, plane_point, plane_normal, hit);
        if (!hit) continue;
        CutSample there = cut_at(point);
        if (clipped(there, point, ivec2(floor(neighbour))) && !cut_is_rear_shell(there.texel)) return true;
    }
    return false;
}
