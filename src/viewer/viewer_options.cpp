#include "viewer/viewer_options.h"

#include "app_core/option_checks.h"
#include "viewer/viewer_script.h"

namespace cutaway::viewer {

void add_viewer_options(CLI::App& c, ViewerOptions& o) {
    app::add_scene_options(c, o.render);
    c.add_option("--script", o.script, "play actions and camera moves from FILE, one per line:\n" + script_actions_help())
        ->check(CLI::ExistingFile);
    c.add_option("--screenshot", o.screenshot, "write the last frame drawn to this PNG")->check(app::writable_output());
    c.add_option("--frames", o.frames, "stop after N frames (0: when the window closes or the script quits)")
        ->check(app::finite_in(0, 10000000));
    c.add_flag("--no-ui", o.no_ui, "start with the control panel and timing overlay hidden (H toggles)");
    c.add_option("--stats", o.stats, "write per-frame loop and stage times with the configuration as JSON")
        ->check(app::writable_output());
    c.add_option("--render-scale", o.render_scale, "render size as a fraction of the window (0.25..1)")
        ->check(app::finite_in(0.25, 1));
    c.add_option("--interaction-fps", o.interaction_fps,
                 "while the view moves (dragging, wheel, a script's drag on), draw smaller frames to hold this many "
                 "per second, and the full size once it stops (0: always the full size)")
        ->check(app::finite_in(0, 240));
    c.add_option("--timing-window", o.timing_window, "frames in the overlay's rolling medians")
        ->check(app::finite_in(1, 1000));
    c.add_option("--ui-scale", o.ui_scale,
                 "the control panel's and overlays' text and widgets at this multiple of their size (0.5..4; "
                 "2 for a high-density screen or a screenshot that prints)")
        ->check(app::finite_in(0.5, 4));
}

}  // namespace cutaway::viewer
