#!/usr/bin/env python3
"""Figure 8 of Duan & Li: GPU ray casting time as the cube grows 10 times by 10x28x25 samples.

Interface (for experiments/run_all):
  experiments/volume_fig8/run.py [--quick] [--force] [--build DIR]
Writes results/volume/fig8.json (per growth step: dims, sample count, trimmed-mean time in ms,
samples per second, raw trials; machine context) and paper_figures/volume_fig8.png (+ .pdf: medians
with min-max bars). Skips when both exist unless --force; plots the JSON again when only the
figure is missing. --quick: steps 1-3, 128x128 pixels, 5 trials.

Protocol: synthetic cubes "growth-1" .. "growth-10" (step k: 10k x 28k x 25k samples, seed 1),
a fixed viewpoint (azimuth 40, elevation 25, distance framing the cube, time axis scaled to the
larger lateral extent so the cube's footprint on screen stays the same), grey transfer function,
512x512 pixels, GPU caster, 20 timed trials after one warm-up, mean after dropping min and max.
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "volume_common"))
import volume_experiment as vx  # noqa: E402


def plot(result, figure_path):
    """Median frame time per cube with min-max bars over the trials (PNG and vector PDF)."""
    plt = vx.require_matplotlib()
    rows, size = result["steps"], result["protocol"]["size"][0]
    voxels = [r["voxels"] / 1e6 for r in rows]
    medians = [sorted(r["trials_ms"])[len(r["trials_ms"]) // 2] for r in rows]
    low = [m - min(r["trials_ms"]) for m, r in zip(medians, rows)]
    high = [max(r["trials_ms"]) - m for m, r in zip(medians, rows)]
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.errorbar(voxels, medians, yerr=[low, high], marker="o", capsize=3, label="GPU caster (median, min-max bars)")
    ax.set_xlabel("cube size (million voxels; step k holds 10k inlines x 28k crosslines x 25k time samples)")
    ax.set_ylabel("time per frame (ms)")
    ax.set_ylim(bottom=0)
    ax.set_title(f"Fig. 8: fixed viewpoint, growing cube, {size}x{size} px", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figure_path, dpi=150)
    fig.savefig(os.path.splitext(figure_path)[0] + ".pdf")
    print("wrote", os.path.relpath(figure_path, vx.REPO))


def main():
    json_path = os.path.join(vx.RESULTS, "fig8.json")
    figure_path = os.path.join(vx.FIGURES, "volume_fig8.png")
    args = vx.begin(__doc__, [json_path, figure_path])
    if args is None:
        return
    if not args.force and os.path.exists(json_path):  # measured already: plot again
        with open(json_path) as f:
            plot(json.load(f), figure_path)
        return
    quick = args.quick
    steps = range(1, 4) if quick else range(1, 11)
    size, trials = (128, 5) if quick else (512, 20)

    rows, last_stats = [], None
    with vx.Workspace(args) as work:
        for step in steps:
            cube = work.generate(f"growth-{step}", "--preset", f"growth-{step}", "--seed", "1")
            stats = work.volume(cube, "--caster", "gpu", "--tf", "grey", "--camera", "40", "25", "0",
                                "--size", str(size), str(size), "--warmup", "1", "--repeat", str(trials))
            os.remove(cube)
            times = vx.frame_times_ms(stats)
            dims = stats["input"]["dims"]
            rows.append({"step": step, "dims": dims, "voxels": dims[0] * dims[1] * dims[2],
                         "trimmed_mean_ms": vx.trimmed_mean(times), "trials_ms": times, "samples": stats["samples"],
                         "samples_per_second": stats["samples_per_second"], "gl_query_valid": stats["gl_query_valid"]})
            last_stats = stats
            print(f"growth-{step} {dims}: {rows[-1]['trimmed_mean_ms']:.2f} ms, {stats['samples']} samples")

    result = {
        "experiment": "volume_fig8", "quick": quick,
        "protocol": {"cubes": "growth-k: 10k x 28k x 25k samples, seed 1", "viewpoint": [40, 25, 0],
                     "size": [size, size], "trials": trials, "warmup": 1, "caster": "gpu", "transfer_function": "grey",
                     "statistic": "mean after dropping min and max",
                     "time": "fenced wall clock of exit_points + ray_cast stages (readback excluded), ms",
                     "configuration": last_stats["configuration"]},
        "context": vx.machine_context(last_stats), "steps": rows,
        "slowest_over_fastest": max(r["trimmed_mean_ms"] for r in rows) / min(r["trimmed_mean_ms"] for r in rows)}
    vx.write_json(json_path, result)
    plot(result, figure_path)


if __name__ == "__main__":
    main()
