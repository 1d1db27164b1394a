#!/usr/bin/env python3
"""Figure 8 of Duan & Li: GPU ray casting time as the cube grows 10 times by 10x28x25 samples.

Interface (for experiments/run_all):
  experiments/volume_fig8/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/volume_fig8/fig8.json (per growth step: dims, sample count, trimmed-mean time in ms,
samples per second, raw trials; machine context), its README.md and paper_figures/volume_fig8.png
(+ .pdf: medians with min-max bars). Skips when all exist unless --force; plots the JSON again when
it exists and --force was not given. --quick: steps 1-3, 128x128 pixels, 5 trials.

Protocol: synthetic cubes "growth-1" .. "growth-10" (step k: k x 10 inlines, k x 28 crosslines and
k x 25 time samples, 10x28x25 to 100x280x250, seed 1),
a fixed viewpoint (azimuth 40, elevation 25, distance framing the cube, time axis scaled to the
larger lateral extent so the cube's footprint on screen stays the same), grey transfer function,
512x512 pixels, GPU caster, 20 timed trials after one warm-up, mean after dropping min and max.
"""
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "volume_common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import volume_experiment as vx  # noqa: E402


def plot(exp, result):
    """Median frame time per cube with min-max bars over the trials (PNG and vector PDF)."""
    figure_path = exp.path("volume_fig8.png")
    plt = cx.pyplot()
    rows, size = result["steps"], result["protocol"]["size"][0]
    voxels = [r["voxels"] / 1e6 for r in rows]
    medians = [sorted(r["trials_ms"])[len(r["trials_ms"]) // 2] for r in rows]
    low = [m - min(r["trials_ms"]) for m, r in zip(medians, rows)]
    high = [max(r["trials_ms"]) - m for m, r in zip(medians, rows)]
    fig, ax = plt.subplots(figsize=(cx.PLOT_WIDTH_IN, 4.4))
    ax.errorbar(voxels, medians, yerr=[low, high], marker="o", capsize=3,
                label=f"GPU caster: median and min-max of {result['protocol']['trials']} trials per cube")
    for r, x, y in ((rows[0], voxels[0], medians[0]), (rows[-1], voxels[-1], medians[-1])):
        ax.annotate(f"step {r['step']}: {'x'.join(map(str, r['dims']))}", (x, y), textcoords="offset points",
                    xytext=(8, -14), ha="left" if r is rows[0] else "right")
    k1 = [d // rows[0]["step"] for d in rows[0]["dims"]]
    ax.set_xlabel(f"cube size (million voxels); step k = {rows[0]['step']}..{rows[-1]['step']}: k x {k1[0]} inlines, "
                  f"k x {k1[1]} crosslines,\nk x {k1[2]} time samples")
    ax.set_ylabel("time per frame (ms)")
    ax.set_ylim(bottom=0)
    fig.suptitle(f"Fig. 8: fixed viewpoint, growing cube, {size}x{size} px\non {cx.device_label(result['context'])}")
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", frameon=False)
    cx.save_figure(fig, figure_path)
    plt.close(fig)


def measure(exp):
    """The GPU caster on each growth step; the stored run instead when there is one and no --force."""
    if not exp.force and exp.stored():  # measured already: plot and report again
        return exp.stored()
    quick = exp.quick
    steps = range(1, 4) if quick else range(1, 11)
    size, trials = (128, 5) if quick else (512, 20)

    rows, last_stats = [], None
    with vx.Workspace(exp) as work:
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
        "protocol": {"cubes": "growth-k: k x 10 inlines, k x 28 crosslines, k x 25 time samples, seed 1", "viewpoint": [40, 25, 0],
                     "size": [size, size], "trials": trials, "warmup": 1, "caster": "gpu", "transfer_function": "grey",
                     "statistic": "mean after dropping min and max",
                     "time": "fenced wall clock of exit_points + ray_cast stages (readback excluded), ms",
                     "configuration": last_stats["configuration"]},
        "context": exp.context(last_stats), "steps": rows,
        "slowest_over_fastest": max(r["trimmed_mean_ms"] for r in rows) / min(r["trimmed_mean_ms"] for r in rows)}
    return result


def report(exp, document):
    """Per growth step: the cube, its median and trimmed-mean time, samples per second."""
    proto, steps = document["protocol"], document["steps"]
    medians = [statistics.median(r["trials_ms"]) for r in steps]
    result = md.Report(
        "Seismic figure 8: GPU ray casting time as the cube grows",
        f"Time to ray cast growing synthetic seismic cubes (growth-k, k = {steps[0]['step']}..{steps[-1]['step']}: "
        f"k x {steps[0]['dims'][0] // steps[0]['step']} inlines, k x {steps[0]['dims'][1] // steps[0]['step']} crosslines "
        f"and k x {steps[0]['dims'][2] // steps[0]['step']} time samples, seed 1) from one viewpoint (azimuth "
        f"{proto['viewpoint'][0]}, elevation {proto['viewpoint'][1]}, the time axis scaled so the cube's footprint on "
        f"screen stays the same) into {proto['size'][0]}x{proto['size'][1]} pixels, {proto['caster'].upper()} caster, "
        f"{proto['transfer_function']} transfer function, as Duan & Li's figure 8: {proto['trials']} timed trials per cube "
        f"after {proto['warmup']} warm-up; a trial is the {proto['time']}.",
        headline=f"{steps[0]['voxels']:,} to {steps[-1]['voxels']:,} voxels: "
                 f"{md.ms(medians[0])} to {md.ms(medians[-1])} ms (medians)")
    result.section("Per cube")
    result.table(["step", "dims", "voxels", "median ms", "min-max ms", "trimmed mean ms", "samples / s (millions)"],
                 [[r["step"], "x".join(map(str, r["dims"])), f"{r['voxels']:,}", md.ms(m),
                   f"{md.ms(min(r['trials_ms']))}-{md.ms(max(r['trials_ms']))}", md.ms(r["trimmed_mean_ms"]),
                   f"{r['samples_per_second'] / 1e6:,.0f}"] for r, m in zip(steps, medians)])
    result.text(f"Slowest / fastest cube (trimmed means): {document['slowest_over_fastest']:.2f}x.")
    return result.figure(exp.path("volume_fig8.png"))


def main():
    cx.Experiment(__doc__, "fig8.json", ["volume_fig8.png"], tools=("cutaway",)).run(measure, report, plot)


if __name__ == "__main__":
    main()
