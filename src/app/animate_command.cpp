// `cutaway animate MODEL --property P --range LO HI --out FILE.mp4 [--stats FILE.json] ...`: a
// cutaway animation over report steps, encoded as H.264 MP4, with per-frame temporal metrics
// (issue 44). The MP4 is written under a temporary name and renamed at the end: an interrupted
// or failed run leaves none.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/animate_options.h"
#include "app/animation_summary.h"
#include "app/commands.h"
#include "app/interrupt_guard.h"
#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "app/progress_bar.h"
#include "app_core/render_report.h"
#include "app_core/run_context.h"
#include "app_core/run_context_json.h"
#include "app_core/frame_wells.h"
#include "app_core/step_value_sources.h"
#include "annotation/property_units.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/cutaway_renderer.h"
#include "cutaway/frame_caption.h"
#include "cutaway/renderer_readback.h"
#include "cutaway/temporal/coherence.h"
#include "cutaway/temporal/coherent_sequence.h"
#include "cutaway/temporal/step_values.h"
#include "eclipse/step_clock.h"
#include "gl/gl_context.h"
#include "gl/image.h"
#include "grid/primary_selection.h"
#include "io/mp4_encoder.h"
#include "io/output_batch.h"
#include "io/staged_file.h"
#include "metrics/image_metrics.h"
#include "metrics/temporal_metrics.h"

