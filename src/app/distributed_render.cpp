// `mpirun -np N cutaway render ...` (distributed_render.h). No rank holds the whole model: each
// loads only its block with its halo (a preset generates it, a file keeps only its values; first
// an equal split to count the active cells per layer, then the balanced slab), and what must be
// global (active cells per layer, model frame, face tolerance, colour and primary ranges) comes
// from the blocks by collectives, equal to what one process computes from the whole model.
#include "app/distributed_render.h"
#include "cutaway/renderer_readback.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app_core/exit_status.h"
#include "app_core/frame_wells.h"
#include "app_core/heap_policy.h"
#include "app_core/model_source.h"
#include "app_core/render_report.h"
#include "app_core/run_context.h"
#include "app_core/run_context_json.h"
#include "cutaway/cell_id_image.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "cutaway/cutaway_renderer.h"
#include "distributed/global_model.h"
#include "distributed/mpi_session.h"
#include "distributed/rank_blocks.h"
#include "distributed/rank_renderer.h"
#include "gl/gl_context.h"
#include "gl/image.h"
#include "grid/face_classification.h"
#include "grid/grid_box.h"
#include "io/output_batch.h"
#include "io/output_error.h"
#include "metrics/median.h"

namespace cutaway::app {
namespace {

using nlohmann::json;

/// Stages a distributed frame adds (CutawayRenderer's FrameHooks).
const std::vector<std::string> combine_stages{"cut_combine", "composite"};

void check_distributed_options(const RenderOptions& options) {
    if (options.exact_check)
        throw std::invalid_argument("--exact-check: not supported under mpirun (it recomputes the cut on one renderer)");
    if (options.baseline) throw std::invalid_argument("--baseline: not supported under mpirun");
    if (!options.select_by.empty())
        throw std::invalid_argument("--select-by: not supported under mpirun (the ranks select by the colouring property on the GPU)");
}

/// A failure every rank agreed on: the lowest failing rank's message, the highest exit code.
struct AgreedFailure {
    std::string message;
    int code = 0;
};

/// Runs `step` on every rank, then all agree (collective): when it failed on any rank, every rank
/// throws AgreedFailure, so all leave together and rank 0 reports why. A step may hold
/// collectives only where every rank reaches them or every rank has thrown before them.
void on_all_ranks(const distributed::MpiSession& mpi, const std::function<void()>& step) {
    std::exception_ptr failure;
    try {
        step();
    } catch (...) {
        failure = std::current_exception();
    }
    const std::string error = mpi.first_error(failure ? exit_status_of(failure).message : std::string());
    const int code = int(mpi.max(failure ? double(exit_status_of(failure).code) : 0.0));
    if (!error.empty()) throw AgreedFailure{error, code};
}

/// Collective: the tubes of `chosen` on the whole model, each rank giving the points of their paths
/// its block (the cells `source` of `whole`) holds; an element-wise max over the ranks fills in
/// the others (wells::well_path_points marks them -infinity). `bounds`: the whole model's.
pipeline::WellSet distributed_wells(const distributed::MpiSession& mpi, const ChosenWells& chosen, const LoadedModel& model,
                                    const grid::IjkBox& source, const grid::Box3& bounds, double well_radius) {
    const wells::WellheadLevel level = wells::wellhead_level(bounds, model.grid.depth_direction());
    std::vector<double> numbers;
    for (const wells::Well& well : chosen.wells)
        for (const grid::Point3& p : wells::well_path_points(well, model.grid, level, {source.i0, source.j0, source.k0}))
            numbers.insert(numbers.end(), {p.x, p.y, p.z});
    mpi.max(numbers);
    std::vector<std::vector<grid::Point3>> paths;
    std::size_t at = 0;
    for (const wells::Well& well : chosen.wells) {
        std::vector<grid::Point3> points;
        for (std::size_t p = 0; p < 2 + well.connections.size(); ++p, at += 3) points.push_back({numbers[at], numbers[at + 1], numbers[at + 2]});
        paths.push_back(wells::assemble_well_path(well, points));
    }
    // The widest of the ranks' radii: every rank draws the same tubes.
    return drawn_wells(chosen.wells, paths, well_radius, mpi.max(wells::default_well_radius(model.grid, bounds)));
}

/// The values of `values` (one per cell of `source`, the cells `source_box`) at the active cells
/// of `box`: this rank's own cells, without the halo.
std::vector<float> own_active_values(const grid::CornerPointGrid& source, const grid::IjkBox& source_box,
                                     const std::vector<float>& values, const grid::IjkBox& box) {
    std::vector<float> own;
    const grid::GridDims& d = source.dims();
    for (int k = box.k0; k <= box.k1; ++k)
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i)
                if (const std::size_t cell = d.cell_index(i - source_box.i0, j - source_box.j0, k - source_box.k0);
                    source.active(cell))
                    own.push_back(values[cell]);
    return own;
}

/// One rank's part of the run, prepared in agreed steps (on_all_ranks): the rank loads an equal
/// split's block to count the active cells per layer, then its balanced slab with the halo; the
/// global quantities come by collectives. start() builds the rank's renderer (collective: the
/// IceT context) and frees the loaded block.
struct RankScene {
    void prepare(const RenderOptions& options, const distributed::MpiSession& mpi) {
        const double rss_before = double(run_context::proc_status_bytes("VmRSS"));
        std::optional<grid::IjkBox> provisional;
        std::vector<std::uint64_t> active_per_layer;
        on_all_ranks(mpi, [&] {
            check_distributed_options(options);
            axis = distributed::slab_axis_from_name(options.rank_slabs);
            whole_dims = model_dims(options.model, options.model_memory_limit_bytes());
            ijk_box = selection_box(options, whole_dims);
            provisional = distributed::equal_slab(whole_dims, mpi.size(), mpi.rank(), axis);
            active_per_layer.assign(std::size_t(distributed::layer_count(whole_dims, axis)), 0);
            if (!provisional) return;
            model = load_block(options.model, *provisional, options.model_memory_limit_bytes(), options.property,
                               options.step, render_outputs(options));
            active_per_layer = distributed::active_per_layer(model.grid, *provisional, whole_dims, axis);
        });
        mpi.sum(active_per_layer);
        grid::PrimaryRange own_range;
        // The rank's own active values (for --primary-fraction) and their true extremes: the top
        // fraction reaches the largest value, beyond the colour range's percentile, and the colour
        // range widens to hold the primaries within them.
        std::vector<float> own_values;
        grid::PrimaryRange own_extremes{std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()};
        on_all_ranks(mpi, [&] {
            slab = distributed::split_into_slabs(active_per_layer, whole_dims, mpi.size(), axis)[std::size_t(mpi.rank())];
            for (std::uint64_t count : active_per_layer) whole_active += count;
            source = grid::with_halo(slab, whole_dims);
            if (!(provisional && *provisional == source)) {
                const double first_load_s = model.load_seconds;
                model = {};
                model = load_block(options.model, source, options.model_memory_limit_bytes(), options.property,
                                   options.step, render_outputs(options));
                model.load_seconds += first_load_s;
            }
            property = choose_property(model.grid, options, source.k0);
            if (options.caption) caption = step_caption(model, property.name, options.step);
            own_range = property.colour_range;
            own_values = own_active_values(model.grid, source, property.values(), slab);
            if (!own_values.empty()) {
                const auto [low, high] = std::minmax_element(own_values.begin(), own_values.end());
                own_extremes = {*low, *high};
            }
        });
        load_peak_bytes = double(run_context::proc_status_bytes("VmHWM")) - rss_before;
        ChosenWells chosen_wells;
        on_all_ranks(mpi, [&] { chosen_wells = choose_wells(model, whole_dims, options.wells, options.step); });
        on_all_ranks(mpi, [&] {
            const distributed::ModelPart part{model.grid, source, whole_dims};
            const grid::Box3 bounds = distributed::global_bounds(mpi, part);
            tolerance = grid::face_tolerance_for(bounds);
            frame = distributed::global_model_frame(mpi, part, bounds, options.z_scale);
            property.colour_range = distributed::global_value_range(mpi, own_range);
            wells = distributed_wells(mpi, chosen_wells, model, source, bounds, options.well_radius);
            pipeline::keep_wellheads_in_view(frame, wells);  // framed as the single-process frame is
            const grid::PrimaryRange extremes = distributed::global_value_range(mpi, own_extremes);
            property.primary_range = options.range.empty() ? distributed::global_range_for_fraction(
                                                                 mpi, own_values, primary_fraction(options), extremes.max)
                                                           : grid::PrimaryRange{options.range[0], options.range[1]};
            if (colour_range_holds_primaries(options))
                property.colour_range =
                    colour_range_holding(property.colour_range, property.primary_range, extremes, property.log_scale);
        });
        on_all_ranks(mpi, [&] {
            check_view(frame, options);
            // Every rank draws every volume into its cut (the same on each: the max is unchanged).
            // A `well:` volume cuts around a well --wells draws (the ranks assemble only those paths).
            cut_volumes = load_cut_volumes(options.cut_volumes, frame, paths_of(wells), options.model_memory_limit_bytes());
            block = distributed::make_grid_block(model.grid, source, whole_dims, slab, tolerance);
            context = gl::create_context(options.context_options());
            shaders = std::make_unique<gl::ShaderLibrary>(gl::ShaderLibrary::default_root());
            const int limit = pipeline::max_image_side();
            if (options.width > limit || options.height > limit)
                throw std::invalid_argument("--size " + std::to_string(options.width) + " " +
                                            std::to_string(options.height) + ": expected sides of at most " +
                                            std::to_string(limit) + " (this GL's texture/viewport limit)");
        });
    }

