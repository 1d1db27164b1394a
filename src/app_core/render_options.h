#pragma once
// Options of `cutaway render` (and the viewer), their CLI registration, and what they select.
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "annotation/colour_bar_layout.h"
#include "app_core/cut_volume_options.h"
#include "app_core/option_checks.h"
#include "cutaway/camera.h"
#include "cutaway/frame_settings.h"
#include "gl/gl_context.h"
#include "grid/primary_selection.h"

namespace cutaway::app {

/// Host bytes a frame needs per pixel: the G-buffers (cut surface 13 with its filtered depth, scene
/// 36, post 6, mean filter, seeds and the cut pyramid about 20; on llvmpipe GPU memory is host
/// memory) plus the CPU read-backs of the image, the cell ids and the metrics' frames. Measured
/// peaks were 145-150 bytes per pixel (render --size 8192 8192: 9.7 GB; 4096 4096: 2.5 GB) when
/// the targets held 33 bytes per pixel more (a second resolved cut, the two-pass face index, the
/// cut's stored normals): the budget keeps that margin.
constexpr std::size_t render_target_bytes_per_pixel = 160;

struct RenderOptions {
    std::vector<std::string> model;   ///< GRDECL file(s) loaded onto one grid, preset:NAME, or CASE.EGRID
    std::string property;             ///< empty: PORO, else the first property
    std::vector<float> range;         ///< LO HI
    std::vector<float> colour_range;  ///< --colour-range LO HI (empty: from the values shown)
    double primary_fraction = 0;      ///< 0: --range or the default 1%
    int step = -1;                    ///< --time-step: report step of a dynamic property (-1: none given)
    bool caption = true;              ///< a dynamic property's date and report step over the frame (--no-caption)
    std::vector<int> ijk_box;         ///< I0 J0 K0 I1 J1 K1
    std::string select_by;            ///< render only: primaries by this property, colours by `property`
    pipeline::FrameSettings settings;
    std::string border = "raycast";
    std::string kernel = "full";
    std::string ssao = "on";
    std::string ssao_resolution = "half";
    std::string contours = "on";
    std::string only = "both";
    std::string scale = "auto";  ///< pipeline::ColourScale by name
    float text_height_px = 0;         ///< capitals of the image's text at least this tall (0: 2% of the height)
    std::string seeds = "boxes";
    std::string draw = "visible";
    std::string stage2_passes = "deferred";
    std::vector<float> aperture{60, 60};  ///< full opening angles, degrees
    bool aperture_180 = false;
    std::vector<float> camera{35, 30, 0};
    std::vector<float> freeze_camera;  ///< AZ EL DIST of the frozen cut camera
    std::optional<pipeline::OrbitPose> freeze_pose;
    std::vector<int> size{1280, 720};
    int width = 1280, height = 720;
    double z_scale = 0;
    std::string out;
    std::string stats;
    std::string cell_ids;             ///< --cell-ids PNG (empty: none)
    bool baseline = false;
    bool metrics = true;
    bool exact_check = false;         ///< compare the cut with the exact cone field (cut_vs_exact)
    int warmup = 1;
    int repeat = 3;
    std::string egl_platform = "auto";
    double memory_limit_gb = default_memory_limit_gib;
    std::string rank_slabs = "k";     ///< under mpirun: the axis the model is cut along into slabs
    CutVolumeOptions cut_volumes;     ///< --cut-volume, --cut-volumes, --primaries
    std::vector<std::string> wells;   ///< --wells values (app_core/frame_wells.h)
    double well_radius = 0;           ///< --well-radius, model units (0: automatic)

