#!/usr/bin/python3
"""Viewer responsiveness: frame times of `cutaway view` on petra at 1280x720 (issue 8).

Interface (for experiments/run_all):
  experiments/viewer_responsiveness/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/viewer_responsiveness/viewer_responsiveness.json and its README.md, and
paper_figures/viewer_petra.png (the window with its panel and timing overlay). Skips when they
exist unless --force. --quick: 640x360, fewer frames (results/quick/viewer_responsiveness/,
paper_figures/quick/).

Protocol: the viewer runs in a real window under Xvfb (xvfb-run, Mesa llvmpipe through GLX) with
the panel and overlay shown and the paper's settings (frustum cut, ray-cast borders, 9x9 mean
filter, SSAO, 1% PORO primaries). A script turns the camera 15 degrees every frame (each frame
re-renders the cutaway, as while dragging the mouse), changes the primary range (new selection),
then leaves the camera still (frames that only redraw the panel over the last cutaway). Each
render scale (the panel's "render scale": the cutaway is rendered smaller and scaled up) is one
run with --interaction-fps 0 (every frame at that scale). A third run turns the camera with the
mouse button held (the script's `drag on` ... `drag off`, twice, as a user orbits again and again)
and --interaction-fps 10: while the view moves the viewer draws smaller frames, sized to hold 10
per second from the frames it measures (src/viewer/interaction_resolution.h), and the full size
once it stops. The first drag starts at half the size; the second where the first ended. Each
drag is reported on its own. The runs go in 3
interleaved rounds (100%, 50%, 100% while moving, 100%, ...; 1 with --quick), so a slow spell of
the machine does not fall on one configuration only. The viewer's --stats file holds every
frame's loop time (events, script, panel, render when something changed, blit, swap) and its
fenced stage times; medians over the frames of all rounds are reported, with each round's median
beside them.

The gallery's screenshot comes from one more, untimed run: a 1920x1440 window (960x720 with
--quick; taller than the timed runs' so that the panel shows its property and cut sections) with
the panel and overlays at --ui-scale 2.5 and the colour bar's text sized to print, so every text
prints at 7 pt or more when the figure is 182 mm wide; the same script. Its overlay's times are
that window's, not the timed runs'.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402


PRINTED_TEXT_PT = 7  # the gallery's smallest text at 182 mm wide (experiments/figures/compose.py MIN_TEXT_PT)
SCREENSHOT_UI_SCALE = 2.5  # Dear ImGui's 13 px font at 32.5 px, digits 20 px: 7.4 pt when 1920 px print 182 mm wide


def script_text(turns, ranges, idle, screenshot, drag):
    lines = ["# written by experiments/viewer_responsiveness/run.py", "wait 3"]
    if drag:  # two drags, the full size drawn between them
        lines += (["drag on"] + ["orbit 15 0\nwait 1"] * turns + ["drag off", "wait 2"]) * 2
    else:
        lines += ["orbit 15 0\nwait 1"] * turns
    lines += [f"set --range {0.30 + 0.005 * i:.3f} 0.40\nwait 1" for i in range(ranges)]
    lines += [f"wait {idle}", f"screenshot {screenshot}" if screenshot else "wait 1", "quit"]
    return "\n".join(lines) + "\n"


def drags(frames):
    """The frames drawn while the view moved, split into drags (a full-size frame ends one)."""
    groups, current = [], []
    for f in frames:
        if not f["rendered"]:
            continue
        if f.get("view_moving"):
            current.append(f)
        elif current:
            groups.append(current)
            current = []
    return groups + ([current] if current else [])


def median(values):
    values = sorted(values)
    n = len(values)
    return 0.0 if n == 0 else values[n // 2] if n % 2 else 0.5 * (values[n // 2 - 1] + values[n // 2])


def measure(exp):
    """The interleaved rounds of the three configurations under Xvfb; returns the document."""
    xvfb_run = shutil.which("xvfb-run")
    if xvfb_run is None:
        raise SystemExit("xvfb-run not found (Debian package xvfb; scripts/install-deps.sh installs it)")
    size = (640, 360) if exp.quick else (1280, 720)
    turns, ranges, idle = (4, 2, 5) if exp.quick else (24, 6, 30)
    rounds = 1 if exp.quick else 3
    # configuration -> (render scale, frames per second held while the view moves: 0 = off)
    configurations = {"1.0": (1.0, 0), "0.5": (0.5, 0), "1.0-moving": (1.0, 10)}
    runs = {name: [] for name in configurations}
    with tempfile.TemporaryDirectory(prefix="cutaway-viewer-") as scratch:
        for round_index in range(rounds):
            for name, (scale, interaction_fps) in configurations.items():
                script = os.path.join(scratch, f"script-{name}-{round_index}.txt")
                stats = os.path.join(scratch, f"stats-{name}-{round_index}.json")
                with open(script, "w") as f:
                    f.write(script_text(turns, ranges, idle, None, drag=interaction_fps > 0))
                command = [xvfb_run, "-a", "-s", "-screen 0 1920x1080x24", exp.cutaway, "view", "preset:petra",
                           "--size", str(size[0]), str(size[1]), "--render-scale", str(scale),
                           "--interaction-fps", str(interaction_fps), "--script", script, "--stats", stats]
                subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
                with open(stats) as f:
                    runs[name].append(cx.json.loads(f.read()))
        # The screenshot goes to scratch and is copied at the end: rewriting the tracked figure
        # during the runs would make the viewer record a dirty revision.
        shot_size = (960, 720) if exp.quick else (1920, 1440)
        text_px = math.ceil(PRINTED_TEXT_PT * 25.4 / 72 / cx.PRINT_WIDTH_MM * shot_size[0])
        script = os.path.join(scratch, "script-screenshot.txt")
        with open(script, "w") as f:
            f.write(script_text(turns, ranges, idle, os.path.join(scratch, "viewer_petra.png"), drag=False))
        subprocess.run([xvfb_run, "-a", "-s", f"-screen 0 {shot_size[0]}x{shot_size[1]}x24", exp.cutaway, "view", "preset:petra",
                        "--size", str(shot_size[0]), str(shot_size[1]), "--ui-scale", str(SCREENSHOT_UI_SCALE),
                        "--text-height", str(text_px), "--interaction-fps", "0", "--script", script],
                       check=True, stdout=subprocess.DEVNULL)
        first = runs["1.0"][0]
        # Before the copy changes a tracked file (the revision would read dirty).
        context = {**exp.context(first), "gl_version": first["gl_version"], "gl_platform": first["gl_platform"],
                   "git_revision_viewer": first["git_revision"]}
        shutil.copyfile(os.path.join(scratch, "viewer_petra.png"), exp.path("viewer_petra.png"))

    return {"experiment": "viewer_responsiveness", "quick": exp.quick, "model": first["model"],
            "primary_cells": first["primary_cells"], "configuration": first["configuration"],
            "protocol": {"turns": turns, "range_changes": ranges, "idle_frames": idle, "panel": "shown",
                         "timing": first["timing"]},
            "context": context, "by_configuration": summarise(runs, configurations), "runs": runs}


def summarise(runs, configurations):
    """Per configuration: medians of the frames that re-render, of the still frames, and per drag."""
    summary = {}
    for name, scale_runs in runs.items():
        stats = scale_runs[0]
        frames = [f for run in scale_runs for f in run["frames"][1:]]  # frame 0 compiles the programs
        rendering = [f["loop_ms"] for f in frames if f["rendered"]]
        idle_frames = [f["loop_ms"] for f in frames if not f["rendered"]]
        round_medians = [median([f["loop_ms"] for f in run["frames"][1:] if f["rendered"]]) for run in scale_runs]
        # Frames drawn while the view moved (only the run with the mouse button held has them), by
        # drag: the first starts at half the size, the second where the first ended.
        by_drag = [drags(run["frames"][1:]) for run in scale_runs]
        moving = {}
        for index, label in enumerate(("first_drag", "second_drag")):
            drag_frames = [f for run in by_drag if len(run) > index for f in run[index]]
            if not drag_frames:
                continue
            loop = median([f["loop_ms"] for f in drag_frames])
            moving[label] = {
                "frames": len(drag_frames), "median_loop_ms": loop, "frames_per_second": 1000.0 / loop,
                "median_loop_ms_by_round": [median([f["loop_ms"] for f in run[index]]) for run in by_drag if len(run) > index],
                "render_widths": sorted({f["render_size"][0] for f in drag_frames}),
                "median_render_size": [median([f["render_size"][k] for f in drag_frames]) for k in (0, 1)],
                "median_stages_ms": {s: median([f["stages_ms"].get(s, 0.0) for f in drag_frames]) for s in cx.STAGES + ("total",)}}
        still_full_size = [f["loop_ms"] for f in frames if f["rendered"] and not f.get("view_moving")]
        summary[name] = {
            "render_scale": configurations[name][0], "interaction_fps": configurations[name][1],
            "while_moving": moving,
            "median_loop_ms_not_moving": median(still_full_size),
            "render_size": stats["render_size"], "window_size": stats["window_size"], "rounds": len(scale_runs),
            "median_loop_ms_rendering_by_round": round_medians,
            "rendered_frames": len(rendering), "idle_frames": len(idle_frames),
            "median_loop_ms_rendering": median(rendering), "median_loop_ms_idle": median(idle_frames),
            "frames_per_second_rendering": 1000.0 / median(rendering) if rendering else 0.0,
            "frames_per_second_idle": 1000.0 / median(idle_frames) if idle_frames else 0.0,
            "median_stages_ms": {s: median([f["stages_ms"][s] for f in frames if f["rendered"] and s in f["stages_ms"]])
                                 for s in cx.STAGES + ("total",)},
        }
    return summary


def scale_rows(summary):
    """One row per render scale held for every frame (the configurations without --interaction-fps)."""
    rows = []
    for s in summary.values():
        if s["interaction_fps"] > 0:
            continue  # its frames have two sizes: the drag table
        st, by_round = s["median_stages_ms"], s["median_loop_ms_rendering_by_round"]
        rows.append([f"{s['render_scale']:.0%}", f"{s['render_size'][0]}x{s['render_size'][1]}",
                     f"{s['median_loop_ms_rendering']:.0f}", f"{min(by_round):.0f}-{max(by_round):.0f}",
                     f"{s['frames_per_second_rendering']:.1f}", f"{s['median_loop_ms_idle']:.1f}",
                     f"{s['frames_per_second_idle']:.0f}", f"{st['cut_surface']:.0f}", f"{st['secondary']:.0f}",
                     f"{st['mean_filter']:.0f}", f"{st['ssao']:.0f}", f"{st['total']:.0f}"])
    return rows


def drag_rows(summary):
    rows = []
    for s in summary.values():
        for label, m in s["while_moving"].items():
            by_round = m["median_loop_ms_by_round"]
            width, height = m["median_render_size"]
            rows.append([f"{s['render_scale']:.0%}, --interaction-fps {s['interaction_fps']:g}, mouse button held",
                         label.replace("_", " "), m["frames"], f"{m['median_loop_ms']:.0f}",
                         f"{min(by_round):.0f}-{max(by_round):.0f}", f"{m['frames_per_second']:.1f}",
                         f"{min(m['render_widths'])}-{max(m['render_widths'])}", f"{width:.0f}x{height:.0f}",
                         f"{m['median_stages_ms']['total']:.0f}", f"{s['median_loop_ms_not_moving']:.0f}"])
    return rows


def report(exp, document):
    summary, proto, context = document["by_configuration"], document["protocol"], document["context"]
    full = summary["1.0"]
    window = full["window_size"]
    moving = next((s for s in summary.values() if s["interaction_fps"] > 0), None)
    result = md.Report(
        f"Viewer responsiveness: {document['model']}, {window[0]}x{window[1]} window",
        f"Frame times of `cutaway view` in a real window under Xvfb ({context.get('gl_platform')}) with the panel and "
        "timing overlay shown and the paper's settings (frustum cut, ray-cast borders, 9x9 mean filter, SSAO, 1% PORO "
        f"primaries). Medians over {proto['turns'] + proto['range_changes']} frames per run that re-render the cutaway "
        f"(camera turns of 15 degrees, primary-range changes) and {proto['idle_frames']} frames with a still view (panel "
        f"and overlay redrawn over the last cutaway), pooled over {full['rounds']} interleaved round(s) of the "
        "configurations; a frame is the viewer's whole loop (events, script, panel, render when something changed, "
        "blit, swap).",
        headline=f"{full['median_loop_ms_rendering']:.0f} ms per re-rendered frame "
                 f"({full['frames_per_second_rendering']:.1f} fps) at render scale 100%")
    result.section("Every frame at one render scale")
    result.table(["render scale", "render size", "frame while the view changes (ms)", "rounds' medians", "fps",
                  "frame with a still view (ms)", "fps", "stage 1", "stage 2", "mean filter", "SSAO", "cutaway total"],
                 scale_rows(summary), align="ll" + "r" * 10)
    if moving:
        result.section("Turning with the mouse button held",
                       "The script's `drag on` ... `drag off`, twice: the viewer draws smaller frames sized to hold "
                       f"{moving['interaction_fps']:g} frames per second (src/viewer/interaction_resolution.h: it starts "
                       "at half the size, steps by the median of the frames it measures, never below a quarter) and the "
                       "full size once the drag ends; the primary-range changes after the drags are drawn at the full "
                       "size. The first drag starts at half the size, the second where the first ended; the first frame "
                       "at each new size, which allocates its targets, is among the frames while turning.")
        result.table(["configuration", "drag", "frames drawn while turning", "frame while turning (ms)", "rounds' medians",
                      "fps", "render widths", "median render size", "cutaway total (ms)", "full-size frames (ms)"],
                     drag_rows(summary), align="ll" + "r" * 8)
    return result.figure(exp.path("viewer_petra.png"))


def main():
    cx.Experiment(__doc__, "viewer_responsiveness.json", ["viewer_petra.png"]).run(measure, report)


if __name__ == "__main__":
    main()
