#include "cell_validity.h"

#include <bit>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace cutaway::generators {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

bool same_point(const grid::Point3& a, const grid::Point3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

CellValidity check_cell(const grid::CellCorners& corners) {
    bool all_pinched = true;
    for (int b = 0; b < 4; ++b) all_pinched = all_pinched && same_point(corners[std::size_t(b)], corners[std::size_t(b + 4)]);
    if (all_pinched) return CellValidity::pinched;

    Kernel::Point_3 point[8];
    for (std::size_t b = 0; b < 8; ++b) point[b] = Kernel::Point_3(corners[b].x, corners[b].y, corners[b].z);
    bool degenerate = false;
    for (unsigned b = 0; b < 8; ++b) {
        const CGAL::Orientation expected = std::popcount(b) % 2 == 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
        const CGAL::Orientation found = CGAL::orientation(point[b], point[b ^ 1u], point[b ^ 2u], point[b ^ 4u]);
        if (found == -expected) return CellValidity::inverted;
        if (found == CGAL::ZERO && !same_point(corners[b], corners[b ^ 4u])) degenerate = true;
    }
    return degenerate ? CellValidity::degenerate : CellValidity::valid;
}

}  // namespace cutaway::generators