    void start(const RenderOptions& options) {
        const auto setup_started = std::chrono::steady_clock::now();
        rank.emplace(*shaders, std::move(*block), frame, options.width, options.height);
        rank->renderer().set_wells(wells);
        const bool primaries = options.frame_settings().primaries;
        rank->set_colouring(property.values(), property.colour_bar_label(primaries));
        rank->renderer().set_cut_volumes(cut_volumes.meshes);
        if (primaries)
            rank->select_range(property.primary_range, ijk_box);
        else
            rank->renderer().select(pipeline::Primaries::none());
        glFinish();
        setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_started).count();
        property.owned = std::vector<float>();  // (= {} would keep the capacity)
        property.external = nullptr;
        model.grid = {};  // the loaded block and its halo go; the renderer's block stays
        // Framed as the single-process frame is: beside the colour bar and below the caption rank 0 draws.
        pipeline::FrameSettings settings = options.frame_settings();
        settings.caption = caption;
        const pipeline::RendererStatus status = rank->renderer().status(settings);
        const float bar_width = status.colour_bar_reserved_width, caption_rows = status.caption_reserved_height;
        camera = pipeline::make_orbit_camera(frame, options.camera_pose(), options.width, options.height, bar_width, 0, caption_rows);
        if (options.freeze_pose)
            rank->renderer().freeze(pipeline::make_orbit_camera(frame, *options.freeze_pose, options.width, options.height, bar_width,
                                                                0, caption_rows));
    }

