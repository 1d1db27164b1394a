#include "app_core/render_options.h"

#include <algorithm>
#include <cfloat>
#include <stdexcept>

#include "annotation/property_units.h"
#include "app_core/frame_wells.h"
#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/setting_names.h"
#include "generators/generator.h"

namespace cutaway::app {
namespace {

/// `value` by the choice table that named it on the command line (where it was checked already).
template <typename Value>
Value parse_choice(const std::string& option, const std::string& value, pipeline::ChoiceTable<Value> table) {
    if (const std::optional<Value> found = pipeline::find_choice(table, value)) return *found;
    throw std::invalid_argument(option + " '" + value + "': expected " + pipeline::joined_choices(pipeline::choice_names(table)));
}

/// The option checked against `table`'s names while parsing, its choices listed in the help.
template <typename Value>
CLI::Option* add_choice(CLI::App& c, const std::string& name, std::string& value, pipeline::ChoiceTable<Value> table,
                        const std::string& help) {
    const std::vector<std::string> names = pipeline::choice_names(table);
    return c.add_option(name, value, pipeline::joined_choices(names) + ": " + help)->check(one_of(names));
}

/// The option given that selects primaries (empty if none): what --primaries none refuses.
std::string primary_selecting_option(const RenderOptions& o) {
    if (!o.range.empty()) return "--range";
    if (o.primary_fraction > 0) return "--primary-fraction";
    if (!o.ijk_box.empty()) return "--ijk-box";
    if (!o.select_by.empty()) return "--select-by";
    return {};
}

std::string names_of(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text.empty() ? "none" : text;
}

}  // namespace

gl::ContextOptions RenderOptions::context_options() const {
    gl::ContextOptions options;
    options.egl_platform = egl_platform;
#ifndef NDEBUG
    options.debug_output = true;
#endif
    return options;
}

std::size_t RenderOptions::memory_limit_bytes() const { return gib_to_bytes(memory_limit_gb); }

std::size_t RenderOptions::render_target_bytes() const {
    return std::size_t(width) * std::size_t(height) * render_target_bytes_per_pixel;
}

std::size_t RenderOptions::model_memory_limit_bytes() const {
    return memory_limit_bytes() - std::min(memory_limit_bytes(), render_target_bytes());
}

pipeline::OrbitPose RenderOptions::camera_pose() const { return {camera[0], camera[1], camera[2], glm::vec3(0)}; }

pipeline::FrameSettings RenderOptions::frame_settings() const {
    using namespace pipeline;
    FrameSettings s = settings;
    s.border = parse_choice("--border", border, choices_of(BorderMode{}));
    s.mean_filter_kernel = parse_choice("--mean-filter-kernel", kernel, choices_of(MeanFilterKernel{}));
    s.ssao = parse_choice("--ssao", ssao, on_off_choices());
    s.ssao_half_resolution = parse_choice("--ssao-resolution", ssao_resolution, ssao_resolution_choices());
    s.contours = parse_choice("--contours", contours, on_off_choices());
    s.only = parse_choice("--only", only, choices_of(OnlyLayer{}));
    s.draw = parse_choice("--draw", draw, choices_of(DrawMode{}));
    s.stage2_passes = parse_choice("--stage2-passes", stage2_passes, choices_of(Stage2Passes{}));
    s.seeds = parse_choice("--seeds", seeds, choices_of(SeedSource{}));
    s.primaries = parse_choice("--primaries", cut_volumes.primaries, primaries_choices());
    const std::vector<std::string> strategies = cut_strategy_names();
    if (std::find(strategies.begin(), strategies.end(), s.strategy) == strategies.end())
        throw std::invalid_argument("--strategy '" + s.strategy + "': expected " + joined_choices(strategies));
    for (float a : aperture)
        if (!(a >= 0 && a <= 180))
            throw std::invalid_argument("--aperture " + std::to_string(a) + ": expected a full opening angle 0..180 degrees");
    s.aperture_h_deg = aperture[0];
    s.aperture_v_deg = aperture[1];
    if (aperture_180) set_aperture_180(s);
    if (s.mean_filter < 0 || s.mean_filter > 65 || (s.mean_filter > 1 && s.mean_filter % 2 == 0))
        throw std::invalid_argument("--mean-filter " + std::to_string(s.mean_filter) + ": expected 0 (off) or an odd size 3..65");
    if (!(s.border_width_px >= 1 && s.border_width_px <= 32))
        throw std::invalid_argument("--border-width: expected 1..32 pixels");
    if (!(s.line_width_px >= 0 && s.line_width_px <= 16)) throw std::invalid_argument("--line-width: expected 0..16 pixels");
    return s;
}

nlohmann::json RenderOptions::describe() const {
    const pipeline::FrameSettings s = frame_settings();
    nlohmann::json description = {{"model", model}, {"property", property}, {"range", range}, {"colour_range", colour_range},
            {"primary_fraction", primary_fraction}, {"step", step}, {"caption", caption}, {"ijk_box", ijk_box}, {"select_by", select_by}, {"strategy", s.strategy}, {"draw", pipeline::to_string(s.draw)}, {"stage2_passes", pipeline::to_string(s.stage2_passes)}, {"seeds", pipeline::to_string(s.seeds)},
            {"aperture_deg", {s.aperture_h_deg, s.aperture_v_deg}}, {"back_margin", s.back_margin},
            {"border", pipeline::to_string(s.border)}, {"border_width_px", s.border_width_px},
            {"line_width_px", s.line_width_px}, {"mean_filter", s.mean_filter},
            {"mean_filter_kernel", pipeline::to_string(s.mean_filter_kernel)}, {"ssao", s.ssao},
            {"ssao_samples", s.ssao_samples}, {"ssao_radius", s.ssao_radius}, {"ssao_strength", s.ssao_strength},
            {"ssao_min_factor", s.ssao_min_factor},
            {"ssao_resolution", s.ssao_half_resolution ? "half" : "full"}, {"saturation", s.saturation},
            {"silhouette", s.silhouette}, {"silhouette_width_px", s.silhouette_width_px}, {"contours", s.contours},
            {"hide_internal_lines", s.hide_internal_lines}, {"see_through", s.see_through}, {"only", pipeline::to_string(s.only)},
            {"scale", scale}, {"text_height_px", text_height_px},
            {"camera", camera}, {"freeze_camera", freeze_camera}, {"z_scale", z_scale},
            {"fovy_deg", pipeline::default_fovy_deg}, {"egl_platform", egl_platform}, {"exact_check", exact_check},
            {"wells", wells}, {"well_radius", well_radius}};
    description.update(cut_volumes.describe());
    return description;
}

void add_selection_options(CLI::App& c, RenderOptions& o) {
    c.add_option("--property", o.property, "property that colours cells and selects primaries (default PORO)")
        ->check(property_name());
    c.add_option("--range", o.range, "primary range LO HI of the property")->expected(2)->check(finite_in(-FLT_MAX, FLT_MAX));
    c.add_option("--colour-range", o.colour_range,
                 "colour scale LO HI of the property (default: its 2nd-98th percentile; animate: min-max over the "
                 "animated steps): one scale for frames of several steps")
        ->expected(2)
        ->check(finite_in(-FLT_MAX, FLT_MAX));
    c.add_option("--primary-fraction", o.primary_fraction, "primaries = this top fraction of active cells (default 0.01)")
        ->check(finite_above(0, 1));
    c.add_option("--time-step,--step", o.step,
                 "report step of a dynamic property: the K-th in the file, 0-based (--step: the same)")
        ->check(finite_in(0, 1e6));
    // Dimensions are at most 1e8 (the GRDECL reader's bound); the box is checked against the grid's.
    c.add_option("--ijk-box", o.ijk_box, "restrict primaries to I0 J0 K0 I1 J1 K1 (0-based, inclusive)")
        ->expected(6)
        ->check(finite_in(0, 1e8));
}

void add_frame_options(CLI::App& c, RenderOptions& o) {
    c.add_option("--strategy", o.settings.strategy, "cut-surface strategy (default auto: frustum-clusters, one frustum per IJK box of adjacent primaries, below 10,000 primary cells on a GPU and 500 on a software rasteriser such as llvmpipe, frustum-sweep from there; frustum: one per primary, the paper's)")
        ->capture_default_str()
        ->check(one_of(pipeline::cut_strategy_names()));
    add_choice(c, "--draw", o.draw, pipeline::choices_of(pipeline::DrawMode{}),
               "stage 2 faces: visible (GPU culling against the frustum and the cut) | all-faces (the paper's path)");
    add_choice(c, "--stage2-passes", o.stage2_passes, pipeline::choices_of(pipeline::Stage2Passes{}),
               "visible path: deferred (the draw makes the cut test only, a compute pass shades each pixel once; the default) | 1 (every fragment shaded) | 2 (cut test and depth first, then the faces drawn again, shading once per pixel)");
    add_choice(c, "--seeds", o.seeds, pipeline::choices_of(pipeline::SeedSource{}), "seeds of the distance-transform strategies");
    add_choice(c, "--border", o.border, pipeline::choices_of(pipeline::BorderMode{}), "border lines");
    c.add_option("--border-width", o.settings.border_width_px, "border line width w, pixels")
        ->check(finite_in(1, 32, "pixels"));
    c.add_option("--line-width", o.settings.line_width_px, "cell edge line width, pixels (0: none)")
        ->check(finite_in(0, 16, "pixels"));
    c.add_option("--mean-filter", o.settings.mean_filter, "mean filter size k (odd; 0 = off)")->check(finite_in(0, 65));
    add_choice(c, "--mean-filter-kernel", o.kernel, pipeline::choices_of(pipeline::MeanFilterKernel{}),
               "mean filter kernel (distance-scaled: radius shrinking with distance to the camera)");
    add_choice(c, "--ssao", o.ssao, pipeline::on_off_choices(), "screen-space ambient occlusion");
    add_choice(c, "--ssao-resolution", o.ssao_resolution, pipeline::ssao_resolution_choices(),
               "half (occlusion for one pixel in four, upsampled by depth; the default) | full (every pixel, as the paper)");
    c.add_option("--aperture", o.aperture,
                 "horizontal and vertical aperture H V: full opening angles, degrees 0..180 (each wall leans out by "
                 "half; 180: flat)")
        ->expected(2)
        ->check(finite_in(0, 180, "degrees"));
    c.add_flag("--aperture-180", o.aperture_180, "remove everything between the primaries and the camera");
    c.add_option("--back-margin", o.settings.back_margin, "back-plane margin, fraction of the model radius")
        ->check(finite_in(0, 1, "of the model radius"));
    c.add_flag("--saturation", o.settings.saturation, "saturation contrast between primaries and secondaries");
    c.add_flag("--silhouette", o.settings.silhouette, "silhouette of the primary cluster");
    // Each silhouette pixel looks at every pixel within the width: 64 is already a very wide band.
    c.add_option("--silhouette-width", o.settings.silhouette_width_px, "silhouette width, pixels")
        ->check(finite_in(1, 64, "pixels"));
    c.add_flag("--hide-internal-lines", o.settings.hide_internal_lines, "no cell edges on the cut fill");
    c.add_flag("--see-through", o.settings.see_through,
               "let the cut leave the model through its rear shell (the paper's frustums; default: the cut "
               "stops just in front of the farthest shell surface, which shows as cut fill)");
    add_choice(c, "--contours", o.contours, pipeline::on_off_choices(), "shell contour lines");
    add_choice(c, "--only", o.only, pipeline::choices_of(pipeline::OnlyLayer{}), "layers drawn");
    add_choice(c, "--scale", o.scale, pipeline::choices_of(pipeline::ColourScale{}),
               "colour scale: auto (logarithmic for permeabilities, PERM*; linear otherwise) | linear | log");
    // 200 px capitals already fill a 4K image's colour bar with a handful of digits.
    c.add_option("--text-height", o.text_height_px,
                 "capitals of the colour bar's text at least this tall, pixels (default: 2% of the image height); "
                 "7 pt at a figure's printed width W mm is 2.47 / W of its width in pixels")
        ->check(finite_in(0, 200, "pixels"));
    c.add_flag("!--no-colour-bar", o.settings.colour_bar, "leave out the colour bar");
}

void add_scene_options(CLI::App& c, RenderOptions& o) {
    c.add_option("model", o.model,
                 "GRDECL file(s) loaded onto one grid (grid first, then properties), preset:NAME, or a simulator case "
                 "CASE.EGRID (or CASE) with CASE.INIT and CASE.UNRST beside it")
        ->required()
        ->check(utf8_text());
    add_selection_options(c, o);
    add_frame_options(c, o);
    // DIST in render units; 1e9 is far beyond any model's framing distance (metres, z-scaled).
    check_orbit_values(*c.add_option("--camera", o.camera, "AZ EL DIST: degrees around the model centre; DIST 0 frames the model")
                            ->expected(3),
                       1e9);
    check_orbit_values(*c.add_option("--freeze-camera", o.freeze_camera, "freeze view: the cut is made from this AZ EL DIST")
                            ->expected(3),
                       1e9);
    // 32768 is the largest texture side any current GL reports; the renderer checks the context's own
    // limit and the memory limit bounds W x H.
    c.add_option("--size", o.size, "image W H, pixels")->expected(2)->check(finite_in(16, 32768, "pixels"));
    // Vertical exaggerations beyond 1000 flatten every model into a line.
    c.add_option("--z-scale", o.z_scale, "vertical exaggeration (0: automatic)")->check(finite_in(0, 1000));
    add_memory_limit_option(c, o.memory_limit_gb, "models and render targets");
    add_cut_volume_options(c, o.cut_volumes);
    add_well_options(c, o.wells, o.well_radius);
    c.callback([&o] {
        check_well_option(o.wells);
        o.width = o.size[0];
        o.height = o.size[1];
        finish_cut_volume_options(o.cut_volumes);
        try {
            check_primaries_none(o.cut_volumes, primary_selecting_option(o), o.only == "primaries");
        } catch (const std::invalid_argument& e) {
            throw CLI::ValidationError(e.what());
        }
        // Render targets are reserved from the one memory budget before the model is read.
        if (o.render_target_bytes() > o.memory_limit_bytes())
            throw CLI::ValidationError("--size", memory_limit_problem(o.render_target_bytes(), o.memory_limit_bytes(),
                                                                      "render targets of " + std::to_string(o.width) +
                                                                          " x " + std::to_string(o.height) + " pixels"));
        if (o.freeze_camera.size() == 3)
            o.freeze_pose = pipeline::OrbitPose{o.freeze_camera[0], o.freeze_camera[1], o.freeze_camera[2], glm::vec3(0)};
    });
}

void add_caption_option(CLI::App& c, RenderOptions& o) {
    c.add_flag("!--no-caption", o.caption, "leave a dynamic property's date and report step out of the frame (drawn at its top left)");
}

void add_render_options(CLI::App& c, RenderOptions& o) {
    add_scene_options(c, o);
    add_caption_option(c, o);
    c.add_option("--out", o.out, "output PNG")->required()->check(writable_output());
    c.add_option("--stats", o.stats, "write stage times, metrics and configuration as JSON")->check(writable_output());
    c.add_option("--cell-ids", o.cell_ids,
                 "write the final frame's Eclipse cell index + 1 per pixel as an RGBA8 PNG "
                 "(R + 256 G + 65536 B + 16777216 A; 0 = no cell)")
        ->check(writable_output());
    c.add_option("--select-by", o.select_by,
                 "choose primaries by this property (its --range or --primary-fraction) while --property colours "
                 "the cells: two properties in one frame")
        ->check(property_name());
    c.add_flag("--baseline", o.baseline, "also time a plain shaded frame of the whole model (baseline_ms)");
    c.add_flag("!--no-metrics", o.metrics, "skip the image metrics (3 extra untimed frames)");
    c.add_flag("--exact-check", o.exact_check,
               "compare the strategy's cut (before the mean filter) with the exact cone field from the same seeds "
               "(stats.json cut_vs_exact)");
    c.add_option("--warmup", o.warmup, "untimed frames first")->check(finite_in(0, 100));
    c.add_option("--repeat", o.repeat, "timed frames; stats hold medians")->check(finite_in(1, 1000));
    c.add_option("--egl-platform", o.egl_platform, "auto|surfaceless|device")
        ->check(one_of({"auto", "surfaceless", "device"}));
    c.add_option("--rank-slabs", o.rank_slabs,
                 "under mpirun: cut the model into one slab of whole layers per rank along i, j or k")
        ->check(one_of({"i", "j", "k"}));
}

annotation::ColourBarLabel PropertyChoice::colour_bar_label(bool mark_primary_range) const {
    annotation::ColourBarLabel bar{name, colour_range.min, colour_range.max, annotation::property_unit(name, unit_system), log_scale};
    bar.min_text_px = text_height_px;
    if (mark_primary_range) bar.primary_range = annotation::ColourBarLabel::Span{primary_range.min, primary_range.max};
    return bar;
}

grid::PrimaryRange given_colour_range(const std::vector<float>& range, bool log_scale) {
    if (range.size() != 2 || !(range[0] < range[1]))
        throw std::invalid_argument("--colour-range: expected LO HI with LO < HI");
    if (log_scale && !(range[0] > 0))
        throw std::invalid_argument("--colour-range: expected LO > 0 on a log scale (--scale linear for others)");
    return {range[0], range[1]};
}

PropertyChoice choose_property(const grid::CornerPointGrid& grid, const RenderOptions& options, int first_layer) {
    PropertyChoice choice;
    const std::vector<std::string> statics = grid.property_names();
    const std::vector<std::string> dynamics = grid.dynamic_property_names();
    const std::string name = options.property.empty() ? default_property_name(grid) : options.property;
    if (name.empty()) {
        // No property in the model: colour and select by layer index so the frame still says something.
        choice.name = choice.label = "K (layer index; the model has no property)";
        choice.owned.resize(grid.cell_count());
        for (std::size_t c = 0; c < grid.cell_count(); ++c) choice.owned[c] = float(grid::cell_ijk(grid.dims(), c).k + first_layer);
    } else if (const std::vector<float>* values = grid.property(name); values && options.step < 0) {
        choice.name = choice.label = name;
        choice.external = values;
    } else if (grid.step_count(name) > 0) {
        const int step = std::max(options.step, 0);
        if (std::size_t(step) >= grid.step_count(name))
            throw std::invalid_argument("--time-step " + std::to_string(step) + ": property " + name + " has " +
                                        std::to_string(grid.step_count(name)) + " time steps (0-based)");
        choice.name = name;
        choice.label = name + " step " + std::to_string(step);
        choice.external = grid.dynamic_property(name, std::size_t(step));
        // A simulator case's step is read on demand (hold_time_step) before a property is chosen.
        if (!choice.external)
            throw std::logic_error("--time-step " + std::to_string(step) + ": step of " + name + " not read before use");
    } else if (values) {
        throw std::invalid_argument("--time-step: property " + name + " is static (dynamic ones: " + names_of(dynamics) + ")");
    } else if (const std::vector<std::int32_t>* integers = grid.int_property(name); integers && options.step < 0) {
        // Integer properties (FACIES, *NUM) colour and select as reals: every int32 class is exact
        // up to 2^24, far beyond any class count.
        choice.name = choice.label = name;
        choice.owned.assign(integers->begin(), integers->end());
    } else {
        throw std::invalid_argument("--property " + name + ": not in the model (static: " + names_of(statics) +
                                    "; integer: " + names_of(grid.int_property_names()) + "; dynamic: " +
                                    names_of(dynamics) + ")");
    }
    const pipeline::ColourScale scale = parse_choice("--scale", options.scale, pipeline::choices_of(pipeline::ColourScale{}));
    choice.log_scale = scale == pipeline::ColourScale::log ||
                       (scale == pipeline::ColourScale::automatic && choice.name.rfind("PERM", 0) == 0);
    // 2nd to 98th percentile: one outlier (a 5000 mD streak among 50 mD rock) would otherwise
    // squeeze every other cell into one end of the colour map. Values beyond it take the end colours.
    constexpr double colour_quantiles[2] = {0.02, 0.98};
    choice.colour_range = grid::active_quantile_range(grid, choice.values(), choice.name, colour_quantiles[0],
                                                      colour_quantiles[1], choice.log_scale);
    if (choice.log_scale && !(choice.colour_range.min > 0)) {
        if (scale == pipeline::ColourScale::log)
            throw std::invalid_argument("--scale log: property " + choice.name + " has no value above 0 in an active cell");
        choice.log_scale = false;  // automatic: a permeability with no positive value stays linear
        choice.colour_range = grid::active_quantile_range(grid, choice.values(), choice.name, colour_quantiles[0],
                                                          colour_quantiles[1], false);
    }
    choice.text_height_px = options.text_height_px;
    if (!options.colour_range.empty()) choice.colour_range = given_colour_range(options.colour_range, choice.log_scale);
    choice.unit_system = grid.metadata().unit_system;
    return choice;
}

grid::PrimaryRange colour_range_holding(grid::PrimaryRange colour, const grid::PrimaryRange& primary,
                                        const grid::PrimaryRange& extremes, bool log_scale) {
    const float low = std::max(primary.min, extremes.min), high = std::min(primary.max, extremes.max);
    if (!(low <= high)) return colour;  // no value in the primary range: nothing to show in its colours
    if (!log_scale || low > 0) colour.min = std::min(colour.min, low);
    colour.max = std::max(colour.max, high);
    return colour;
}

bool colour_range_holds_primaries(const RenderOptions& options) {
    return options.colour_range.empty() && options.select_by.empty() && options.frame_settings().primaries;
}

std::optional<grid::IjkBox> choose_primary_range(const grid::CornerPointGrid& grid, PropertyChoice& property,
                                                 const RenderOptions& options) {
    std::optional<grid::IjkBox> box = selection_box(options, grid.dims());
    if (!options.range.empty())
        property.primary_range = {options.range[0], options.range[1]};
    else
        property.primary_range = grid::range_for_fraction(grid, property.values(), property.name, primary_fraction(options));
    if (colour_range_holds_primaries(options))
        property.colour_range = colour_range_holding(property.colour_range, property.primary_range,
                                                     grid::active_value_range(grid, property.values(), property.name),
                                                     property.log_scale);
    return box;
}

std::optional<SecondPropertySelection> select_by_second_property(const grid::CornerPointGrid& grid,
                                                                 const RenderOptions& options) {
    if (options.select_by.empty()) return std::nullopt;
    RenderOptions by = options;
    by.property = options.select_by;
    if (grid.step_count(options.select_by) == 0) by.step = -1;  // --step belongs to a dynamic colouring property
    PropertyChoice chooser;
    try {
        chooser = choose_property(grid, by);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--select-by: ") + e.what());
    }
    const std::optional<grid::IjkBox> box = choose_primary_range(grid, chooser, by);
    return SecondPropertySelection{chooser.label, chooser.primary_range,
                                   grid::select_primaries(grid, chooser.values(), chooser.name, chooser.primary_range, box)};
}

std::optional<std::string> property_to_load(const RenderOptions& options) {
    return options.select_by == generators::generated_dynamic_property ? options.select_by : options.property;
}

double primary_fraction(const RenderOptions& options) { return options.primary_fraction > 0 ? options.primary_fraction : 0.01; }

std::optional<grid::IjkBox> selection_box(const RenderOptions& options, const grid::GridDims& d) {
    if (!options.range.empty() && options.primary_fraction > 0)
        throw std::invalid_argument("give either --range or --primary-fraction, not both");
    if (!options.range.empty() && !(options.range[0] <= options.range[1]))
        throw std::invalid_argument("--range: expected LO <= HI, found " + number_text(options.range[0]) + " > " +
                                    number_text(options.range[1]));
    std::optional<grid::IjkBox> box;
    if (options.ijk_box.size() == 6) {
        const auto& b = options.ijk_box;
        const int size[3] = {d.nx, d.ny, d.nz};
        for (int axis = 0; axis < 3; ++axis)
            if (b[std::size_t(axis)] > b[std::size_t(axis) + 3] || b[std::size_t(axis) + 3] >= size[axis])
                throw std::invalid_argument(
                    "--ijk-box: expected 0 <= I0 <= I1 < NX, 0 <= J0 <= J1 < NY, 0 <= K0 <= K1 < NZ for the grid's " +
                    std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " + std::to_string(d.nz) + " cells, found " +
                    std::to_string(b[0]) + " " + std::to_string(b[1]) + " " + std::to_string(b[2]) + " " +
                    std::to_string(b[3]) + " " + std::to_string(b[4]) + " " + std::to_string(b[5]));
        box = grid::IjkBox{b[0], b[1], b[2], b[3], b[4], b[5]};
    }
    return box;
}

}  // namespace cutaway::app
