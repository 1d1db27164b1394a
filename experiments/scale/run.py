#!/usr/bin/python3
"""Scale: a cutaway frame of models from 7.5K to 100M cells, frame time and peak memory.

Interface (for experiments/run_all):
  experiments/scale/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR] [--replot]
Writes results/scale/scale.json (per model: active cells, stats.json stage times and faces drawn,
wall time of the whole command including generating the model in memory, peak resident memory of
the process and per active cell, each the median of the model's rounds with every round's own
beside; machine context), results/scale/README.md and paper_figures/scale.png (frame time and
peak bytes per active cell against active cells). --quick: zaphirus and petra at 480x270, 2 rounds
(results/quick/scale/). --replot: only the plot, from scale.json.

Each model is `cutaway render preset:NAME` at 1920x1080 with the main job's settings (1% of PORO
primaries, 9x9 mean filter, SSAO, ray-cast borders, --draw visible), one warm-up frame (none above
a million cells) and one timed frame (plus the same frame once more unfenced, frame_ms_unfenced),
run as its own process so its peak resident set (getrusage of the child) is its own. A model whose
first command took under REPEAT_BELOW_S runs ROUNDS times, in rounds over those models after the
first pass over all (so a machine whose speed drifts slows each alike), and its numbers are the
medians; the larger ones keep their one timed frame (a round of scale-100m takes minutes). Every
model runs twice: with the default cut strategy, auto (cut_surface/cut_strategy_choice.h: frustum-clusters,
one frustum per IJK box of adjacent primaries, O(boxes x wall area), below 10,000 primary cells on a GPU and 500 on llvmpipe;
frustum-sweep, the same union as chessboard sweeps over the boxes' back faces, O(pixels), from
there; cut_surface/frustum_sweep.cpp says how its walls differ), and with the one of the two that
auto did not pick. The 100M model takes about 5 minutes per strategy here (1 of them generating it).
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import stage_style  # noqa: E402
import strategy_style  # noqa: E402

FULL = ("zaphirus", "petra", "opharine", "sapphire", "scale-1m", "scale-10m", "scale-100m")
QUICK = ("zaphirus", "petra")
DEFAULT = "auto"  # picks one of STRATEGIES by primary count
STRATEGIES = ("frustum-clusters", "frustum-sweep")
MEMORY_TARGET = 100  # peak resident bytes per active cell (issue 14)
ROUNDS = 3
# Here everything below scale-10m (frames under 1.2 s) and scale-10m with frustum-sweep (2.5 s
# frame, 20 s command) get their rounds: about 100 s more than one round's 570 s.
REPEAT_BELOW_S = 30
# The ring around a point timed once, among points with rounds.
ONE_FRAME = {"marker": "o", "markersize": 12, "markerfacecolor": "none", "markeredgecolor": "grey", "markeredgewidth": 0.8}


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


def row_for(preset, rounds):
    """The model's row from its `rounds` ((stats, wall s, peak RSS bytes) each): the first's counts
    and memory break-down; stage times, unfenced frame, load, set-up, wall and peak the medians of
    the rounds, every round's beside ("rounds")."""
    stats = rounds[0][0]
    cells = stats["active_cells"]
    each = [{"stages_ms": s["stages_ms"], "frame_ms_unfenced": s.get("frame_ms_unfenced"), "model_load_s": s.get("model_load_s"),
             "renderer_setup_s": s.get("renderer_setup_s"), "command_wall_s": wall, "peak_resident_bytes": peak,
             "peak_bytes_per_active_cell": peak / cells} for s, wall, peak in rounds]
    median = {key: statistics.median(r[key] for r in each)
              for key in ("frame_ms_unfenced", "model_load_s", "renderer_setup_s", "command_wall_s", "peak_resident_bytes")}
    return {"preset": preset, "active_cells": cells, "primary_cells": stats["primary_cells"],
            "stages_ms": stage_style.median_stages([r["stages_ms"] for r in each]),
            "faces_drawn": stats.get("faces_drawn"), "strategy": (stats.get("strategy") or {}).get("name"),
            "requested": (stats.get("strategy") or {}).get("requested"),
            **median, "peak_bytes_per_active_cell": median["peak_resident_bytes"] / cells,
            "gpu_memory_bytes": stats.get("gpu_memory_bytes"), "memory_bytes": stats.get("memory_bytes"),
            "frames_redrawn": stats.get("frames_redrawn"), "rounds": each}


