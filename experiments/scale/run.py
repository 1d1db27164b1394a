#!/usr/bin/python3
"""Scale: one cutaway frame of models from 7.5K to 100M cells, frame time and peak memory.

Interface (for experiments/run_all):
  experiments/scale/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR] [--replot]
Writes results/scale/scale.json (per model: active cells, stats.json stage times and faces drawn,
wall time of the whole command including generating the model in memory, peak resident memory of
the process and per active cell, machine context), results/scale/README.md and
paper_figures/scale.png (frame time and peak bytes per active cell against active cells).
--quick: zaphirus and petra at 480x270 (results/quick/scale/). --replot: only the plot, from scale.json.

Each model is `cutaway render preset:NAME` at 1920x1080 with the main job's settings (1% of PORO
primaries, 9x9 mean filter, SSAO, ray-cast borders, --draw visible), one warm-up frame (none above
a million cells) and one timed frame (plus the same frame once more unfenced, frame_ms_unfenced),
run as its own process so its peak resident set (getrusage of the child) is its own. Every model
runs twice: with the default cut strategy, auto (cut_surface/cut_strategy_choice.h: frustum-clusters,
one frustum per IJK box of adjacent primaries, O(boxes x wall area), below 10,000 primary cells on a GPU and 500 on llvmpipe;
frustum-sweep, the same union as chessboard sweeps over the boxes' back faces, O(pixels), from
there; cut_surface/frustum_sweep.cpp says how its walls differ), and with the one of the two that
auto did not pick. The 100M model takes about 5 minutes per strategy here (1 of them generating it).
"""
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402

FULL = ("zaphirus", "petra", "opharine", "sapphire", "scale-1m", "scale-10m", "scale-100m")
QUICK = ("zaphirus", "petra")
DEFAULT = "auto"  # picks one of STRATEGIES by primary count
STRATEGIES = ("frustum-clusters", "frustum-sweep")


def measure_one(exp, preset, size, strategy):
    """Runs one render as a child process; returns its stats, wall seconds and peak RSS bytes."""
    with tempfile.TemporaryDirectory(prefix="cutaway-scale-") as scratch:
        stats_path = os.path.join(scratch, "stats.json")
        warmup = "0" if preset.startswith("scale-") else "1"
        command = [exp.cutaway, "render", "preset:" + preset, "--size", *size.split("x"), "--warmup", warmup, "--repeat", "1",
                   "--no-metrics", "--strategy", strategy, "--out", os.path.join(scratch, "frame.png"), "--stats", stats_path]
        started = time.monotonic()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.monotonic() - started
        if status != 0:
            raise SystemExit(f"{' '.join(command)}: exit status {status}")
        with open(stats_path) as f:
            stats = json.load(f)
    return stats, wall, usage.ru_maxrss * 1024  # ru_maxrss is in KiB on Linux


def row_for(preset, stats, wall, peak):
    cells = stats["active_cells"]
    return {"preset": preset, "active_cells": cells, "primary_cells": stats["primary_cells"],
            "stages_ms": stats["stages_ms"], "frame_ms_unfenced": stats.get("frame_ms_unfenced"),
            "faces_drawn": stats.get("faces_drawn"), "model_load_s": stats.get("model_load_s"),
            "renderer_setup_s": stats.get("renderer_setup_s"), "strategy": (stats.get("strategy") or {}).get("name"),
            "requested": (stats.get("strategy") or {}).get("requested"),
            "command_wall_s": wall, "peak_resident_bytes": peak, "peak_bytes_per_active_cell": peak / cells,
            "gpu_memory_bytes": stats.get("gpu_memory_bytes"), "memory_bytes": stats.get("memory_bytes"),
            "frames_redrawn": stats.get("frames_redrawn")}


def is_default(row):
    """Whether the row ran the default strategy (rows from before auto have no "requested": their
    default was frustum-clusters)."""
    return row.get("requested", DEFAULT if row.get("strategy") == "frustum-clusters" else None) == DEFAULT


def label(row):
    return row["strategy"] + (" (default)" if is_default(row) else "")


