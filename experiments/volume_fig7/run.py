#!/usr/bin/env python3
"""Figure 7 of Duan & Li: GL (GPU) caster vs CPU caster, ray casting time of a 101x101x250 cube from 10 eye positions.

Interface (for experiments/run_all):
  experiments/volume_fig7/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/volume_fig7/fig7.json (per eye: median time in ms, raw trials, samples; machine
context), its README.md and paper_figures/volume_fig7.png. Skips when both exist unless --force. --quick: a
20x20x40 cube, 128x128 pixels, 5 GPU / 3 CPU trials per eye (well under a minute).

Protocol: the synthetic "paper-250" cube (seed 1), layer highlight off (grey transfer function,
the paper's default display), 512x512 pixels, eye azimuths 0, 36, ..., 324 degrees at 25 degrees
elevation, distance framing the cube. GPU: 50 timed trials per eye after one warm-up (the paper's
count). CPU: the reference caster, 5 trials per eye. Per eye the median of its trials, bars from the
fastest to the slowest, as figure 8 (volume_fig8) and the other experiments report; Duan & Li's
numbers are means after dropping the min and max, quoted as such. A trial's time is the fenced wall
time of the exit points and ray casting passes (readback excluded), as `cutaway volume --stats`
reports it.
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

PAPER = {"gpu_ms": {"min": 14.19, "max": 15.70, "mean": 14.99}, "cpu_ms": {"min": 9250, "max": 9737, "mean": 9486}}


def measure(exp):
    """Both casters from every eye; returns the document."""
    quick = exp.quick
    cube_options = ["--dims", "20", "20", "40"] if quick else ["--preset", "paper-250"]
    size = 128 if quick else 512
    trials = {"gpu": 5 if quick else 50, "cpu": 3 if quick else 5}
    azimuths = [36 * k for k in range(10)]

    with vx.Workspace(exp) as work:
        cube = work.generate("fig7", *cube_options, "--seed", "1")
        eyes, last_stats = [], None
        for azimuth in azimuths:
            eye = {"azimuth_deg": azimuth, "elevation_deg": 25}
            for caster in ("gpu", "cpu"):
                stats = work.volume(cube, "--caster", caster, "--tf", "grey", "--camera", str(azimuth), "25", "0",
                                    "--size", str(size), str(size), "--warmup", "1", "--repeat", str(trials[caster]))
                times = vx.frame_times_ms(stats)
                eye[caster] = {"median_ms": statistics.median(times), "trials_ms": times, "samples": stats["samples"],
                               "samples_per_second": stats["samples_per_second"],
                               "gl_query_valid": stats["gl_query_valid"]}
                if caster == "gpu":
                    last_stats = stats
            print(f"azimuth {azimuth:3d}: gpu {eye['gpu']['median_ms']:.2f} ms, cpu {eye['cpu']['median_ms']:.1f} ms (medians)")
            eyes.append(eye)

    document = {
        "experiment": "volume_fig7", "quick": quick,
        "protocol": {"cube": cube_options, "seed": 1, "size": [size, size], "transfer_function": "grey",
                     "eyes": len(azimuths), "trials_per_eye": trials, "warmup_per_eye": 1,
                     "statistic": "median of each eye's trials",
                     "note": "CPU caster uses fewer trials than the paper's 50: it is the slow reference",
                     "time": "fenced wall clock of exit_points + ray_cast stages (readback excluded), ms",
                     "configuration": last_stats["configuration"]},
        "context": exp.context(last_stats), "eyes": eyes, "summary": summarise(eyes), "paper": PAPER}
    return document


def eye_medians(eyes, caster):
    """Each eye's median over its trials of `caster` (from the raw trials: runs from before the
    medians stored trimmed means)."""
    return [statistics.median(e[caster]["trials_ms"]) for e in eyes]


def summarise(eyes):
    """Per caster the fastest, median and slowest of the eyes' medians, and the ratio of the casters' medians."""
    summary = {}
    for caster in ("gpu", "cpu"):
        medians = eye_medians(eyes, caster)
        summary[caster] = {"min_ms": min(medians), "median_ms": statistics.median(medians), "max_ms": max(medians)}
    summary["cpu_over_gpu"] = summary["cpu"]["median_ms"] / summary["gpu"]["median_ms"]
    return summary


def plot(exp, document):
    """Each caster's median per eye on a log axis, bars from its fastest to its slowest trial.
    The paper's numbers were measured on other hardware: they are not drawn on the axes but stated
    below them as a reference, beside this run's ratio."""
    figure_path = exp.path("volume_fig7.png")
    plt = cx.pyplot()
    eyes, summary, quick = document["eyes"], summarise(document["eyes"]), document["quick"]
    paper = document["paper"]
    size = document["protocol"]["size"][0]
    threads = document["protocol"]["configuration"].get("cpu_threads")
    azimuths = [e["azimuth_deg"] for e in eyes]
    fig, ax = plt.subplots(figsize=(cx.PLOT_WIDTH_IN, 4.8))
    gl_name = vx.gl_caster_name(document["context"])
    casters = (("gpu", "o", "C0", gl_name), ("cpu", "s", "C1", "CPU caster" + (f", {threads} threads" if threads else "")))
    for caster, marker, colour, name in casters:
        medians = eye_medians(eyes, caster)
        ax.errorbar(azimuths, medians, yerr=cx.min_max_bars(medians, [e[caster]["trials_ms"] for e in eyes]), marker=marker,
                    color=colour, capsize=3, label=f"{name}: {len(eyes[0][caster]['trials_ms'])} trials per eye; "
                                                   f"median over the eyes {summary[caster]['median_ms']:.1f} ms")
    vx.log_time_axis(ax, [t for e in eyes for c in ("gpu", "cpu") for t in e[c]["trials_ms"]], cx)
    ax.set_xticks(azimuths)
    ax.set_xlabel("eye azimuth (degrees, elevation 25)")
    ax.set_ylabel("time per frame (ms, log scale): an eye's\nmedian, bars its fastest to slowest trial")
    fig.suptitle(f"Fig. 7: ray casting {'20x20x40' if quick else '101x101x250'} samples into {size}x{size} px\n"
                 f"on {cx.device_label(document['context'])}")
    handles, labels = ax.get_legend_handles_labels()
    published = paper["cpu_ms"]["mean"] / paper["gpu_ms"]["mean"]
    labels.append(f"CPU caster / {gl_name}: {summary['cpu_over_gpu']:.2f}x here (medians).\nFor reference, not measured here: "
                  f"Duan & Li published means of GPU {paper['gpu_ms']['mean']:g} ms and CPU {paper['cpu_ms']['mean']:g} ms "
                  f"({published:.0f}x),\non their own GPU and CPU.")
    from matplotlib.patches import Patch
    handles.append(Patch(visible=False))
    fig.legend(handles, labels, ncol=1, loc="lower center", frameon=False)
    cx.save_figure(fig, figure_path)
    plt.close(fig)