    std::size_t memory_limit_bytes() const;
    /// What the frame's targets and read-backs need for --size (render_target_bytes_per_pixel each).
    std::size_t render_target_bytes() const;
    /// The memory limit less the render targets: what reading or generating the model may use.
    std::size_t model_memory_limit_bytes() const;
    gl::ContextOptions context_options() const;
    pipeline::OrbitPose camera_pose() const;
    /// Settings after the string options are checked (throws std::invalid_argument naming the
    /// option and the accepted values).
    pipeline::FrameSettings frame_settings() const;
    /// Every effective option, for stats.json.
    nlohmann::json describe() const;
};

/// --colour-range LO HI as a range; throws std::invalid_argument naming the option unless LO < HI
/// (and LO > 0 on a log scale).
grid::PrimaryRange given_colour_range(const std::vector<float>& range, bool log_scale);

/// Which cells are primaries: --property, --range, --primary-fraction, --step, --ijk-box.
void add_selection_options(CLI::App& command, RenderOptions& options);
/// Every switch of the frame (FrameSettings): --strategy, --border, --mean-filter, --ssao, ...
void add_frame_options(CLI::App& command, RenderOptions& options);
/// The model, selection and frame options plus camera, size, z-scale and memory limit: what
/// `cutaway render` and `cutaway view` share. Parsed values land in `options` (finalised by a callback).
void add_scene_options(CLI::App& command, RenderOptions& options);
/// --no-caption: the headless frames (`render`, `animate`) without their date and report step.
void add_caption_option(CLI::App& command, RenderOptions& options);
/// add_scene_options plus the headless run's outputs and repetitions (`cutaway render`).
void add_render_options(CLI::App& command, RenderOptions& options);

/// The property cells are coloured and selected by.
struct PropertyChoice {
    std::string name;                 ///< as in the file, e.g. "SWAT"
    std::string label;                ///< with the step, e.g. "SWAT step 3"
    const std::vector<float>* external = nullptr;  ///< the grid's array, or null when owned
    std::vector<float> owned;         ///< storage for a derived property (layer index)
    grid::PrimaryRange colour_range;  ///< colour_quantiles of the active values (positive ones on a log scale)
    bool log_scale = false;           ///< colours by log10 of the value (--scale)
    float text_height_px = 0;         ///< --text-height
    grid::PrimaryRange primary_range;
    std::string unit_system;          ///< the grid's (GridMetadata::unit_system), for the unit
    const std::vector<float>& values() const { return external ? *external : owned; }
    /// The colour bar's title (the name: a frame shows its step in its caption), unit (by the property's keyword and unit system), colour
    /// range and scale; `mark_primary_range`: with primary_range marked (when the primaries are chosen by it).
    annotation::ColourBarLabel colour_bar_label(bool mark_primary_range = false) const;
};

/// Throws std::invalid_argument for an unknown property or step, naming the known ones.
/// `first_layer`: the whole model's k of the grid's first layer (a block's), for the layer-index
/// colouring of a model without properties.
PropertyChoice choose_property(const grid::CornerPointGrid& grid, const RenderOptions& options, int first_layer = 0);

/// The colour range `colour` (the values' percentiles) widened to hold `primary` within the
/// values' `extremes`, so that primaries coloured by the property that selects them keep their
/// values' colours (a top 1% lies beyond the 98th percentile, all in the bar's end colour); on a
/// log scale the low end stays above 0.
grid::PrimaryRange colour_range_holding(grid::PrimaryRange colour, const grid::PrimaryRange& primary,
                                        const grid::PrimaryRange& extremes, bool log_scale);
/// Whether the colouring property's primary range widens its colour range (colour_range_holding):
/// it picks the primaries (no --select-by, not --primaries none) and --colour-range gave none.
bool colour_range_holds_primaries(const RenderOptions& options);
/// Sets property.primary_range from --range (or --primary-fraction), widens its colour range to
/// hold it where colour_range_holds_primaries, and returns the --ijk-box, if any: the selection
/// the renderer makes on the GPU (CutawayRenderer::select).
std::optional<grid::IjkBox> choose_primary_range(const grid::CornerPointGrid& grid, PropertyChoice& property,
                                                 const RenderOptions& options);
/// The checks of --range and --primary-fraction, and the --ijk-box (checked against `dims`).
std::optional<grid::IjkBox> selection_box(const RenderOptions& options, const grid::GridDims& dims);
/// Primaries chosen by a second property (`render --select-by NAME`): NAME's --range or
/// --primary-fraction (and --ijk-box) pick the cells while --property colours them.
struct SecondPropertySelection {
    std::string label;          ///< NAME, with its step for a dynamic one
    grid::PrimaryRange range;   ///< of NAME's values
    std::vector<std::uint8_t> flags;  ///< one per cell (grid::select_primaries)
};
/// std::nullopt without --select-by (the renderer then selects by the colouring values on the
/// GPU). Throws std::invalid_argument for an unknown property, naming --select-by and the known ones.
std::optional<SecondPropertySelection> select_by_second_property(const grid::CornerPointGrid& grid,
                                                                 const RenderOptions& options);
/// The property a preset must generate for `options` (load_model's only_property): --property,
/// unless --select-by names the dynamic one.
std::optional<std::string> property_to_load(const RenderOptions& options);
/// --primary-fraction, or its default 0.01.
double primary_fraction(const RenderOptions& options);

}  // namespace cutaway::app