def rounds_of(row):
    """The row's rounds (rows from before the rounds: the row itself, their one)."""
    return row.get("rounds", [row])


def is_default(row):
    """Whether the row ran the default strategy (rows from before auto have no "requested": their
    default was frustum-clusters)."""
    return row.get("requested", DEFAULT if row.get("strategy") == "frustum-clusters" else None) == DEFAULT


def label(row):
    return row["strategy"] + (" (default)" if is_default(row) else "")


def frame_rows(rows):
    out = []
    for r in rows:
        s, frames = r["stages_ms"], [q["stages_ms"]["total"] for q in rounds_of(r)]
        out.append([r["preset"], label(r), f"{r['active_cells']:,}", len(frames), f"{s['total']:.0f}",
                    f"{min(frames):.0f}-{max(frames):.0f}" if len(frames) > 1 else "-", f"{r['frame_ms_unfenced']:.0f}",
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
    single = [f"{r['preset']} {r['strategy']}" for r in rows if len(rounds_of(r)) == 1]
    rounds = document.get("rounds", 1)
    timed = ("one timed frame" if rounds == 1 else
             f"one timed frame in each of {rounds} rounds (a process each; the rounds of all such models in turn, after a "
             "first pass over every model) where the first command took under "
             f"{document['repeat_below_s']:g} s, the times and peak memory then the medians of the rounds (the memory "
             "break-down below: the first round's)" + (f"; one timed frame only for {', '.join(single)} (a round would "
                                                       "cost too much)" if single else ""))
    result = md.Report(
        f"Scale: a cutaway frame per model, {rows[0]['preset']} to {rows[-1]['preset']} ({size})",
        "Frame time and peak memory of `cutaway render preset:NAME` per model, from "
        f"{rows[0]['active_cells']:,} to {rows[-1]['active_cells']:,} active cells, each run as its own process (so its peak resident set is its own), with the main job's settings (1% of PORO primaries, 9x9 "
        f"mean filter, SSAO, ray-cast borders, --draw visible), one warm-up frame (none above a million cells) and {timed}. "
        f"Frame: the stats' fenced total; wall: the whole command (model generated in memory, renderer "
        f"set-up, warm-up, timed frame, the same frame unfenced, no metrics). Cut strategies: the default ({DEFAULT}: "
        "frustum-clusters below 10,000 primary cells on a GPU and 500 on llvmpipe, frustum-sweep from there; marked "
        "'(default)') and the other of the two. Targets (issue 14): scale-10m frame <= 5 s, wall <= 30 s, <= 100 bytes "
        "per active cell; scale-100m renders" + (f" (this machine: {memory / 2**30:.0f} GB)." if memory else "."),
        headline=f"{largest_default['preset']}: {largest_default['stages_ms']['total'] / 1000:.1f} s frame"
                 + (" (one timed frame)" if len(rounds_of(largest_default)) == 1 else f" (median of {len(rounds_of(largest_default))})")
                 + f", {largest_default['peak_bytes_per_active_cell']:.0f} bytes per active cell")
    result.section("Frame time and peak memory")
    result.table(["model", "cut strategy", "active cells", "rounds", "frame ms", "frame min-max ms", "unfenced ms",
                  "cut surface ms", "culling ms", "stage 2 ms", "stage 2 faces", "load s", "set-up s", "wall s", "peak RSS MB",
                  "bytes / active cell"], frame_rows(rows), align="ll" + "r" * 14)
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
    where auto picked it, open for the other; each point the median of the model's rounds with a bar
    from the fastest to the slowest, ringed where the model was timed once; no connecting line: each
    point is a different model (issue 15), named in the memory panel."""
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
    # A ring marks a model timed once, where the others have rounds (then a point is their median).
    single = [r for r in rows if len(rounds_of(r)) == 1] if any(len(rounds_of(r)) > 1 for r in rows) else []
    for ax, (title, value, target, target_label) in zip(axes.flat, panels):
        for name in strategies:
            for picked in (True, False):
                mine = [r for r in rows if r["strategy"] == name and is_default(r) == picked]
                y = [value(r) for r in mine]
                ax.errorbar([r["active_cells"] for r in mine], y, cx.min_max_bars(y, [[value(q) for q in rounds_of(r)] for r in mine]),
                            linestyle="none", capsize=2, elinewidth=1, markerfacecolor=None if picked else "none",
                            **strategy_style.style(name))
        ax.plot([r["active_cells"] for r in single], [value(r) for r in single], linestyle="none", **ONE_FRAME)
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
        # the models sit a decade apart at about the same height: the last model's label under the
        # line ending at its point, the others' over it starting at theirs (the lower limit leaves room).
        below = [q for q in rows if is_default(q) and q["peak_bytes_per_active_cell"] < 1.5 * MEMORY_TARGET]
        if r in below:  # a decade apart the labels are wider than the gap: the last under, the others over
            last = r is below[-1]
            memory.annotate(r["preset"], (r["active_cells"], y), textcoords="offset points", ha="right" if last else "left",
                            va="top" if last else "bottom", xytext=(8, -8) if last else (2, 8))
        else:
            memory.annotate(r["preset"], (r["active_cells"], y), textcoords="offset points", xytext=(6, 0), va="center")
    memory.set_ylim(bottom=min(r["peak_bytes_per_active_cell"] for r in rows) / 5)
    for ax in axes[-1]:
        ax.set_xlabel("active cells (one model per point)")
    handles = [plt.Line2D([], [], linestyle="none", markerfacecolor=None if picked else "none",
                          label=f"{name} ({'picked by ' + DEFAULT if picked else DEFAULT + ' picked the other'})",
                          **strategy_style.style(name)) for name in strategies for picked in (True, False)]
    rounds = max(len(rounds_of(r)) for r in rows)
    if single:
        handles.append(plt.Line2D([], [], linestyle="none", label=f"one timed frame (a round took over "
                                  f"{document['repeat_below_s']:g} s): no bar", **ONE_FRAME))
    fig.legend(handles=handles, ncol=2, loc="lower center", frameon=False)
    timed = "one timed frame per model" if rounds == 1 else (
        f"a point: the median of {rounds} rounds (bars: fastest to slowest round)" + ("; ringed: one timed frame" if single else ""))
    fig.suptitle(f"Scale at {document['size']}, {DEFAULT} and the other strategy\n{timed}\n{cx.device_label(document['context'])}")
    cx.save_figure(fig, path)
    plt.close(fig)


def measure(exp):
    """Every model with the default strategy and the other one, then the further rounds of the
    cheap ones; returns the document."""
    size, rounds = ("480x270", 2) if exp.quick else ("1920x1080", ROUNDS)
    runs, stats = [], None

    def run_once(preset, strategy, runs_of_model):
        nonlocal stats
        stats, wall, peak = measure_one(exp, preset, size, strategy)
        runs_of_model.append((stats, wall, peak))
        print(f"{preset}, {stats['strategy']['name']} (round {len(runs_of_model)}): {stats['stages_ms']['total']:.0f} ms "
              f"frame, {wall:.1f} s wall, {peak / stats['active_cells']:.0f} bytes per active cell", flush=True)

    for preset in QUICK if exp.quick else FULL:
        picked = None
        for strategy in (DEFAULT,) + STRATEGIES:
            if strategy == picked:
                continue  # the default drew it already
            runs.append((preset, strategy, []))
            run_once(*runs[-1])
            picked = picked or stats["strategy"]["name"]
    cheap = [run for run in runs if run[2][0][1] < REPEAT_BELOW_S]
    for _ in range(rounds - 1):
        for run in cheap:
            run_once(*run)
    return {"experiment": "scale", "quick": exp.quick, "size": size, "default": DEFAULT, "strategies": STRATEGIES,
            "rounds": rounds, "repeat_below_s": REPEAT_BELOW_S,
            "context": {**exp.context(stats), "gl_version": stats.get("gl_version")},
            "models": [row_for(preset, rounds_of_model) for preset, _, rounds_of_model in runs]}


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
