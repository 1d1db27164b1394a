#pragma once
// The corner-point grid: pillars (COORD), corner depths (ZCORN), ACTNUM and per-cell properties.
// No geometry here beyond the raw arrays; see cell_geometry.h for corners, centres and volumes.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grid/grid_dims.h"
#include "grid/point3.h"
#include "grid/zcorn_store.h"

namespace cutaway::grid {

/// A pillar: the straight line through its top and bottom COORD points (model units).
struct Pillar {
    Point3 top;
    Point3 bottom;
};

/// File-level metadata kept as read (not applied to the coordinates).
struct GridMetadata {
    std::optional<std::array<double, 6>> mapaxes;  // x1 y1 (y axis point), x0 y0 (origin), x2 y2 (x axis point)
    std::string grid_unit;                          // GRIDUNIT first item, e.g. "METRES"
    std::string map_units;                          // MAPUNITS, e.g. "METRES"
    std::vector<std::string> gdorient;              // GDORIENT items, e.g. INC INC INC DOWN RIGHT
    std::string unit_system;                        // a simulator case's INTEHEAD: METRIC, FIELD, LAB, PVT-M; empty when unknown
};

class CornerPointGrid {
public:
    CornerPointGrid() = default;
    /// `coord`: 6*(NX+1)(NY+1) values (top xyz, bottom xyz per pillar, i fastest);
    /// `zcorn`: a complete store; `actnum`: NX*NY*NZ flags (empty = all active).
    CornerPointGrid(GridDims dims, std::vector<double> coord, ZcornStore zcorn, std::vector<std::uint8_t> actnum);

    const GridDims& dims() const { return dims_; }
    std::size_t cell_count() const { return dims_.cell_count(); }

    Pillar pillar(int pi, int pj) const;
    const std::vector<double>& coord() const { return coord_; }
    const ZcornStore& zcorn() const { return zcorn_; }

    /// +1 when depths grow with k (z down, the usual case), -1 when they shrink. Decided as OPM's
    /// fixupZCORN does: from corner 0 of cell (0,0,0)'s top against corner 4 of (0,0,NZ-1)'s bottom.
    int depth_direction() const { return depth_direction_; }

    bool active(std::size_t cell) const { return actnum_[cell] != 0; }
    const std::vector<std::uint8_t>& actnum() const { return actnum_; }
    std::size_t active_count() const { return active_count_; }

    GridMetadata& metadata() { return metadata_; }
    const GridMetadata& metadata() const { return metadata_; }

    // Static properties: one value per cell (all cells, active or not), by keyword name.
    void set_property(const std::string& name, std::vector<float> values);
    void set_int_property(const std::string& name, std::vector<std::int32_t> values);
    const std::vector<float>* property(const std::string& name) const;
    const std::vector<std::int32_t>* int_property(const std::string& name) const;
    std::vector<std::string> property_names() const;
    std::vector<std::string> int_property_names() const;

    // Dynamic properties: one array per time step, in the order the steps were added.
    void add_dynamic_step(const std::string& name, std::vector<float> values);
    /// A dynamic property read on demand (a simulator's restart file): `name` gets `step_count`
    /// steps, none of them held (dynamic_property gives null) until set_dynamic_step holds one.
    void declare_dynamic_steps(const std::string& name, std::size_t step_count);
    /// Holds `values` (one per cell) as step `step` of a declared property and releases the step
    /// held before, so a property read on demand costs one step's array.
    void set_dynamic_step(const std::string& name, std::size_t step, std::vector<float> values);
    std::size_t step_count(const std::string& name) const;
    /// Null for an unknown name or step, or a declared step not held.
    const std::vector<float>* dynamic_property(const std::string& name, std::size_t step) const;
    std::vector<std::string> dynamic_property_names() const;

    /// Removes every property, static and dynamic (a one-frame render keeps only the array it
    /// colours by, which it holds itself: 4 bytes per cell instead of all of them).
    void clear_properties();
    /// Frees ZCORN (the largest array: 32 bytes per cell compact, 64 full) once its depths live
    /// elsewhere, e.g. on the GPU (a one-frame render after the renderer's set-up). Corners cannot
    /// be read afterwards: cell_corners throws std::logic_error.
    void release_corner_depths() { zcorn_ = ZcornStore(); }
    bool has_corner_depths() const { return zcorn_.dims().cell_count() == dims_.cell_count(); }

    /// Bytes held by COORD, ZCORN and ACTNUM (properties excluded).
    std::size_t geometry_bytes() const;
    /// Bytes held by all property arrays.
    std::size_t property_bytes() const;

private:
    void require_cell_sized(const std::string& name, std::size_t size) const;

    GridDims dims_{};
    std::vector<double> coord_;
    ZcornStore zcorn_;
    std::vector<std::uint8_t> actnum_;
    std::size_t active_count_ = 0;
    int depth_direction_ = 1;
    GridMetadata metadata_;
    std::map<std::string, std::vector<float>> float_properties_;
    std::map<std::string, std::vector<std::int32_t>> int_properties_;
    std::map<std::string, std::vector<std::vector<float>>> dynamic_properties_;
};

}  // namespace cutaway::grid
