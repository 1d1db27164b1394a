#!/usr/bin/python3
"""Stage times over the camera path for each model (the thesis's figures 5.1-5.4).

Interface (for experiments/run_all):
  experiments/stage_over_path/run.py [--quick] [--force] [--build DIR]
Writes results/stage_over_path/stage_over_path.json (per model, per pose: azimuth, aperture, fenced
ms per stage) and paper_figures/stage_over_path.png (one panel per model). Skips when both exist
unless --force. --quick: 480x270 pixels, 3 poses, two models (results/quick/, paper_figures/quick/).

Protocol: Table 1's settings (9x9 mean filter, 1% primaries, SSAO on, frustum cut, ray-cast borders),
1920x1080, a 16-pose path (bench_cutaway --per_pose: azimuth steps of 22.5 degrees, elevation
alternating 25/45, full aperture rising 30..120 degrees), one warm-up pass, one timed frame per pose.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402


def main():
    exp = cx.Experiment("stage_over_path", __doc__, ["stage_over_path.json", "stage_over_path.png"])
    if exp.up_to_date():
        return
    size, poses = ("480x270", 3) if exp.quick else ("1920x1080", 16)
    presets = cx.PRESETS[:2] if exp.quick else cx.PRESETS
    document = exp.benchmark("--presets=" + ",".join(presets), "--size=" + size, "--poses=" + str(poses), "--per_pose",
                             "--fractions=0.01", "--mean_filters=9", "--borders=raycast", "--strategies=frustum",
                             "--warmup=1", "--repeat=1", "--benchmark_filter=BM_cutaway")
    path = document["context"]["camera_path_az_el_aperture_deg"].split("; ")
    models = {p: sorted((r for r in cx.cutaway_runs(document) if r["preset"] == p), key=lambda r: r["pose"]) for p in presets}
    cx.write_json(exp.path("stage_over_path.json"), {
        "experiment": "stage_over_path", "quick": exp.quick, "size": size,
        "camera_path_az_el_aperture_deg": path,
        "context": {**exp.context(), **cx.benchmark_context(document)},
        "models": {p: [{"pose": r["pose"], "aperture_deg": r.get("aperture_deg"), "stages_ms": r["stages_ms"],
                        "primary_cells": r["primary_cells"], "cells": r["cells"]} for r in rows]
                   for p, rows in models.items()}})

    plt = cx.pyplot()
    fig, axes = plt.subplots(len(presets), 1, figsize=(7, 2.4 * len(presets)), sharex=True, squeeze=False)
    for ax, preset in zip(axes[:, 0], presets):
        rows = models[preset]
        for stage in cx.STAGES + ("total",):
            ax.plot([r["pose"] for r in rows], [r["stages_ms"][stage] for r in rows], marker="o", label=cx.STAGE_LABELS[stage])
        ax.set_ylabel("time (ms)")
        ax.set_title(f"{preset} ({int(rows[0]['cells']):,} cells, {int(rows[0]['primary_cells'])} primaries), {size}")
    axes[0, 0].legend(ncol=4, loc="upper left")
    axes[-1, 0].set_xlabel(f"camera pose (index; azimuth step {360 / poses:g} degrees, full aperture 30 to 120 degrees)")
    cx.save_figure(fig, exp.path("stage_over_path.png"))


if __name__ == "__main__":
    main()