    grid::GridDims whole_dims;
    LoadedModel model;  ///< this rank's block with its halo: the cells `source`
    grid::IjkBox source;
    PropertyChoice property;
    std::string caption;  ///< the frame's report step (step_caption), empty for a static property
    std::optional<grid::IjkBox> ijk_box;
    pipeline::ModelFrame frame;
    CutVolumeSet cut_volumes;
    pipeline::WellSet wells;
    double tolerance = 0;
    distributed::SlabAxis axis = distributed::SlabAxis::k;
    grid::IjkBox slab;
    std::optional<distributed::GridBlock> block;
    double setup_seconds = 0, load_peak_bytes = 0;
    std::size_t whole_active = 0;
    std::unique_ptr<gl::GlContext> context;
    std::unique_ptr<gl::ShaderLibrary> shaders;
    std::optional<distributed::RankRenderer> rank;
    pipeline::Camera camera;
};

/// Per-frame exchange measurements of one rank.
struct ExchangeTimes {
    std::vector<double> allreduce_ms, allreduce_wait_ms, icet_ms, icet_wait_ms, icet_bytes, reduce_bytes;
    void add(const distributed::ExchangeCosts& c) {
        allreduce_ms.push_back(c.allreduce_ms);
        allreduce_wait_ms.push_back(c.allreduce_wait_ms);
        icet_ms.push_back(c.composite_ms);
        icet_wait_ms.push_back(c.composite_wait_ms);
        icet_bytes.push_back(double(c.icet_bytes_sent));
        reduce_bytes.push_back(double(c.reduce_bytes_sent));
    }
};

