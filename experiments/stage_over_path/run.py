#!/usr/bin/python3
"""Stage times over the camera path for each model (the thesis's figures 5.1-5.4).

Interface (for experiments/run_all):
  experiments/stage_over_path/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/stage_over_path/stage_over_path.json (per model, per pose: azimuth, aperture, fenced
ms per stage, the median over the rounds and every round's own), its README.md and
paper_figures/stage_over_path.png (+ .pdf: the camera path's azimuth and aperture on their own
axes, then one panel per model). Skips when all exist unless --force; replots and reports from the
JSON when it exists and --force was not given. --quick: 480x270 pixels, 3 poses, two models, 2
rounds (results/quick/, paper_figures/quick/).

Protocol: Table 1's settings (9x9 mean filter, 1% primaries, SSAO on, frustum cut, ray-cast borders),
1920x1080, a 16-pose path (bench_cutaway --per_pose: azimuth steps of 22.5 degrees, elevation
alternating 25/45, full aperture rising 30..120 degrees), one warm-up pass and one timed frame per
pose, in ROUNDS rounds: each round a bench_cutaway run over every model and pose, so a machine whose
speed drifts slows every pose alike; a pose's time is the median of its rounds.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import stage_style  # noqa: E402

ROUNDS = 3


def measure(exp):
    """Runs the benchmark once per round; returns the document (the stored one when there is one and no --force)."""
    if not exp.force and exp.stored():
        return exp.stored()
    size, poses, rounds = ("480x270", 3, 2) if exp.quick else ("1920x1080", 16, ROUNDS)
    presets = cx.PRESETS[:2] if exp.quick else cx.PRESETS
    by_round = []
    for round_index in range(rounds):
        print(f"round {round_index + 1} of {rounds}", flush=True)
        document = exp.benchmark("--presets=" + ",".join(presets), "--size=" + size, "--poses=" + str(poses), "--per_pose",
                                 "--fractions=0.01", "--mean_filters=9", "--borders=raycast", "--strategies=frustum",
                                 "--warmup=1", "--repeat=1", "--benchmark_filter=BM_cutaway")
        by_round.append({(r["preset"], r["pose"]): r for r in cx.cutaway_runs(document)})
    path = document["context"]["camera_path_az_el_aperture_deg"].split("; ")
    models = {p: sorted((key for key in by_round[0] if key[0] == p), key=lambda key: key[1]) for p in presets}

    def pose_row(key):
        first, runs = by_round[0][key], [r[key]["stages_ms"] for r in by_round]
        return {"pose": first["pose"], "aperture_deg": first.get("aperture_deg"), "stages_ms": stage_style.median_stages(runs),
                "stages_ms_by_round": runs, "primary_cells": first["primary_cells"], "cells": first["cells"]}

    return {
        "experiment": "stage_over_path", "quick": exp.quick, "size": size, "aperture": "full opening angle", "rounds": rounds,
        "statistic": "per pose and stage the median of the rounds' fenced ms (stages_ms_by_round: every round's)",
        "camera_path_az_el_aperture_deg": path,
        "context": {**exp.context(), **cx.benchmark_context(document)},
        "models": {p: [pose_row(key) for key in keys] for p, keys in models.items()}}


def totals_by_round(rows):
    """Per pose the total of every round (runs from before the rounds: their one frame)."""
    return [[r["total"] for r in row.get("stages_ms_by_round", [row["stages_ms"]])] for row in rows]


def plot(exp, result):
    """The camera path on top (azimuth and aperture on twin axes), then one panel of stage times
    per model in a grid of two columns; one legend below the panels, clear of every curve. Printed
    at 182 mm wide it stays within a page (six stacked panels printed 264 mm tall)."""
    path = exp.path("stage_over_path.png")
    plt = cx.pyplot()
    camera = [tuple(float(v) for v in pose.split("/")) for pose in result["camera_path_az_el_aperture_deg"]]
    # Runs before the full-angle convention recorded each wall's angle: the full opening is twice it.
    full = result.get("aperture") == "full opening angle"
    apertures = [c[2] if full else 2 * c[2] for c in camera]
    models = result["models"]
    rows = (len(models) + 1) // 2
    fig = plt.figure(figsize=(cx.PLOT_WIDTH_IN, 2.6 + 2.3 * rows))
    grid = fig.add_gridspec(rows + 1, 2, height_ratios=[0.7] + [1] * rows)
    poses = list(range(len(camera)))
    elevations = "/".join(f"{e:g}" for e in dict.fromkeys(c[1] for c in camera))
    top = fig.add_subplot(grid[0, :])
    # Black and grey: a colour in these plots means a stage (stage_style) or a strategy (strategy_style).
    # Both rise linearly along the path: the azimuth's axis puts its line in the panel's upper half,
    # the aperture's its line in the lower half, so the two never cover each other; each labelled.
    azimuths = [c[0] for c in camera]
    top.plot(poses, azimuths, marker="s", color="black")
    top.set_ylim(-max(azimuths) * 0.75, max(azimuths) * 1.1)
    top.set_yticks([a for a in (0, 180, 360) if a <= max(azimuths) * 1.1])
    top.set_ylabel("azimuth (deg)", color="black")
    top.annotate("azimuth", (poses[len(poses) // 2], azimuths[len(poses) // 2]), textcoords="offset points",
                 xytext=(-8, 6), ha="right", color="black")
    twin = top.twinx()
    twin.plot(poses, apertures, marker="^", color="dimgrey", linestyle="--")
    twin.set_ylim(min(apertures) - 0.1 * (max(apertures) - min(apertures)),
                  max(apertures) + 1.2 * (max(apertures) - min(apertures)))
    twin.set_yticks(range(int(min(apertures)) // 30 * 30, int(max(apertures)) + 1, 30))
    twin.set_ylabel("full aperture (deg)", color="dimgrey")
    twin.grid(False)  # one set of grid lines in the panel: the azimuth's
    twin.annotate("full aperture", (poses[len(poses) // 2], apertures[len(poses) // 2]), textcoords="offset points",
                  xytext=(8, -6), ha="left", va="top", color="dimgrey")
    top.set_xlabel("camera pose along the path")
    axes = []
    for index, (preset, rows_of_model) in enumerate(models.items()):
        ax = fig.add_subplot(grid[1 + index // 2, index % 2], sharex=top)
        stage_style.plot_stages(ax, [r["pose"] for r in rows_of_model], [r["stages_ms"] for r in rows_of_model],
                                totals_by_round(rows_of_model))
        if index % 2 == 0:
            ax.set_ylabel("time (ms)")
        ax.set_title(f"{preset} ({int(rows_of_model[0]['cells']):,} cells, {int(rows_of_model[0]['primary_cells']):,} primaries)")
        axes.append(ax)
    for ax in axes[-2:]:
        ax.set_xlabel("pose (azimuth and aperture\nrise together: not separable)")
    fig.legend(*axes[0].get_legend_handles_labels(), ncol=4, loc="lower center", frameon=False)
    fig.suptitle(f"Stage times over the camera path (elevation alternating {elevations} deg), {result['size']} px, "
                 f"frustum cut,\nper pose: {stage_style.rounds_note(result.get('rounds', 1), ' ')}\n"
                 f"on {cx.device_label(result['context'])}")
    cx.save_figure(fig, path)
    plt.close(fig)


def report(exp, document):
    """Per model: each stage's median, minimum and maximum over the path's poses (of each pose's
    median over the rounds), and how far a pose's rounds spread."""
    models, rounds = document["models"], document.get("rounds", 1)
    largest = max(models, key=lambda p: models[p][0]["cells"])
    totals = [r["stages_ms"]["total"] for r in models[largest]]
    poses = document["camera_path_az_el_aperture_deg"]
    timed = (f"one warm-up pass and one timed frame per pose in each of {rounds} rounds, each round a pass over every model "
             "and pose; a pose's time is the median of its rounds" if rounds > 1 else
             "one warm-up pass, one timed frame per pose")
    result = md.Report(
        "Stage times over the camera path (the thesis's figures 5.1-5.4)",
        f"Fenced wall-clock time of each cutaway stage at every pose of a {len(poses)}-pose camera path around each model "
        f"({document['size']} px; Table 1's settings: 9x9 mean filter, the top 1% of PORO as primaries, SSAO on, frustum "
        f"cut, ray-cast borders; {timed}). The path turns the azimuth, alternates the "
        f"elevation and opens the aperture ({document['aperture']}) as it goes (azimuth/elevation/aperture in degrees: "
        f"{'; '.join(poses)}), so a change along the path is the view and the aperture together. Below, per model and "
        "stage: the median, fastest and slowest over the poses" + (f" of the per-pose medians; the plot's bars span a "
                                                                  f"pose's {rounds} rounds' totals." if rounds > 1 else "."),
        headline=f"{largest} frame {md.ms(statistics.median(totals))} ms median over the path "
                 f"({md.ms(min(totals))}-{md.ms(max(totals))})" + (f", each pose the median of {rounds} rounds" if rounds > 1 else ""))
    for preset, rows in models.items():
        stages = [s for s in cx.STAGES + ("total",) if s in rows[0]["stages_ms"]]
        values = {s: [r["stages_ms"][s] for r in rows] for s in stages}
        result.section(f"{preset} ({int(rows[0]['cells']):,} cells, {int(rows[0]['primary_cells']):,} primaries)")
        result.table(["stage", "median ms", "min ms", "max ms", "max / min"],
                     [[cx.STAGE_LABELS[s], md.ms(statistics.median(v)), md.ms(min(v)), md.ms(max(v)),
                       f"{max(v) / min(v):.2f}" if min(v) > 0 else "-"] for s, v in values.items()])
        if rounds > 1:
            spread = [(max(t) - min(t)) / statistics.median(t) for t in totals_by_round(rows)]
            result.text(f"Rounds at one pose: the total's slowest less its fastest is {100 * statistics.median(spread):.0f}% "
                        f"of its median at the median pose, {100 * max(spread):.0f}% at most.")
    return result.figure(exp.path("stage_over_path.png"))


def main():
    cx.Experiment(__doc__, "stage_over_path.json", ["stage_over_path.png"]).run(measure, report, plot)


if __name__ == "__main__":
    main()
