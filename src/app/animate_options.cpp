#include "app/animate_options.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "app_core/option_checks.h"
#include "cutaway/temporal/coherence.h"

namespace cutaway::app {
namespace {

/// A directory the frames can be written to: an existing writable one, or a new one whose
/// parent exists and is writable (it is made when the first frame is written).
CLI::Validator frames_directory() {
    return CLI::Validator(
        [](std::string& path) -> std::string {
            std::error_code error;
            const std::filesystem::path dir(path);
            if (std::filesystem::exists(dir, error)) {
                if (!std::filesystem::is_directory(dir, error)) return "expected a directory, found the file '" + path + "'";
                if (::access(dir.c_str(), W_OK | X_OK) != 0) return "expected a writable directory, found '" + path + "'";
                return {};
            }
            const std::filesystem::path parent = dir.has_parent_path() ? dir.parent_path() : ".";
            if (!std::filesystem::is_directory(parent, error) || ::access(parent.c_str(), W_OK | X_OK) != 0)
                return "expected a directory that exists or can be made, found '" + path + "' (no writable '" +
                       parent.string() + "')";
            return {};
        },
        "DIR");
}

}  // namespace

void add_animate_options(CLI::App& c, AnimateOptions& o) {
    add_scene_options(c, o.scene);
    c.add_option("--out", o.out, "output MP4 (H.264, yuv420p)")->required()->check(writable_output());
    c.add_option("--stats", o.stats, "write per-frame metrics, summaries and configuration as JSON")->check(writable_output());
    // Report steps are counted in the millions at most; the model's own count is checked after loading.
    c.add_option("--steps", o.steps, "FIRST LAST report steps to animate (0-based, inclusive; default: all)")
        ->expected(2)
        ->check(finite_in(0, 1e6));
    // 1000 frames per step is already far slower than any player shows.
    c.add_option("--frames-per-step", o.frames_per_step, "frames from one report step to the next")->check(finite_in(1, 1000));
    c.add_option("--fps", o.fps, "playback frames per second")->check(finite_in(1, 240));
    c.add_option("--coherence", o.coherence,
                 "none: each report step shown until the next, primaries selected anew (the paper) | smooth: values "
                 "interpolated between steps, primaries kept by hysteresis (default)")
        ->check(one_of(temporal::coherence_names()));
    c.add_option("--hysteresis", o.hysteresis,
                 "smooth: a primary stays primary until its value leaves the range widened by this fraction of the "
                 "property's span on each side")
        ->check(finite_in(0, 1, "of the span"));
    c.add_option("--orbit", o.orbit_deg, "azimuth the camera turns over the whole animation, degrees")
        ->check(finite_in(-3600, 3600, "degrees"));
    c.add_option("--frames", o.frames_dir, "also write each frame as DIR/frame_NNNNN.png")->check(frames_directory());
    add_caption_option(c, o.scene);
    c.add_flag("!--no-metrics", o.metrics, "skip primary_exposure (one extra untimed frame each) and cut_flicker");
    c.add_flag("--time-against-render", o.time_against_render,
               "draw every frame a second time as render does (no upload, read-back or encoding), timed: "
               "render_ms per frame and frame_over_render");
    c.add_option("--crf", o.crf, "x264 constant rate factor (lower: larger, sharper)")->check(finite_in(0, 51));
}

nlohmann::json describe(const AnimateOptions& o) {
    nlohmann::json configuration = o.scene.describe();
    configuration["steps"] = o.steps;
    configuration["frames_per_step"] = o.frames_per_step;
    configuration["fps"] = o.fps;
    configuration["coherence"] = o.coherence;
    configuration["hysteresis"] = o.hysteresis;
    configuration["orbit_deg"] = o.orbit_deg;
    configuration["frames_dir"] = o.frames_dir;
    configuration["metrics"] = o.metrics;
    configuration["crf"] = o.crf;
    configuration["time_against_render"] = o.time_against_render;
    return configuration;
}

}  // namespace cutaway::app