def report(exp, document):
    """Per eye both casters' medians and their ratio, the paper's numbers (means) beside."""
    summary, proto, paper = summarise(document["eyes"]), document["protocol"], document["paper"]
    gpu, cpu = summary["gpu"], summary["cpu"]
    result = md.Report(
        "Seismic figure 7: GPU against CPU ray casting",
        f"Time to ray cast the synthetic seismic cube `cutaway generate-seismic {' '.join(proto['cube'])}` "
        f"(seed {proto['seed']}) into {proto['size'][0]}x{proto['size'][1]} pixels with the grey "
        f"transfer function from {proto['eyes']} eyes around it (azimuth steps of 36 degrees, elevation 25), with the GPU "
        "caster (fragment shader, empty-space skipping, early termination) and the CPU reference caster, as Duan & Li's "
        f"figure 7. Per eye: {proto['trials_per_eye']['gpu']} GPU / {proto['trials_per_eye']['cpu']} CPU timed trials after "
        f"{proto['warmup_per_eye']} warm-up, the median of each eye's trials (as figure 8); a trial is the {proto['time']}. "
        "Over the eyes: the fastest, median and slowest of the eyes' medians. Duan & Li's numbers are their means (after "
        "dropping each eye's minimum and maximum) over the eyes, on their own hardware.",
        headline=f"{vx.gl_caster_name(document['context'])} {gpu['median_ms']:.1f} ms vs CPU caster {cpu['median_ms']:.1f} ms "
                 f"({summary['cpu_over_gpu']:.2f}x), medians")
    if "llvmpipe" in str(document["context"].get("gl_renderer", "")):
        result.text("Here the fragment-shader (\"GPU\") caster ran on llvmpipe, a software rasteriser on the same CPU as "
                    "the CPU caster: the rows named GPU below are that GL caster, and their ratio is not the paper's "
                    "GPU against CPU (scripts/device-benchmarks.sh measures it on a lent GPU).")
    result.section("Summary over the eyes")
    result.table(["caster", "min ms", "median ms", "max ms", "paper mean ms (min-max)"],
                 [[c.upper(), md.ms(summary[c]["min_ms"]), md.ms(summary[c]["median_ms"]), md.ms(summary[c]["max_ms"]),
                   f"{md.ms(paper[c + '_ms']['mean'])} ({md.ms(paper[c + '_ms']['min'])}-{md.ms(paper[c + '_ms']['max'])})"]
                  for c in ("gpu", "cpu")])
    result.text(f"CPU / GPU: {summary['cpu_over_gpu']:.2f}x here (medians), "
                f"{paper['cpu_ms']['mean'] / paper['gpu_ms']['mean']:.0f}x in the paper (means).")
    result.section("Per eye")
    eyes = document["eyes"]
    trials = {c: [e[c]["trials_ms"] for e in eyes] for c in ("gpu", "cpu")}
    medians = {c: eye_medians(eyes, c) for c in ("gpu", "cpu")}
    result.table(["azimuth (deg)", "GPU median ms", "GPU min-max ms", "CPU median ms", "CPU min-max ms", "CPU / GPU",
                  "GPU samples"],
                 [[e["azimuth_deg"], md.ms(medians["gpu"][k]), f"{md.ms(min(trials['gpu'][k]))}-{md.ms(max(trials['gpu'][k]))}",
                   md.ms(medians["cpu"][k]), f"{md.ms(min(trials['cpu'][k]))}-{md.ms(max(trials['cpu'][k]))}",
                   f"{medians['cpu'][k] / medians['gpu'][k]:.2f}", f"{e['gpu']['samples']:,}"] for k, e in enumerate(eyes)])
    return result.figure(exp.path("volume_fig7.png"))


def main():
    cx.Experiment(__doc__, "fig7.json", ["volume_fig7.png"], tools=("cutaway",)).run(measure, report, plot)


if __name__ == "__main__":
    main()
