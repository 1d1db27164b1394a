#include "shapes/tube_mesh.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace cutaway::shapes {
namespace {

glm::dvec3 vec(const grid::Point3& p) { return {p.x, p.y, p.z}; }
grid::Point3 point(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

std::vector<glm::dvec3> distinct_points(const std::vector<grid::Point3>& path) {
    std::vector<glm::dvec3> points;
    for (const grid::Point3& p : path) {
        const glm::dvec3 v = vec(p);
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw std::invalid_argument("tube path has a point that is not finite");
        if (points.empty() || glm::length(v - points.back()) > 0) points.push_back(v);
    }
    if (points.size() < 2) throw std::invalid_argument("tube path needs at least two distinct points");
    return points;
}

/// A unit vector perpendicular to `axis`.
glm::dvec3 any_perpendicular(const glm::dvec3& axis) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, helper));
}

/// `frame` carried from the plane normal to `from` to the one normal to `to` (rotation about
/// from x to, the parallel transport of a polyline).
glm::dvec3 transport(const glm::dvec3& frame, const glm::dvec3& from, const glm::dvec3& to) {
    const glm::dvec3 axis = glm::cross(from, to);
    const double sin_angle = glm::length(axis);
    if (sin_angle < 1e-12) return frame;
    const glm::dvec3 k = axis / sin_angle;
    const double cos_angle = glm::dot(from, to);
    // Rodrigues' rotation.
    return frame * cos_angle + glm::cross(k, frame) * sin_angle + k * glm::dot(k, frame) * (1 - cos_angle);
}

struct Ring {
    glm::dvec3 centre;
    glm::dvec3 u, v;        ///< the cross-section's axes (unit, perpendicular to the segment)
    glm::dvec3 tangent;     ///< the segment direction the ring's offsets are projected along
    glm::dvec3 bisector;    ///< normal of the plane the ring lies in
};

/// The ring's point at `angle`: the circle of the segment's cross-section, pushed along the
/// segment onto the bisecting plane so that neighbouring segments meet.
glm::dvec3 ring_point(const Ring& ring, double radius, double angle) {
    const glm::dvec3 offset = radius * (std::cos(angle) * ring.u + std::sin(angle) * ring.v);
    const double along = -glm::dot(offset, ring.bisector) / glm::dot(ring.tangent, ring.bisector);
    return ring.centre + offset + along * ring.tangent;
}

void add_cap(TriangleMesh& mesh, const glm::dvec3& centre, const glm::dvec3& outward,
             const std::vector<glm::dvec3>& rim) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(point(centre));
    mesh.normals.push_back(point(outward));
    for (const glm::dvec3& p : rim) {
        mesh.positions.push_back(point(p));
        mesh.normals.push_back(point(outward));
    }
    const auto n = static_cast<std::uint32_t>(rim.size());
    for (std::uint32_t s = 0; s < n; ++s) {
        std::array<std::uint32_t, 3> t = {first, first + 1 + s, first + 1 + (s + 1) % n};
        const glm::dvec3 a = rim[s] - centre, b = rim[(s + 1) % n] - centre;
        if (glm::dot(glm::cross(a, b), outward) < 0) std::swap(t[1], t[2]);
        mesh.triangles.push_back(t);
    }
}

}  // namespace

TriangleMesh tube_mesh(const std::vector<grid::Point3>& path, double radius, int sides) {
    if (!std::isfinite(radius) || radius <= 0) throw std::invalid_argument("tube radius must be finite and positive");
    if (sides < 3) throw std::invalid_argument("tube needs at least 3 sides");
    const std::vector<glm::dvec3> points = distinct_points(path);
    const std::size_t segments = points.size() - 1;
    std::vector<glm::dvec3> directions(segments);
    for (std::size_t s = 0; s < segments; ++s) directions[s] = glm::normalize(points[s + 1] - points[s]);

    // Each segment's ring frame, carried along the path without twist.
    std::vector<glm::dvec3> frame_u(segments);
    frame_u[0] = any_perpendicular(directions[0]);
    for (std::size_t s = 1; s < segments; ++s)
        frame_u[s] = glm::normalize(transport(frame_u[s - 1], directions[s - 1], directions[s]));

    TriangleMesh mesh;
    const auto ring_size = static_cast<std::uint32_t>(sides);
    const double step = 2 * std::acos(-1.0) / sides;
    std::vector<glm::dvec3> first_rim, last_rim;
    for (std::size_t s = 0; s < segments; ++s) {
        const glm::dvec3 d = directions[s];
        const glm::dvec3 u = frame_u[s], v = glm::cross(d, u);
        // The planes at the segment's two ends: bisecting with the neighbour, or square at the tube's ends.
        const glm::dvec3 start_plane = s == 0 ? d : glm::normalize(directions[s - 1] + d);
        const glm::dvec3 end_plane = s + 1 == segments ? d : glm::normalize(d + directions[s + 1]);
        const Ring start{points[s], u, v, d, start_plane};
        const Ring end{points[s + 1], u, v, d, end_plane};
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        for (int k = 0; k < sides; ++k) {
            const double angle = k * step;
            const glm::dvec3 normal = std::cos(angle) * u + std::sin(angle) * v;
            const glm::dvec3 a = ring_point(start, radius, angle), b = ring_point(end, radius, angle);
            mesh.positions.push_back(point(a));
            mesh.normals.push_back(point(normal));
            mesh.positions.push_back(point(b));
            mesh.normals.push_back(point(normal));
            if (s == 0) first_rim.push_back(a);
            if (s + 1 == segments) last_rim.push_back(b);
        }
        for (std::uint32_t k = 0; k < ring_size; ++k) {
            const std::uint32_t a0 = first + 2 * k, b0 = a0 + 1;
            const std::uint32_t a1 = first + 2 * ((k + 1) % ring_size), b1 = a1 + 1;
            // u, v, d right-handed: going round from angle k to k+1 and along d, (a1-a0) x (b0-a0) points out.
            mesh.triangles.push_back({a0, a1, b0});
            mesh.triangles.push_back({a1, b1, b0});
        }
    }
    add_cap(mesh, points.front(), -directions.front(), first_rim);
    add_cap(mesh, points.back(), directions.back(), last_rim);
    return mesh;
}

}  // namespace cutaway::shapes