namespace cutaway::app {
namespace {

using nlohmann::json;

/// Per-cell arrays the animation holds besides the model: the sequence's, the renderer's compact
/// copy of the colouring (4 bytes) and the flags of the frame before (1).
constexpr std::size_t animation_bytes_per_cell = temporal::CoherentSequence::bytes_per_cell + 4 + 1;
/// Per-pixel arrays besides the render targets: the frame handed to ffmpeg and the one being
/// read (4 bytes each), two frames' cut states (1 each).
constexpr std::size_t animation_bytes_per_pixel = 4 * 2 + 2;

/// The report steps to animate: --steps, or all of them. Throws std::invalid_argument naming
/// --steps and the property's steps when out of range.
temporal::AnimationTimeline timeline_of(const AnimateOptions& options, std::size_t step_count, const std::string& property) {
    temporal::AnimationTimeline timeline;
    timeline.frames_per_step = std::size_t(options.frames_per_step);
    timeline.last_step = step_count - 1;
    if (options.steps.size() == 2) {
        if (options.steps[0] > options.steps[1] || std::size_t(options.steps[1]) >= step_count)
            throw std::invalid_argument("--steps " + std::to_string(options.steps[0]) + " " + std::to_string(options.steps[1]) +
                                        ": expected 0 <= FIRST <= LAST < " + std::to_string(step_count) + " (" + property +
                                        "'s report steps, 0-based)");
        timeline.first_step = std::size_t(options.steps[0]);
        timeline.last_step = std::size_t(options.steps[1]);
    }
    return timeline;
}

/// What the animation's report steps hold, read before the frames.
struct StepSurvey {
    grid::PrimaryRange colour_range;    ///< min and max over active cells of every step: one colour scale
    std::size_t most_primaries = 0;     ///< the largest primary set of a step (selected anew)
};

StepSurvey survey_steps(const grid::CornerPointGrid& grid, const temporal::StepValueSource& source,
                        const temporal::AnimationTimeline& timeline, const grid::PrimaryRange& primary_range,
                        const std::optional<grid::IjkBox>& box) {
    StepSurvey survey;
    survey.colour_range = temporal::value_range_over_steps(grid, source, timeline.first_step, timeline.last_step);
    for (std::size_t step = timeline.first_step; step <= timeline.last_step; ++step)
        survey.most_primaries = std::max(survey.most_primaries, grid::count_primaries(grid::select_primaries(
                                                                    grid, source.values(step), source.property(), primary_range, box)));
    return survey;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

metrics::PixelIds view(const pipeline::IdImage& ids) { return {ids.width, ids.height, ids.cell, ids.flags}; }

/// The drawn frame's image metrics into its stats entry: cut_flicker against `previous_states`
/// (the frame before's cut states, empty for the first frame; replaced by this frame's),
/// context_share, and primary_exposure against a primaries-only frame drawn with `primaries_only`.
void add_image_metrics(json& entry, pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& primaries_only,
                       const pipeline::Camera& camera, std::vector<metrics::CutState>& previous_states) {
    const pipeline::IdImage ids = pipeline::FrameReadback(renderer).read_ids();
    std::vector<metrics::CutState> states = metrics::cut_states(ids.cell, ids.flags);
    if (!previous_states.empty()) entry["cut_flicker"] = metrics::cut_flicker(previous_states, states).fraction;
    previous_states = std::move(states);
    entry["context_share"] = metrics::context_share(view(ids)).fraction;
    renderer.render(primaries_only, camera);
    const metrics::Exposure exposure = metrics::primary_exposure(view(pipeline::FrameReadback(renderer).read_ids()), view(ids));
    put_metric(entry, "primary_exposure", exposure.fraction, exposure.primary_pixels, "no primary pixel in the primaries-only frame");
}

/// Refuses what animate does not take, before any file is read.
void check_animate_options(const AnimateOptions& options) {
    const RenderOptions& scene = options.scene;
    if (scene.property.empty()) throw std::invalid_argument("--property: expected the dynamic property to animate (e.g. SWAT)");
    if (scene.step >= 0) throw std::invalid_argument("--step: animate shows report steps --steps FIRST LAST instead");
    if (!scene.select_by.empty()) throw std::invalid_argument("--select-by: not available in animate");
    std::vector<io::NamedFile> inputs;
    for (const std::string& model : scene.model) inputs.push_back({"the model", model});
    refuse_overwrites(inputs, {{"--out", options.out}, {"--stats", options.stats}});
    io::require_even_size(scene.width, scene.height);
}

/// The animation's value ranges: the primaries' (--range, or --primary-fraction of the first
/// animated step) and IJK box, the steps' survey, one colour range and the hysteresis band.
struct AnimationRanges {
    std::optional<grid::IjkBox> box;
    grid::PrimaryRange primary_range;
    StepSurvey survey;
    grid::PrimaryRange colour_range;
    float band = 0;
};

AnimationRanges animation_ranges(const AnimateOptions& options, const grid::CornerPointGrid& grid,
                                 const temporal::StepValueSource& source, const temporal::AnimationTimeline& timeline,
                                 temporal::Coherence coherence) {
    const RenderOptions& scene = options.scene;
    const std::size_t needed = grid.cell_count() * animation_bytes_per_cell +
                               std::size_t(scene.width) * std::size_t(scene.height) * animation_bytes_per_pixel;
    if (needed > scene.model_memory_limit_bytes())
        throw std::invalid_argument("--memory-limit-gb: " + memory_limit_problem(needed, scene.model_memory_limit_bytes(),
                                                                                "the animation's per-cell and per-pixel arrays"));
    AnimationRanges r;
    PropertyChoice first_step;
    first_step.name = scene.property;
    first_step.owned = source.values(timeline.first_step);
    r.box = choose_primary_range(grid, first_step, scene);
    r.primary_range = first_step.primary_range;
    first_step.owned = std::vector<float>();
    r.survey = survey_steps(grid, source, timeline, r.primary_range, r.box);
    r.colour_range = scene.colour_range.empty() ? r.survey.colour_range : given_colour_range(scene.colour_range, false);
    if (coherence == temporal::Coherence::smooth)
        r.band = float(options.hysteresis) * (r.colour_range.max - r.colour_range.min);
    return r;
}

/// Draws, encodes and measures the animation's frames one by one (upload what changed, draw with
/// one fence, read back, hand to the encoder), keeping what the next frame compares with.
class FrameLoop {
public:
    FrameLoop(const AnimateOptions& options, pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
              const annotation::ColourBarLabel& label, const StepWellSets& step_wells, io::Mp4Encoder& encoder,
              std::size_t frame_count, std::size_t first_step, temporal::Coherence coherence, const AnimationRanges& ranges)
        : options_(options), scene_(options.scene), renderer_(renderer), settings_(settings), label_(label),
          step_wells_(step_wells), encoder_(encoder), frame_count_(frame_count), shown_wells_step_(first_step),
          coherence_(coherence), primary_range_(ranges.primary_range), box_(ranges.box),
          frames_to_open_(temporal::frames_to_open(options.frames_per_step)) {
        primaries_only_ = settings;
        primaries_only_.ssao = false;
        primaries_only_.colour_bar = false;
        primaries_only_.only = pipeline::OnlyLayer::primaries;
    }

    /// Draws each frame's date (from `steps`, none when empty) and report step of `step_count`,
    /// the model framed below the caption (the same rows in every frame: the camera does not jump).
    void caption_with(std::vector<eclipse::ReportStep> steps, std::size_t step_count) {
        caption_steps_ = std::move(steps);
        caption_step_count_ = step_count;
        const std::string first = eclipse::step_caption(label_.property, eclipse::date_at(caption_steps_, 0.0), 0.0, step_count);
        caption_rows_ = pipeline::caption_reserved_rows(first, scene_.width, scene_.height,
                                                        renderer_.status(settings_).colour_bar_reserved_width, label_.min_text_px);
    }

    /// Frame `f` of `frame`: its stats entry.
    json draw(std::size_t f, const temporal::CoherentSequence::Frame& frame) {
        const auto started = std::chrono::steady_clock::now();
        const pipeline::Camera camera = upload(f, frame);
        const double upload_ms = milliseconds_since(started);
        // One fence at the frame's end, as a user's frame runs (the stage times are render's job).
        const double draw_ms = renderer_.render(settings_, camera, pipeline::Fencing::frame_only).total.wall_ms;
        gl::RgbaImage image = pipeline::FrameReadback(renderer_).read_image();
        const double png_ms = write_png_frame(f, image);  // an extra output, left out of the frame's time
        // Waits only while ffmpeg still takes the frame before: encoding overlaps the next frame.
        encoder_.write_frame(std::move(image.pixels));
        const double ms = milliseconds_since(started) - png_ms;

        json entry{{"frame", f}, {"time_step", frame.time_step}, {"ms", ms},
                   {"ms_by_part", {{"upload", upload_ms}, {"draw", draw_ms}, {"readback_and_encoder", ms - upload_ms - draw_ms}}},
                   {"primary_cells", frame.primary_cells}, {"cells_opening", frame.openings->size()},
                   {"upload_bytes", uploaded_bytes_}};
        if (options_.time_against_render)
            entry["render_ms"] = renderer_.render(settings_, camera, pipeline::Fencing::frame_only).total.wall_ms;
        if (f > 0) {
            const metrics::PopCounts pops = metrics::count_pops(previous_flags_, *frame.flags);
            entry["pop_in"] = pops.in;
            entry["pop_out"] = pops.out;
            if (!reversals_) reversals_.emplace(frame.flags->size());
            entry["pop_reversals"] = reversals_->count(previous_flags_, *frame.flags);
        }
        if (options_.metrics) add_image_metrics(entry, renderer_, primaries_only_, camera, previous_states_);
        previous_flags_ = *frame.flags;
        return entry;
    }

private:
    /// What changed since the frame before (values, primaries, wells, the camera's orbit) uploaded;
    /// the frame's camera. A step held (none, between report steps) uploads nothing.
    pipeline::Camera upload(std::size_t f, const temporal::CoherentSequence::Frame& frame) {
        const std::size_t uploaded_before = renderer_.status(settings_).uploaded_bytes;
        // Smooth's blended values change every frame and only colour (its primaries come as
        // flags): 16 bits each. None selects by range over its values: they stay exact.
        if (frame.values_changed)
            renderer_.set_colouring(*frame.values, label_, coherence_ == temporal::Coherence::smooth
                                                               ? pipeline::ValueStorage::unorm16 : pipeline::ValueStorage::float32);
        if (caption_step_count_ > 0)
            settings_.caption = eclipse::step_caption(label_.property, eclipse::date_at(caption_steps_, frame.time_step),
                                                      frame.time_step, caption_step_count_);
        select(f, frame);
        if (coherence_ == temporal::Coherence::smooth) ease_cone_reference();
        if (f == 0 || !frame.openings->empty() || had_openings_) renderer_.set_opening_cells(*frame.openings);
        had_openings_ = !frame.openings->empty();
        // The report step shown (the one held until the next is reached) has its wells.
        const auto wells_step = std::size_t(frame.time_step);
        if (f == 0 || step_wells_.changes(shown_wells_step_, wells_step)) renderer_.set_wells(step_wells_.at(wells_step));
        shown_wells_step_ = wells_step;
        uploaded_bytes_ = renderer_.status(settings_).uploaded_bytes - uploaded_before;
        pipeline::OrbitPose pose = scene_.camera_pose();
        if (frame_count_ > 1) pose.azimuth_deg += float(options_.orbit_deg * double(f) / double(frame_count_ - 1));
        const float bar_width = renderer_.status(settings_).colour_bar_reserved_width;
        if (scene_.freeze_pose && f == 0)
            renderer_.freeze(pipeline::make_orbit_camera(renderer_.frame(), *scene_.freeze_pose, scene_.width, scene_.height, bar_width,
                                                         0, caption_rows_));
        return pipeline::make_orbit_camera(renderer_.frame(), pose, scene_.width, scene_.height, bar_width, 0, caption_rows_);
    }

    /// The frame's primaries, where they changed. Under none they are the step's values in the
    /// range, selected on the GPU from the values just uploaded (no upload of their own); under
    /// smooth, hysteresis and pacing decide: their flags are uploaded (1 bit per active cell).
    void select(std::size_t f, const temporal::CoherentSequence::Frame& frame) {
        // --primaries none: the volumes alone cut, whatever the steps' values select.
        if (!settings_.primaries) {
            if (f == 0) renderer_.select(pipeline::Primaries::none());
        } else if (f == 0 || *frame.flags != previous_flags_) {
            if (coherence_ == temporal::Coherence::none) renderer_.select(pipeline::Primaries(primary_range_, box_));
            else renderer_.select(*frame.flags);
        }
    }

    /// Smooth: the seed strategies' cone slope follows the primaries' centroid a share per frame
    /// (as the cells' cuts open, over temporal::frames_to_open frames), not at once: a
    /// centroid jump (a few first primaries, a far cell entering) changed the slope of every wall.
    void ease_cone_reference() {
        const pipeline::RendererStatus status = renderer_.status(settings_);
        if (status.primary_cells == 0) return;
        const float share = 1.0f / float(frames_to_open_);
        cone_reference_ = cone_reference_ ? *cone_reference_ + share * (status.primary_centroid - *cone_reference_)
                                          : status.primary_centroid;
        renderer_.set_cone_reference(cone_reference_);
    }

    /// --frames DIR: frame `f` as a PNG there; the milliseconds it took (0 without --frames).
    double write_png_frame(std::size_t f, const gl::RgbaImage& image) const {
        if (options_.frames_dir.empty()) return 0;
        const auto started = std::chrono::steady_clock::now();
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05zu.png", f);
        gl::write_png(image, std::filesystem::path(options_.frames_dir) / name);
        return milliseconds_since(started);
    }

    const AnimateOptions& options_;
    const RenderOptions& scene_;
    pipeline::CutawayRenderer& renderer_;
    pipeline::FrameSettings settings_;  ///< the run's, with each frame's caption
    pipeline::FrameSettings primaries_only_;
    const annotation::ColourBarLabel& label_;
    const StepWellSets& step_wells_;
    io::Mp4Encoder& encoder_;
    std::size_t frame_count_;
    std::size_t shown_wells_step_;
    temporal::Coherence coherence_;
    grid::PrimaryRange primary_range_;
    std::optional<grid::IjkBox> box_;
    std::vector<std::uint8_t> previous_flags_;
    std::optional<metrics::PopReversals> reversals_;  ///< from frame 1: each cell's last change
    std::vector<metrics::CutState> previous_states_;
    bool had_openings_ = false;
    std::optional<glm::vec3> cone_reference_;  ///< smooth: the eased point (ease_cone_reference)
    std::size_t frames_to_open_;
    std::size_t uploaded_bytes_ = 0;  ///< by the frame's upload
    std::vector<eclipse::ReportStep> caption_steps_;  ///< caption_with: the dates
    std::size_t caption_step_count_ = 0;              ///< caption_with: report steps (0: no caption)
    float caption_rows_ = 0;                          ///< caption_with: top rows the model is framed below
};

/// What stats.json says of the run beside its frames.
struct AnimationFacts {
    const LoadedModel& model;
    const AnimationRanges& ranges;
    const temporal::StepValueSource& source;
    const pipeline::FrameSettings& settings;
    const io::Mp4Settings& video;
    const CutVolumeSet& cut_volumes;
    double setup_seconds = 0;
    double frames_seconds = 0;
    double finish_ms = 0;
    std::size_t steps_read = 0;
};

void write_animation_stats(const AnimateOptions& options, json frames, const AnimationFacts& facts,
                           const GlDevice& device) {
    const RenderOptions& scene = options.scene;
    json stats;
    const std::size_t frame_count = frames.size();
    stats["frames"] = std::move(frames);
    put_frame_summaries(stats, stats["frames"], facts.finish_ms);
    stats["frames_wall_s"] = facts.frames_seconds;  // every frame, its metrics and the encoding to the end
    stats["encoder_finish_ms"] = facts.finish_ms;   // after the last frame: ffmpeg's queue and index
    stats["frame_count"] = frame_count;
    stats["report_steps_read"] = facts.steps_read;
    stats.update(run_context_json(device));
    stats["size"] = {scene.width, scene.height};
    stats["cells"] = facts.model.grid.cell_count();
    stats["active_cells"] = facts.model.grid.active_count();
    stats["model"] = facts.model.description;
    stats["model_load_s"] = facts.model.load_seconds;
    stats["renderer_setup_s"] = facts.setup_seconds;
    stats["strategy"] = {{"requested", scene.settings.strategy}, {"drawn", facts.settings.strategy},
                         {"largest_step_primaries", facts.ranges.survey.most_primaries}};
    const AnimationRanges& r = facts.ranges;
    stats["property"] = {{"name", scene.property}, {"colour_range", {r.colour_range.min, r.colour_range.max}},
                         {"primary_range", {r.primary_range.min, r.primary_range.max}}, {"hysteresis_band", r.band},
                         {"report_steps", facts.source.step_count()}};
    stats["video"] = {{"codec", "h264"}, {"pixel_format", "yuv420p"}, {"encoder", "ffmpeg libx264"},
                      {"preset", facts.video.preset}, {"crf", facts.video.crf}, {"fps", facts.video.fps}};
    stats["configuration"] = describe(options);
    stats["configuration"]["cut_volumes"] = facts.cut_volumes.describe();
    stats["memory_bytes"] = {{"peak_resident", run_context::proc_status_bytes("VmHWM")}};
    io::write_file(options.stats, stats.dump(2) + '\n');
}

int animate(const AnimateOptions& options) {
    // Before any thread starts (OpenMP in the generator, llvmpipe's, the encoder's): see interrupt_guard.h.
    const InterruptGuard interrupts;
    const RenderOptions& scene = options.scene;
    check_animate_options(options);
    const temporal::Coherence coherence = temporal::parse_coherence(options.coherence);
    pipeline::FrameSettings settings = scene.frame_settings();

    LoadedModel model = load_model(scene.model, scene.model_memory_limit_bytes(), scene.property);
    interrupts.check();
    const grid::CornerPointGrid& grid = model.grid;
    const std::unique_ptr<temporal::StepValueSource> step_values = step_values_of(model, scene.property);
    const temporal::StepValueSource& source = *step_values;
    const temporal::AnimationTimeline timeline = timeline_of(options, source.step_count(), scene.property);
    const AnimationRanges ranges = animation_ranges(options, grid, source, timeline, coherence);
    const StepWellSets step_wells(model, scene.wells, scene.well_radius, timeline.first_step, timeline.last_step);
    // A `well:` volume follows the well's path at the first step shown (one cut for the animation).
    const volumes::WellPaths volume_wells = cut_volume_well_paths(model, scene.wells, int(timeline.first_step));

    std::unique_ptr<gl::GlContext> context = gl::create_context(scene.context_options());
    const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
    const auto setup_started = std::chrono::steady_clock::now();
    pipeline::CutawayRenderer renderer(shaders, grid, scene.z_scale, scene.width, scene.height,
                                       [&model] { model.grid.release_corner_depths(); });
    check_view(renderer.frame(), scene);
    const CutVolumeSet cut_volumes =
        load_cut_volumes(scene.cut_volumes, renderer.frame(), volume_wells, scene.model_memory_limit_bytes());
    renderer.set_cut_volumes(cut_volumes.meshes);
    // "auto" picks a strategy by the primary count, which changes from frame to frame: a switch
    // redraws the whole cut another way at once (on petra it made the first step's largest
    // flicker). The animation keeps the one auto picks for its largest primary set.
    settings.strategy = pipeline::resolve_cut_strategy(settings.strategy, ranges.survey.most_primaries, renderer.status().auto_sweep_from);
    annotation::ColourBarLabel label{scene.property, ranges.colour_range.min, ranges.colour_range.max,
                                     annotation::property_unit(scene.property)};
    label.min_text_px = scene.text_height_px;
    // --primaries none: the steps' values select nothing, no range to mark.
    if (settings.primaries) label.primary_range = annotation::ColourBarLabel::Span{ranges.primary_range.min, ranges.primary_range.max};
    const double setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_started).count();

    temporal::CoherentSequence sequence(grid, source, timeline, coherence, ranges.primary_range, ranges.band, ranges.box);
    io::StagedFile staged(options.out);
    io::Mp4Settings video;
    video.width = scene.width;
    video.height = scene.height;
    video.fps = options.fps;
    video.crf = options.crf;
    io::Mp4Encoder encoder(staged.write_path(), video);
    if (!options.frames_dir.empty()) std::filesystem::create_directories(options.frames_dir);

    const std::size_t frame_count = timeline.frame_count();
    ProgressBar progress("cutaway animate", frame_count, "frames");
    FrameLoop loop(options, renderer, settings, label, step_wells, encoder, frame_count, timeline.first_step, coherence, ranges);
    if (options.scene.caption) loop.caption_with(model.report_steps ? model.report_steps->steps() : std::vector<eclipse::ReportStep>(),
                                           source.step_count());
    json frames = json::array();
    const auto frames_started = std::chrono::steady_clock::now();
    for (std::size_t f = 0; f < frame_count; ++f) {
        interrupts.check();
        frames.push_back(loop.draw(f, sequence.next()));
        progress.show(f + 1);
    }
    progress.end();
    const auto finish_started = std::chrono::steady_clock::now();
    encoder.finish();  // ffmpeg encodes the frames still queued and writes the index
    const double finish_ms = milliseconds_since(finish_started);
    interrupts.check();
    staged.commit();
    const double frames_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - frames_started).count();
    if (!options.stats.empty())
        write_animation_stats(options, std::move(frames),
                              {model, ranges, source, settings, video, cut_volumes, setup_seconds, frames_seconds, finish_ms,
                               sequence.steps_read()},
                              current_gl_device(context->platform()));
    std::cout << "cutaway animate: " << options.out << " (" << frame_count << " frames, steps " << timeline.first_step << "-"
              << timeline.last_step << ", " << temporal::to_string(coherence) << ", " << frames_seconds << " s)\n";
    return 0;
}

}  // namespace

CommandAction add_animate_command(CLI::App& app) {
    auto options = std::make_shared<AnimateOptions>();
    CLI::App* command = app.add_subcommand("animate", "Render a cutaway animation over report steps to an H.264 MP4");
    add_animate_options(*command, *options);
    return [options] {
        try {
            return animate(*options);
        } catch (const Interrupted& interrupted) {
            // Everything above has unwound: ffmpeg ended, the partial MP4 removed.
            std::cerr << "cutaway animate: " << interrupted.what() << "; no MP4 written\n";
            return 128 + interrupted.signal_number();
        }
    };
}

}  // namespace cutaway::app