/// One rank's numbers, in the order of rank_fields (gathered at rank 0).
std::vector<double> rank_numbers(const RankScene& scene, const json& stages, const ExchangeTimes& exchange,
                                 const std::vector<std::string>& stage_order) {
    const distributed::RankRenderer& rank = *scene.rank;
    const grid::CornerPointGrid& g = rank.block().grid;
    std::vector<double> numbers{double(g.cell_count()),
                                double(g.active_count()),
                                double(rank.renderer().status().primary_cells),
                                double(rank.renderer().status().gpu_memory_bytes()),
                                double(g.geometry_bytes()),
                                double(run_context::proc_status_bytes("VmHWM")),
                                double(run_context::proc_status_bytes("VmRSS")),
                                scene.load_peak_bytes,
                                scene.model.load_seconds,
                                scene.setup_seconds,
                                metrics::median(exchange.allreduce_ms),
                                metrics::median(exchange.icet_ms),
                                metrics::median(exchange.icet_bytes),
                                metrics::median(exchange.reduce_bytes),
                                metrics::median(exchange.allreduce_wait_ms),
                                metrics::median(exchange.icet_wait_ms)};
    const grid::IjkBox& b = rank.block().box;
    for (int bound : {b.i0, b.j0, b.k0, b.i1, b.j1, b.k1}) numbers.push_back(double(bound));
    for (const std::string& name : stage_order) numbers.push_back(stages["stages_ms"][name].get<double>());
    return numbers;
}

const std::vector<std::string> rank_fields{"cells", "active_cells", "primary_cells", "gpu_memory_bytes",
                                           "block_geometry_bytes", "peak_rss_bytes", "rss_bytes_after_frames",
                                           "load_peak_bytes", "model_load_s", "renderer_setup_s",
                                           "allreduce_mpi_ms", "icet_composite_ms", "icet_bytes_sent",
                                           "shell_reduce_bytes_sent", "allreduce_wait_ms", "icet_wait_ms", "box_i0", "box_j0", "box_k0", "box_i1",
                                           "box_j1", "box_k1"};

/// Position of `field` in rank_fields.
std::size_t field_index(const std::string& field) {
    return std::size_t(std::find(rank_fields.begin(), rank_fields.end(), field) - rank_fields.begin());
}

