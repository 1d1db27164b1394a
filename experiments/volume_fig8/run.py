#!/usr/bin/env python3
"""Figure 8 of Duan & Li: GL (on a GPU where one ran it) and CPU ray casting time as the cube grows 10 times by 10x28x25 samples.

Interface (for experiments/run_all):
  experiments/volume_fig8/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/volume_fig8/fig8.json (per growth step: dims, sample count, trimmed-mean time in ms,
samples per second, raw trials, for each caster; machine context), its README.md and
paper_figures/volume_fig8.png (+ .pdf: medians with min-max bars, log time axis). Skips when all
exist unless --force; plots the JSON again when it exists and --force was not given. --quick:
steps 1-3, 128x128 pixels, 5 trials (3 for the CPU caster).

Protocol: synthetic cubes "growth-1" .. "growth-10" (step k: k x 10 inlines, k x 28 crosslines and
k x 25 time samples, 10x28x25 to 100x280x250, seed 1),
a fixed viewpoint (azimuth 40, elevation 25, distance framing the cube, time axis scaled to the
larger lateral extent so the cube's footprint on screen stays the same), grey transfer function,
512x512 pixels, 20 timed trials of the GPU caster and 5 of the CPU caster (the paper's CPU series;
the slow reference, all the machine's threads) after one warm-up each, mean after dropping min and max.
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


CASTERS = (("gpu", "o", "C0", None), ("cpu", "s", "C1", "CPU caster"))  # None: vx.gl_caster_name


def caster_rows(rows, caster):
    """Each growth step's record of `caster` (runs from before the CPU series hold the GPU's at the top level)."""
    return [r.get(caster, r if caster == "gpu" else None) for r in rows]


def plot(exp, result):
    """Median frame time per cube and caster with min-max bars over the trials, log time axis (PNG and PDF)."""
    figure_path = exp.path("volume_fig8.png")
    plt = cx.pyplot()
    rows, size = result["steps"], result["protocol"]["size"][0]
    voxels = [r["voxels"] / 1e6 for r in rows]
    fig, ax = plt.subplots(figsize=(cx.PLOT_WIDTH_IN, 4.4))
    shown_ms = []
    for caster, marker, colour, name in CASTERS:
        name = name or vx.gl_caster_name(result["context"])
        records = caster_rows(rows, caster)
        if any(c is None for c in records):
            continue
        shown_ms += [t for c in records for t in c["trials_ms"]]
        medians = [statistics.median(c["trials_ms"]) for c in records]
        threads = result["protocol"].get("cpu_threads") if caster == "cpu" else None
        ax.errorbar(voxels, medians, yerr=cx.min_max_bars(medians, [c["trials_ms"] for c in records]), marker=marker,
                    color=colour, capsize=3,
                    label=f"{name}{f', {threads} threads' if threads else ''}: median and min-max of "
                          f"{len(records[0]['trials_ms'])} trials per cube")
    vx.log_time_axis(ax, shown_ms, cx)
    first, last = rows[0], rows[-1]
    k1 = [d // first["step"] for d in first["dims"]]
    # The size grows as k cubed: on a log axis the ten steps spread out (on a linear one four of
    # them sat in its first 7%).
    ax.set_xscale("log")
    ax.set_xlabel(f"cube size (million voxels, log scale); step k = {first['step']}..{last['step']}: k x {k1[0]} inlines, "
                  f"k x {k1[1]} crosslines,\nk x {k1[2]} time samples ({'x'.join(map(str, first['dims']))} to "
                  f"{'x'.join(map(str, last['dims']))})")
    ax.set_ylabel("time per frame (ms, log)")
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
    cpu_trials = 3 if quick else 5

    rows, last_stats = [], None
    with vx.Workspace(exp) as work:
        for step in steps:
            cube = work.generate(f"growth-{step}", "--preset", f"growth-{step}", "--seed", "1")
            row = {"step": step}
            for caster, repeat in (("gpu", trials), ("cpu", cpu_trials)):
                stats = work.volume(cube, "--caster", caster, "--tf", "grey", "--camera", "40", "25", "0",
                                    "--size", str(size), str(size), "--warmup", "1", "--repeat", str(repeat))
                times = vx.frame_times_ms(stats)
                row["dims"] = stats["input"]["dims"]
                row[caster] = {"trimmed_mean_ms": vx.trimmed_mean(times), "trials_ms": times, "samples": stats["samples"],
                               "samples_per_second": stats["samples_per_second"], "gl_query_valid": stats["gl_query_valid"]}
                if caster == "gpu":
                    last_stats = stats
                else:
                    cpu_threads = stats["configuration"].get("cpu_threads")
            os.remove(cube)
            dims = row["dims"]
            row["voxels"] = dims[0] * dims[1] * dims[2]
            rows.append(row)
            print(f"growth-{step} {dims}: GPU {row['gpu']['trimmed_mean_ms']:.2f} ms, CPU {row['cpu']['trimmed_mean_ms']:.2f} ms")

    result = {
        "experiment": "volume_fig8", "quick": quick,
        "protocol": {"cubes": "growth-k: k x 10 inlines, k x 28 crosslines, k x 25 time samples, seed 1", "viewpoint": [40, 25, 0],
                     "size": [size, size], "trials": trials, "cpu_trials": cpu_trials, "cpu_threads": cpu_threads, "warmup": 1,
                     "casters": ["gpu", "cpu"], "transfer_function": "grey",
                     "statistic": "mean after dropping min and max",
                     "time": "fenced wall clock of exit_points + ray_cast stages (readback excluded; the CPU caster's "
                             "ray_cast alone), ms",
                     "configuration": last_stats["configuration"]},
        "context": exp.context(last_stats), "steps": rows,
        "slowest_over_fastest": {c: max(r[c]["trimmed_mean_ms"] for r in rows) / min(r[c]["trimmed_mean_ms"] for r in rows)
                                 for c in ("gpu", "cpu")},
        "cpu_over_gpu": [r["cpu"]["trimmed_mean_ms"] / r["gpu"]["trimmed_mean_ms"] for r in rows]}
    return result


def report(exp, document):
    """Per growth step: the cube, each caster's median and trimmed-mean time, samples per second."""
    proto, steps = document["protocol"], document["steps"]
    gpu, cpu = caster_rows(steps, "gpu"), caster_rows(steps, "cpu")
    both = all(c is not None for c in cpu)
    medians = [statistics.median(c["trials_ms"]) for c in gpu]
    cpu_medians = [statistics.median(c["trials_ms"]) for c in cpu] if both else []
    cpu_part = f" and {proto.get('cpu_trials')} of the CPU caster" if both else ""
    ratios = f"; the CPU caster {min(document['cpu_over_gpu']):.1f}-{max(document['cpu_over_gpu']):.1f}x the GL caster's" if both else ""
    result = md.Report(
        "Seismic figure 8: GPU and CPU ray casting time as the cube grows",
        f"Time to ray cast growing synthetic seismic cubes (growth-k, k = {steps[0]['step']}..{steps[-1]['step']}: "
        f"k x {steps[0]['dims'][0] // steps[0]['step']} inlines, k x {steps[0]['dims'][1] // steps[0]['step']} crosslines "
        f"and k x {steps[0]['dims'][2] // steps[0]['step']} time samples, seed 1) from one viewpoint (azimuth "
        f"{proto['viewpoint'][0]}, elevation {proto['viewpoint'][1]}, the time axis scaled so the cube's footprint on "
        f"screen stays the same) into {proto['size'][0]}x{proto['size'][1]} pixels, "
        f"{proto['transfer_function']} transfer function, as Duan & Li's figure 8: {proto['trials']} timed trials of the "
        f"GPU caster{cpu_part} per cube after "
        f"{proto['warmup']} warm-up; a trial is the {proto['time']}.",
        headline=f"{steps[0]['voxels']:,} to {steps[-1]['voxels']:,} voxels: {vx.gl_caster_name(document['context'])} "
                 f"{md.ms(medians[0])} to {md.ms(medians[-1])} ms (medians){ratios}")
    if "llvmpipe" in str(document["context"].get("gl_renderer", "")):
        result.text("Here the fragment-shader (\"GPU\") caster ran on llvmpipe, a software rasteriser on the CPU: the "
                    "columns named GPU below are that GL caster (scripts/device-benchmarks.sh measures it on a lent GPU).")
    result.section("Per cube")
    header = ["step", "dims", "voxels", "GPU median ms", "GPU min-max ms", "GPU trimmed mean ms", "GPU samples / s (millions)"]
    if both:
        header += ["CPU median ms", "CPU trimmed mean ms", "CPU / GPU"]
    rows = []
    for k, (r, g, m) in enumerate(zip(steps, gpu, medians)):
        row = [r["step"], "x".join(map(str, r["dims"])), f"{r['voxels']:,}", md.ms(m),
               f"{md.ms(min(g['trials_ms']))}-{md.ms(max(g['trials_ms']))}", md.ms(g["trimmed_mean_ms"]),
               f"{g['samples_per_second'] / 1e6:,.0f}"]
        if both:
            row += [md.ms(cpu_medians[k]), md.ms(cpu[k]["trimmed_mean_ms"]), f"{document['cpu_over_gpu'][k]:.1f}x"]
        rows.append(row)
    result.table(header, rows)
    slowest = document["slowest_over_fastest"]
    if isinstance(slowest, dict):
        result.text(f"Slowest / fastest cube (trimmed means): GPU caster {slowest['gpu']:.2f}x, CPU caster {slowest['cpu']:.2f}x.")
    else:
        result.text(f"Slowest / fastest cube (trimmed means): {slowest:.2f}x.")
    return result.figure(exp.path("volume_fig8.png"))


def main():
    cx.Experiment(__doc__, "fig8.json", ["volume_fig8.png"], tools=("cutaway",)).run(measure, report, plot)


if __name__ == "__main__":
    main()
