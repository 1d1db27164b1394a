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
import strategy_style  # noqa: E402

FULL = ("zaphirus", "petra", "opharine", "sapphire", "scale-1m", "scale-10m", "scale-100m")
QUICK = ("zaphirus", "petra")
DEFAULT = "auto"  # picks one of STRATEGIES by primary count
STRATEGIES = ("frustum-clusters", "frustum-sweep")
MEMORY_TARGET = 100  # peak resident bytes per active cell (issue 14)


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
    """Frame, stage 1, culling, stage 2, the command's wall time and peak bytes per active cell
    against active cells, a panel each; one colour and marker per strategy (strategy_style), filled
    where auto picked it, open for the other; no connecting line: each point is a different model
    (issue 15), named in the memory panel."""
    rows, path = document["models"], exp.path("scale.png")
    plt = cx.pyplot()
    fig, axes = plt.subplots(3, 2, figsize=(cx.PLOT_WIDTH_IN, 8.4), sharex=True)
    panels = (("frame (fenced total), ms", lambda r: r["stages_ms"]["total"], 5000, "scale-10m: 5 s"),
              ("stage 1: cut surface, ms", lambda r: r["stages_ms"]["cut_surface"], None, None),
              ("culling, ms", lambda r: r["stages_ms"].get("culling", 0), None, None),
              ("stage 2: secondaries, ms", lambda r: r["stages_ms"]["secondary"], None, None),
              ("whole command (wall), s", lambda r: r["command_wall_s"], 30, "scale-10m: 30 s"),
              ("peak resident bytes / active cell", lambda r: r["peak_bytes_per_active_cell"], MEMORY_TARGET,
               f"{MEMORY_TARGET} bytes"))
    strategies = strategy_style.ordered(r["strategy"] for r in rows)
    for ax, (title, value, target, target_label) in zip(axes.flat, panels):
        for name in strategies:
            for picked in (True, False):
                mine = [r for r in rows if r["strategy"] == name and is_default(r) == picked]
                ax.plot([r["active_cells"] for r in mine], [value(r) for r in mine], linestyle="none",
                        markerfacecolor=None if picked else "none", **strategy_style.style(name))
        if target:
            ax.axhline(target, color="grey", linestyle="--", linewidth=1)
            ax.annotate(f"target: {target_label}", (0.02, target), xycoords=("axes fraction", "data"),
                        textcoords="offset points", xytext=(0, 3), color="dimgrey")
        ax.set(xscale="log", yscale="log", title=title)
        ax.grid(True, which="both", linewidth=0.3)
    memory = axes[2][1]
    for r in (r for r in rows if is_default(r)):
        y = r["peak_bytes_per_active_cell"]
        # Right of the point (the next model's point is well below); near the target line, where
        # the models sit a decade apart at about the same height, below it, the two staggered.
        below = [q for q in rows if is_default(q) and q["peak_bytes_per_active_cell"] < 1.5 * MEMORY_TARGET]
        if r in below:
            last = r is below[-1]  # at the axes' right end: its label ends at the point
            memory.annotate(r["preset"], (r["active_cells"], y), textcoords="offset points", ha="right" if last else "center",
                            xytext=(6 if last else 0, -13 - 11 * (below.index(r) % 2)))
        else:
            memory.annotate(r["preset"], (r["active_cells"], y), textcoords="offset points", xytext=(6, 0), va="center")
    memory.set_ylim(bottom=min(r["peak_bytes_per_active_cell"] for r in rows) / 5)
    for ax in axes[-1]:
        ax.set_xlabel("active cells (one model per point)")
    handles = [plt.Line2D([], [], linestyle="none", markerfacecolor=None if picked else "none",
                          label=f"{name} ({'picked by ' + DEFAULT if picked else DEFAULT + ' picked the other'})",
                          **strategy_style.style(name)) for name in strategies for picked in (True, False)]
    fig.legend(handles=handles, ncol=2, loc="lower center", frameon=False)
    fig.suptitle(f"Scale: one frame per model at {document['size']}, {DEFAULT} and the other strategy\n"
                 f"{cx.device_label(document['context'])}")
    cx.save_figure(fig, path)
    plt.close(fig)


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