json distributed_json(const distributed::MpiSession& mpi, const RankScene& scene, const std::vector<double>& gathered,
                      const std::vector<std::string>& stage_order, std::size_t allreduce_message_bytes) {
    const std::size_t per_rank = rank_fields.size() + stage_order.size();
    json ranks = json::array();
    std::vector<double> allreduce, icet, composite, cut_combine, allreduce_wait, icet_wait;
    double icet_bytes = 0, reduce_bytes = 0;
    for (int r = 0; r < mpi.size(); ++r) {
        const double* n = &gathered[std::size_t(r) * per_rank];
        json rank = {{"rank", r}};
        for (std::size_t f = 0; f < rank_fields.size(); ++f) rank[rank_fields[f]] = n[f];
        json stages = json::object();
        for (std::size_t s = 0; s < stage_order.size(); ++s) stages[stage_order[s]] = n[rank_fields.size() + s];
        rank["stages_ms"] = stages;
        ranks.push_back(rank);
        allreduce.push_back(n[field_index("allreduce_mpi_ms")]);
        icet.push_back(n[field_index("icet_composite_ms")]);
        allreduce_wait.push_back(n[field_index("allreduce_wait_ms")]);
        icet_wait.push_back(n[field_index("icet_wait_ms")]);
        icet_bytes += n[field_index("icet_bytes_sent")];
        reduce_bytes += n[field_index("shell_reduce_bytes_sent")];
        cut_combine.push_back(stages["cut_combine"].get<double>());
        composite.push_back(stages["composite"].get<double>());
    }
    const auto max_of = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    return {{"ranks", mpi.size()},
            {"slab_axis", distributed::slab_axis_name(scene.axis)},
            {"per_rank", ranks},
            {"allreduce_ms", max_of(allreduce)},
            {"composite_ms", max_of(icet)},
            {"allreduce_wait_ms", max_of(allreduce_wait)},
            {"composite_wait_ms", max_of(icet_wait)},
            {"cut_combine_stage_ms", max_of(cut_combine)},
            {"composite_stage_ms", max_of(composite)},
            {"bytes_per_frame",
             {{"allreduce_message_per_rank", allreduce_message_bytes},
              {"allreduce_sent_per_rank_estimate", mpi.size() > 1 ? 2.0 * double(mpi.size() - 1) / mpi.size() * double(allreduce_message_bytes) : 0.0},
              {"icet_sent_all_ranks", icet_bytes},
              {"shell_reduce_sent_all_ranks", reduce_bytes}}},
            {"notes",
             {{"allreduce_ms", "slowest rank's median MPI_Allreduce(MAX) of the cut and rear-shell depth (the MPI call only, after a barrier)"},
              {"allreduce_wait_ms", "longest median wait in the barrier before the allreduce: load imbalance of stage 1"},
              {"composite_wait_ms", "longest median wait in the barrier before IceT: load imbalance of stages 2 and 3"},
              {"composite_ms", "slowest rank's median of the two IceT Z-buffer composites plus the shell-depth MPI_Reduce(MIN)"},
              {"cut_combine_stage_ms", "the fenced stage: GPU read-back, allreduce, upload and the cut resolve pass"},
              {"composite_stage_ms", "the fenced stage: G-buffer read-back, packing, IceT, upload at rank 0"},
              {"allreduce_sent_per_rank_estimate", "2(N-1)/N x message (ring/Rabenseifner bound); MPI reports no byte count"},
              {"icet_sent_all_ranks", "ICET_BYTES_SENT summed over ranks and both composites"},
              {"model_load", "each rank loads only its block with a one-cell halo (a preset generates it; a file keeps only its values as it is parsed), first an equal split's block to count active cells per layer, then its balanced slab: load_peak_bytes is the peak resident growth while loading, peak_rss_bytes the rank's peak resident memory (VmHWM)"}}}};
}

