#include "faults.h"

#include <charconv>
#include <cmath>
#include <numbers>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace cutaway::generators {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

std::string text(double value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

}  // namespace

std::string FaultPlane::describe() const {
    return "strike " + text(strike_deg) + " deg, dip " + text(dip_deg) + " deg, throw " + text(throw_m) +
           " m, through (" + text(anchor.x) + ", " + text(anchor.y) + ", " + text(anchor.z) + ")";
}

std::vector<FaultPlane> make_faults(const GeneratorParameters& p, const ModelFrame& frame, DeterministicRandom& random) {
    std::vector<FaultPlane> faults;
    for (int f = 0; f < p.fault_count; ++f) {
        FaultPlane fault;
        fault.anchor = {random.uniform(0.2, 0.8) * p.length_x, random.uniform(0.2, 0.8) * p.length_y, frame.mid_depth};
        fault.strike_deg = p.fault_azimuth_deg + random.uniform(-1, 1) * p.fault_azimuth_spread_deg;
        fault.dip_deg = p.fault_dip_deg;
        fault.throw_m = random.uniform(p.throw_range.first, p.throw_range.second);
        const double dip_side = random.uniform01() < 0.5 ? -1.0 : 1.0;
        // Horizontal unit vector across the strike, towards the side the plane dips to.
        const double strike = radians(fault.strike_deg);
        const double across_x = dip_side * std::cos(strike), across_y = -dip_side * std::sin(strike);
        const double dip = radians(fault.dip_deg);
        // A plane dipping towards `across` contains cos(dip) * across + sin(dip) * down; its normal
        // sin(dip) * across - cos(dip) * down points up into the hanging wall (z is down).
        fault.normal = {std::sin(dip) * across_x, std::sin(dip) * across_y, -std::cos(dip)};
        if (fault.dip_deg >= 90) fault.normal.z = 0;  // exactly vertical: no lean, no rounding
        const double nz = fault.normal.z, horizontal = 1 - nz * nz;
        fault.lean_x = -fault.normal.x * nz / horizontal;
        fault.lean_y = -fault.normal.y * nz / horizontal;
        faults.push_back(fault);
    }
    return faults;
}

std::vector<std::uint64_t> hanging_wall_masks(const std::vector<FaultPlane>& faults, const ModelFrame& frame) {
    std::vector<CGAL::Plane_3<Kernel>> planes;
    for (const FaultPlane& f : faults)
        planes.emplace_back(Kernel::Point_3(f.anchor.x, f.anchor.y, f.anchor.z),
                            Kernel::Vector_3(f.normal.x, f.normal.y, f.normal.z));
    std::vector<std::uint64_t> masks(frame.column_count(), 0);
    for (int j = 0; j < frame.dims.ny; ++j)
        for (int i = 0; i < frame.dims.nx; ++i) {
            const grid::Point3 c = frame.column_centre(i, j);
            const Kernel::Point_3 centre(c.x, c.y, c.z);
            std::uint64_t mask = 0;
            for (std::size_t f = 0; f < planes.size(); ++f)
                if (planes[f].oriented_side(centre) == CGAL::ON_POSITIVE_SIDE) mask |= std::uint64_t(1) << f;
            masks[frame.column_index(i, j)] = mask;
        }
    return masks;
}

std::vector<double> column_offsets(const std::vector<FaultPlane>& faults, const std::vector<std::uint64_t>& masks) {
    std::vector<double> offsets(masks.size(), 0.0);
    for (std::size_t c = 0; c < masks.size(); ++c)
        for (std::size_t f = 0; f < faults.size(); ++f)
            if (masks[c] >> f & 1) offsets[c] += faults[f].throw_m;
    return offsets;
}

}  // namespace cutaway::generators