def frame_rows(rows):
    out = []
    for r in rows:
        s = r["stages_ms"]
        out.append([r["preset"], label(r), f"{r['active_cells']:,}", f"{s['total']:.0f}", f"{r['frame_ms_unfenced']:.0f}",
                    f"{s['cut_surface']:.0f}", f"{s.get('culling', 0):.0f}", f"{s['secondary']:.0f}",
                    f"{r['faces_drawn']['secondary']:,}", f"{r['model_load_s']:.1f}", f"{r['renderer_setup_s']:.1f}",
                    f"{r['command_wall_s']:.1f}", f"{r['peak_resident_bytes'] / 2**20:.0f}", f"{r['peak_bytes_per_active_cell']:.0f}"])
    return out


def memory_rows(rows):
    """Bytes per active cell: after loading, added by the set-up (GPU buffers apart), by the frames, peak."""
    out = []
    for r in rows:
        m, cells = r["memory_bytes"], r["active_cells"]
        out.append([r["preset"], label(r), f"{m['resident_after_load'] / cells:.0f}",
                    f"{(m['resident_after_setup'] - m['resident_after_load']) / cells:.0f}", f"{m['gpu_buffers'] / cells:.0f}",
                    f"{(m['resident_after_frames'] - m['resident_after_setup']) / cells:.0f}", f"{m['peak_resident'] / cells:.0f}"])
    return out


def report(exp, document):
    rows, size, context = document["models"], document["size"], document["context"]
    largest_default = [r for r in rows if is_default(r)][-1]
    memory = context.get("memory_bytes")
    result = md.Report(
        f"Scale: one cutaway frame per model, {rows[0]['preset']} to {rows[-1]['preset']} ({size})",
        "Frame time and peak memory of one `cutaway render preset:NAME` per model, from "
        f"{rows[0]['active_cells']:,} to {rows[-1]['active_cells']:,} active cells, each run as its own process (so its peak resident set is its own), with the main job's settings (1% of PORO primaries, 9x9 "
        "mean filter, SSAO, ray-cast borders, --draw visible), one warm-up frame (none above a million cells) and one "
        f"timed frame. Frame: the stats' fenced total; wall: the whole command (model generated in memory, renderer "
        f"set-up, warm-up, timed frame, the same frame unfenced, no metrics). Cut strategies: the default ({DEFAULT}: "
        "frustum-clusters below 10,000 primary cells on a GPU and 500 on llvmpipe, frustum-sweep from there; marked "
        "'(default)') and the other of the two. Targets (issue 14): scale-10m frame <= 5 s, wall <= 30 s, <= 100 bytes "
        "per active cell; scale-100m renders" + (f" (this machine: {memory / 2**30:.0f} GB)." if memory else "."),
        headline=f"{largest_default['preset']}: {largest_default['stages_ms']['total'] / 1000:.1f} s frame, "
                 f"{largest_default['peak_bytes_per_active_cell']:.0f} bytes per active cell")
    result.section("Frame time and peak memory")
    result.table(["model", "cut strategy", "active cells", "frame ms", "unfenced ms", "cut surface ms", "culling ms",
                  "stage 2 ms", "stage 2 faces", "load s", "set-up s", "wall s", "peak RSS MB", "bytes / active cell"],
                 frame_rows(rows), align="ll" + "r" * 12)
    redrawn = [r for r in rows if r.get("frames_redrawn")]
    result.text("Frames drawn twice because the culling's face buffer (sized to what frames select, grown when one "
                "selects more) had to grow: " + (", ".join(f"{r['preset']} {r['strategy']} {r['frames_redrawn']}" for r in redrawn)
                                                 if redrawn else "none") + " (stats.json `frames_redrawn`).")
    result.section("Where the memory goes",
                   "Render's stats.json `memory_bytes`, bytes per active cell; on llvmpipe GPU memory is host memory: "
                   "resident after the model is loaded or generated, what the renderer's set-up added (its GPU buffers, "
                   f"listed apart, and the render targets, about {rows[0]['memory_bytes']['render_target_budget'] / 2**20:.0f} "
                   "MB budgeted), what the timed frames added, and the peak.")
    result.table(["model", "cut strategy", "after load", "set-up added", "of which GPU buffers", "frames added", "peak"],
                 memory_rows(rows), align="llrrrrr")
    return result.figure(exp.path("scale.png"))