int render_frames(const RenderOptions& options, const distributed::MpiSession& mpi, RankScene& scene) {
    scene.start(options);
    distributed::RankRenderer& rank = *scene.rank;
    const std::uint64_t primary_count = mpi.sum(rank.renderer().status().primary_cells);
    on_all_ranks(mpi, [&] {
        refuse_nothing_to_draw(options, primary_count, scene.property.name, scene.property.primary_range);
    });
    pipeline::FrameSettings settings = options.frame_settings();
    settings.caption = scene.caption;
    for (int i = 0; i < options.warmup; ++i) rank.render(settings, scene.camera);
    std::vector<pipeline::FrameTimes> runs;
    ExchangeTimes exchange;
    for (int i = 0; i < options.repeat; ++i) {
        runs.push_back(rank.render(settings, scene.camera));
        exchange.add(rank.last_exchange());
    }
    json stats = stage_statistics(runs, combine_stages);
    std::vector<std::string> stage_order;
    for (const auto& [name, value] : stats["stages_ms"].items()) stage_order.push_back(name);
    const std::vector<double> gathered = mpi.gather(rank_numbers(scene, stats, exchange, stage_order));
    const pipeline::FacesDrawn drawn = pipeline::FrameReadback(rank.renderer()).faces_drawn();
    const std::uint64_t faces_secondary = mpi.sum(drawn.secondary), faces_primary = mpi.sum(drawn.primary);
    if (!mpi.root()) return 0;

    // Committed together once the stats are written too (render_command.cpp).
    io::OutputBatch outputs;
    outputs.write(options.out, gl::encode_png(pipeline::FrameReadback(rank.renderer()).read_image(), options.out));
    if (!options.cell_ids.empty())
        outputs.write(options.cell_ids,
                      gl::encode_png(pipeline::encode_cell_ids(rank.composited_ids(), options.width, options.height),
                                     options.cell_ids));
    const PropertyChoice& property = scene.property;
    if (primary_count == 0 && settings.primaries)
        std::cerr << "cutaway render: no cell of " << property.name << " lies in the primary range ["
                  << property.primary_range.min << ", " << property.primary_range.max << "]; rendering the context only\n";
    stats["faces_drawn"] = {{"secondary", faces_secondary}, {"primary", faces_primary}, {"summed_over_ranks", true}};
    const pipeline::CutSurfaceEntry strategy = pipeline::find_cut_surface(rank.renderer().status(settings).cut_strategy);
    stats["cut_device"] = strategy.device;
    stats["readback_bytes"] = 0;  // the strategy's own; the exchange's read-backs are in "distributed"
    stats["frame_ms_unfenced"] = nullptr;
    stats["frame_ms_unfenced_absent"] = "not measured under mpirun";
    if (options.metrics)
        for (const char* metric : {"primary_exposure", "context_kept"}) {
            stats[metric] = nullptr;
            stats[std::string(metric) + "_absent"] =
                "not computed under mpirun (the metrics' extra frames are single-process; compare --cell-ids with a "
                "single-process run instead)";
        }
    stats["strategy"] = strategy_json(strategy, settings.strategy, rank.renderer().status().auto_sweep_from);
    stats.update(run_context_json(current_gl_device(scene.context->platform())));
    stats["size"] = {options.width, options.height};
    stats["cells"] = scene.whole_dims.cell_count();
    stats["active_cells"] = scene.whole_active;
    stats["primary_cells"] = primary_count;
    stats["model"] = scene.model.description;
    stats["model_load_s"] = scene.model.load_seconds;
    stats["renderer_setup_s"] = scene.setup_seconds;
    stats["property"] = {{"name", property.label}, {"primary_range", {property.primary_range.min, property.primary_range.max}},
                         {"colour_range", {property.colour_range.min, property.colour_range.max}}};
    stats["configuration"] = options.describe();
    stats["configuration"]["rank_slabs"] = options.rank_slabs;
    stats["configuration"]["cut_volumes"] = scene.cut_volumes.describe();
    stats["plan"] = rank.renderer().status().last_plan.describe();
    stats["warmup"] = options.warmup;
    stats["repeat"] = options.repeat;
    stats["distributed"] = distributed_json(mpi, scene, gathered, stage_order, rank.last_exchange().allreduce_bytes);
    if (!options.stats.empty()) outputs.write(options.stats, stats.dump(2) + '\n');
    outputs.commit();
    std::cout << "cutaway render: " << options.out << " (" << primary_count << " primary cells, " << mpi.size()
              << " ranks, total " << stats["stages_ms"]["total"].get<double>() << " ms median of " << options.repeat
              << ")\n";
    return 0;
}

}  // namespace

int run_distributed_render(const RenderOptions& options) {
    const distributed::MpiSession mpi;
    // Every rank builds its part without collectives, then all agree: a failure on any rank ends
    // all of them with rank 0 reporting it (the ranks check the same inputs, so an input error is
    // reported once).
    RankScene scene;
    try {
        // Before any rank reads the model: rank 0 alone checks that no output overwrites an input
        // or another output (one file system view, one message), and every rank learns its verdict.
        on_all_ranks(mpi, [&] {
            if (mpi.root()) refuse_render_overwrites(options);
        });
        scene.prepare(options, mpi);
    } catch (const AgreedFailure& failure) {
        if (mpi.root()) std::cerr << "cutaway: " << failure.message << '\n';
        return failure.code;
    }
    try {
        return render_frames(options, mpi, scene);
    } catch (const AgreedFailure& failure) {
        if (mpi.root()) std::cerr << "cutaway: " << failure.message << '\n';
        return failure.code;
    } catch (const io::OutputError& error) {
        // Rank 0 writes after the last collective, when the other ranks are done: it reports the
        // failed write and ends as a single process does (its OutputBatch removed what it staged).
        if (!mpi.root()) mpi.abort(exit_bad_input);
        std::cerr << "cutaway: " << error.what() << '\n';
        return exit_bad_input;
    } catch (...) {
        // Mid-frame a rank may fail alone while the others wait in a collective: end them all.
        std::cerr << "cutaway: rank " << mpi.rank() << " of " << mpi.size() << ": " << exit_status_of(std::current_exception()).message
                  << '\n';
        mpi.abort(exit_status_of(std::current_exception()).code);
    }
}

}  // namespace cutaway::app
