// Cell edges and border lines: a shade of the surface they lie on (darker on a light surface,
// lighter on a dark one, where darker would be black), so a cut wall of small cells reads as its
// colours rather than as a black mesh, and faded out on faces only a few pixels across (where
// edges would cover the face).
const float line_shade = 0.6;       // on a light surface: line colour = surface colour x this
const float line_lightening = 0.3;  // on a dark one: this far from the surface colour to white

vec3 line_colour_on(vec3 surface) {
    float luminance = dot(surface, vec3(0.2126, 0.7152, 0.0722));
    return luminance > 0.25 ? surface * line_shade : mix(surface, vec3(1.0), line_lightening);
}

// Single-pass wireframe: line opacity at `distance` pixels from an edge, for a line `width` wide
// with a smooth falloff over the last pixel.
float line_opacity(float distance, float width) {
    float d = max(distance - 0.5 * width + 0.5, 0.0);
    return exp2(-2.0 * d * d);
}

// Opacity of a quad's edge lines at a fragment `edge_distance` pixels from its 4 edges (edges 0
// and 2, 1 and 3 are opposite): full on faces at least 10 pixels across, none below 4.
float face_edge_opacity(vec4 edge_distance, float width) {
    float nearest = min(min(edge_distance.x, edge_distance.y), min(edge_distance.z, edge_distance.w));
    float across = min(edge_distance.x + edge_distance.z, edge_distance.y + edge_distance.w);
    return line_opacity(nearest, width) * smoothstep(4.0, 10.0, across);
}