def plot(exp, document):
    """Frame time per stage and peak bytes per active cell against active cells. One marker per
    model and no connecting line: each point is a different model (issue 15), named on the right."""
    rows, path = document["models"], exp.path("scale.png")
    plt = cx.pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    default = [r for r in rows if is_default(r)]
    cells = [r["active_cells"] for r in default]
    for stage, label, marker in (("total", "frame (fenced total)", "o"), ("cut_surface", "stage 1: cut surface", "s"),
                                 ("secondary", "stage 2: secondaries", "^"), ("culling", "culling", "v")):
        left.plot(cells, [r["stages_ms"].get(stage, 0) for r in default], marker=marker, linestyle="none",
                  label=f"{label}, default ({DEFAULT})")
    # The strategy the default did not pick: its frame and stage 1 as open markers, one shape pair each.
    for strategy, markers in zip(STRATEGIES, (("o", "s"), ("D", "P"))):
        other = [r for r in rows if r.get("strategy") == strategy and not is_default(r)]
        for stage, label, marker, colour in (("total", "frame", markers[0], "C0"), ("cut_surface", "stage 1", markers[1], "C1")):
            left.plot([r["active_cells"] for r in other], [r["stages_ms"][stage] for r in other], marker=marker,
                      linestyle="none", markerfacecolor="none", color=colour, label=f"{label}, {strategy}")
    left.axhline(5000, color="grey", linestyle="--", linewidth=1, label="target: scale-10m frame 5 s")
    left.set(xscale="log", yscale="log", xlabel="active cells (one model per column)", ylabel="ms (llvmpipe, one timed frame)",
             title="Frame time")
    left.legend(fontsize="x-small")
    per_cell = [r["peak_bytes_per_active_cell"] for r in default]
    right.plot(cells, per_cell, marker="o", linestyle="none", color="C4")
    for r, x, y in zip(default, cells, per_cell):
        # The value too: on a log axis 97 and 100 bytes look the same. Near the target line the
        # label goes below and to the left, clear of the line and the axes' edge.
        near_target = y < 150
        right.annotate(f"{r['preset']}: {y:,.1f}" if y < 1000 else f"{r['preset']}: {y:,.0f}", (x, y),
                       textcoords="offset points", xytext=(-5, -12) if near_target else (5, 4),
                       ha="right" if near_target else "left", fontsize="small")
    right.axhline(100, color="grey", linestyle="--", linewidth=1, label="target: 100 bytes per cell")
    right.set(xscale="log", yscale="log", xlabel="active cells (one model per point)", ylabel="peak resident bytes / active cell",
              title="Peak memory per active cell")
    right.set_xlim(right=max(cells) * 8)
    right.set_ylim(bottom=min(per_cell) / 2)  # room for the labels below the lowest points
    right.legend(fontsize="small")
    cx.save_figure(fig, path)


def measure(exp):
    """Every model with the default strategy and the other one; returns the document."""
    size = "480x270" if exp.quick else "1920x1080"
    rows, stats = [], None
    for preset in QUICK if exp.quick else FULL:
        picked = None
        for strategy in (DEFAULT,) + STRATEGIES:
            if strategy == picked:
                continue  # the default drew it already
            stats, wall, peak = measure_one(exp, preset, size, strategy)
            rows.append(row_for(preset, stats, wall, peak))
            picked = picked or rows[-1]["strategy"]
            print(f"{preset}, {label(rows[-1])}: {rows[-1]['stages_ms']['total']:.0f} ms frame, {wall:.1f} s wall, "
                  f"{rows[-1]['peak_bytes_per_active_cell']:.0f} bytes per active cell", flush=True)
    return {"experiment": "scale", "quick": exp.quick, "size": size, "default": DEFAULT, "strategies": STRATEGIES,
            "context": {**exp.context(stats), "gl_version": stats.get("gl_version")}, "models": rows}


def main():
    exp = cx.Experiment(__doc__, "scale.json", ["scale.png"], add_options=lambda parser: parser.add_argument(
        "--replot", action="store_true", help="only the plot, from the stored scale.json (no measuring)"))
    if exp.args.replot:
        if exp.stored() is None:
            cx.options.refuse("--replot", f"expected the data of an earlier run, found no {cx.exio.shown(exp.path('scale.json'))}")
        plot(exp, exp.stored())
        return
    exp.run(measure, report, plot)


if __name__ == "__main__":
    main()
