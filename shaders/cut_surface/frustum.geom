#version 450 core
// Stage 1, frustum union: the frustum of one primary cell. Its back face (the box's far side,
// pushed back by the margin, widened by one pixel so pixel-centre coverage never misses) stays;
// the four walls open towards the camera at the horizontal and vertical aperture angles, up to
// the rim depth (nearest depth of the model: nothing in front of it can be cut). Vertices are
// emitted with w = 1 and z linear in s, so the stored depth is (s - near) / (far - near) and
// interpolates linearly in screen space: the contract of every strategy (cut_surface_strategy.h).
// With BACK_FACE_ONLY defined only the back face is emitted: the cone-field strategies' seeds
// (cut_surface/cut_seeds.h), the primaries' rear hull from their cell boxes.
layout(points) in;
layout(triangle_strip, max_vertices = 20) out;

in CellBox {
    vec4 uv_box;
    float far_depth;
} box[];

uniform vec2 projection_scale;   // P[0][0], P[1][1] of the cut camera
uniform float near_plane;
uniform float far_plane;
uniform float rim_depth;         // walls stop here
uniform float back_margin;       // depth units added behind the box
uniform vec2 aperture_tangent;   // tan(horizontal), tan(vertical) aperture
uniform float pixel_uv;          // one pixel in u, v units (1 / focal length in pixels)

void emit(vec2 uv, float s) {
    gl_Position = vec4(uv * projection_scale, 2.0 * (s - near_plane) / (far_plane - near_plane) - 1.0, 1.0);
    EmitVertex();
}

void main() {
    vec2 lo = box[0].uv_box.xy - pixel_uv;
    vec2 hi = box[0].uv_box.zw + pixel_uv;
    float back = min(box[0].far_depth + back_margin, far_plane);
    float rim = min(rim_depth, back);
    // Widening at the rim: a wall at angle a from the view ray moves tan(a) * (back - s) eye units
    // between depth back and s, which is tan(a) * (back - s) / back in u at the back face's scale.
    vec2 open = aperture_tangent * (back - rim) / back;
    vec2 rim_lo = lo - open;
    vec2 rim_hi = hi + open;
    // back face
    emit(vec2(lo.x, lo.y), back); emit(vec2(hi.x, lo.y), back); emit(vec2(lo.x, hi.y), back); emit(vec2(hi.x, hi.y), back);
    EndPrimitive();
#ifndef BACK_FACE_ONLY
    // walls: left, right, bottom, top
    emit(vec2(lo.x, lo.y), back); emit(vec2(lo.x, hi.y), back); emit(vec2(rim_lo.x, rim_lo.y), rim); emit(vec2(rim_lo.x, rim_hi.y), rim);
    EndPrimitive();
    emit(vec2(hi.x, lo.y), back); emit(vec2(hi.x, hi.y), back); emit(vec2(rim_hi.x, rim_lo.y), rim); emit(vec2(rim_hi.x, rim_hi.y), rim);
    EndPrimitive();
    emit(vec2(lo.x, lo.y), back); emit(vec2(hi.x, lo.y), back); emit(vec2(rim_lo.x, rim_lo.y), rim); emit(vec2(rim_hi.x, rim_lo.y), rim);
    EndPrimitive();
    emit(vec2(lo.x, hi.y), back); emit(vec2(hi.x, hi.y), back); emit(vec2(rim_lo.x, rim_hi.y), rim); emit(vec2(rim_hi.x, rim_hi.y), rim);
    EndPrimitive();
#endif
}
