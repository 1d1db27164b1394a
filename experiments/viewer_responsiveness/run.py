#!/usr/bin/python3
"""Viewer responsiveness: frame times of `cutaway view` on petra at 1280x720 (issue 8).

Interface (for experiments/run_all):
  experiments/viewer_responsiveness/run.py [--quick] [--force] [--build DIR]
Writes results/viewer/viewer_responsiveness.json and .md, and paper_figures/viewer_petra.png (the
window with its panel and timing overlay). Skips when they exist unless --force. --quick: 640x360,
fewer frames (results/quick/viewer/, paper_figures/quick/).

Protocol: the viewer runs in a real window under Xvfb (xvfb-run, Mesa llvmpipe through GLX) with
the panel and overlay shown and the paper's settings (frustum cut, ray-cast borders, 9x9 mean
filter, SSAO, 1% PORO primaries). A script turns the camera 15 degrees every frame (each frame
re-renders the cutaway, as while dragging the mouse), changes the primary range (new selection),
then leaves the camera still (frames that only redraw the panel over the last cutaway). Each
render scale (the panel's "render scale": the cutaway is rendered smaller and scaled up) is one
run; the runs go in 3 interleaved rounds (100%, 50%, 100%, ...; 1 with --quick), so a slow spell
of this shared machine does not fall on one scale only. The viewer's --stats file holds every
frame's loop time (events, script, panel, render when something changed, blit, swap) and its
fenced stage times; medians over the frames of all rounds are reported, with each round's median
beside them.
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402


def script_text(turns, ranges, idle, screenshot):
    lines = ["# written by experiments/viewer_responsiveness/run.py", "wait 3"]
    lines += ["orbit 15 0\nwait 1"] * turns
    lines += [f"set --range {0.30 + 0.005 * i:.3f} 0.40\nwait 1" for i in range(ranges)]
    lines += [f"wait {idle}", f"screenshot {screenshot}" if screenshot else "wait 1", "quit"]
    return "\n".join(lines) + "\n"


def median(values):
    values = sorted(values)
    n = len(values)
    return 0.0 if n == 0 else values[n // 2] if n % 2 else 0.5 * (values[n // 2 - 1] + values[n // 2])


def main():
    exp = cx.Experiment("viewer", __doc__, ["viewer_responsiveness.json", "viewer_responsiveness.md", "viewer_petra.png"])
    if exp.up_to_date():
        return
    xvfb_run = shutil.which("xvfb-run")
    if xvfb_run is None:
        raise SystemExit("xvfb-run not found (Debian package xvfb; scripts/install-deps.sh installs it)")
    size = (640, 360) if exp.quick else (1280, 720)
    turns, ranges, idle = (4, 2, 5) if exp.quick else (24, 6, 30)
    rounds = 1 if exp.quick else 3
    runs = {1.0: [], 0.5: []}
    with tempfile.TemporaryDirectory(prefix="cutaway-viewer-") as scratch:
        for round_index in range(rounds):
            for scale in runs:
                script = os.path.join(scratch, f"script-{scale}-{round_index}.txt")
                stats = os.path.join(scratch, f"stats-{scale}-{round_index}.json")
                shot = scale == 1.0 and round_index == 0
                with open(script, "w") as f:
                    # The screenshot goes to scratch and is copied at the end: rewriting the tracked
                    # figure during the runs would make the viewer record a dirty revision.
                    f.write(script_text(turns, ranges, idle, os.path.join(scratch, "viewer_petra.png") if shot else None))
                command = [xvfb_run, "-a", "-s", "-screen 0 1920x1080x24", exp.cutaway, "view", "preset:petra",
                           "--size", str(size[0]), str(size[1]), "--render-scale", str(scale), "--script", script,
                           "--stats", stats]
                subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
                with open(stats) as f:
                    runs[scale].append(cx.json.loads(f.read()))
        revision = exp.context()["git_revision"]  # before the copy changes a tracked file
        shutil.copyfile(os.path.join(scratch, "viewer_petra.png"), exp.path("viewer_petra.png"))

    summary = {}
    for scale, scale_runs in runs.items():
        stats = scale_runs[0]
        frames = [f for run in scale_runs for f in run["frames"][1:]]  # frame 0 compiles the programs
        rendering = [f["loop_ms"] for f in frames if f["rendered"]]
        idle_frames = [f["loop_ms"] for f in frames if not f["rendered"]]
        round_medians = [median([f["loop_ms"] for f in run["frames"][1:] if f["rendered"]]) for run in scale_runs]
        summary[str(scale)] = {
            "render_size": stats["render_size"], "window_size": stats["window_size"], "rounds": len(scale_runs),
            "median_loop_ms_rendering_by_round": round_medians,
            "rendered_frames": len(rendering), "idle_frames": len(idle_frames),
            "median_loop_ms_rendering": median(rendering), "median_loop_ms_idle": median(idle_frames),
            "frames_per_second_rendering": 1000.0 / median(rendering) if rendering else 0.0,
            "frames_per_second_idle": 1000.0 / median(idle_frames) if idle_frames else 0.0,
            "median_stages_ms": {s: median([f["stages_ms"][s] for f in frames if f["rendered"] and s in f["stages_ms"]])
                                 for s in cx.STAGES + ("total",)},
        }
    first = runs[1.0][0]
    cx.write_json(exp.path("viewer_responsiveness.json"), {
        "experiment": "viewer_responsiveness", "quick": exp.quick, "model": first["model"],
        "primary_cells": first["primary_cells"], "configuration": first["configuration"],
        "protocol": {"turns": turns, "range_changes": ranges, "idle_frames": idle, "panel": "shown",
                     "timing": first["timing"]},
        "context": {**exp.context(first), "git_revision": revision, "gl_version": first["gl_version"], "gl_platform": first["gl_platform"],
                    "git_revision_viewer": first["git_revision"]},
        "by_render_scale": summary, "runs": {str(k): v for k, v in runs.items()}})

    rows = ["| render scale | render size | frame while the view changes (ms) | rounds' medians | fps "
            "| frame with a still view (ms) | fps | stage 1 | stage 2 | mean filter | SSAO | cutaway total |", "|" + "---|" * 12]
    for scale, s in summary.items():
        st = s["median_stages_ms"]
        by_round = s["median_loop_ms_rendering_by_round"]
        rows.append(f"| {float(scale):.0%} | {s['render_size'][0]}x{s['render_size'][1]} | "
                    f"{s['median_loop_ms_rendering']:.0f} | {min(by_round):.0f}-{max(by_round):.0f} | "
                    f"{s['frames_per_second_rendering']:.1f} | "
                    f"{s['median_loop_ms_idle']:.1f} | {s['frames_per_second_idle']:.0f} | {st['cut_surface']:.0f} | "
                    f"{st['secondary']:.0f} | {st['mean_filter']:.0f} | {st['ssao']:.0f} | {st['total']:.0f} |")
    with open(exp.path("viewer_responsiveness.md"), "w") as f:
        f.write(f"# Viewer responsiveness: petra, {size[0]}x{size[1]} window, {first['gl_renderer']}\n\n"
                f"Written by experiments/viewer_responsiveness/run.py (git {revision}, "
                f"LP_NUM_THREADS={os.environ['LP_NUM_THREADS']}, {first['gl_platform']} under Xvfb). Medians over "
                f"{turns + ranges} frames that re-render the cutaway (camera turns, primary-range changes) and {idle} "
                f"frames with a still view (panel and overlay redrawn over the last cutaway) per run, pooled over "
                f"{rounds} interleaved round(s) of the render scales.\n\n" + "\n".join(rows) + "\n")
    print("wrote", os.path.relpath(exp.path("viewer_responsiveness.md"), cx.REPO))


if __name__ == "__main__":
    main()
