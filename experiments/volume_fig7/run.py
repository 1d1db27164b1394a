#!/usr/bin/env python3
"""Figure 7 of Duan & Li: GPU vs CPU ray casting time of a 101x101x250 cube from 10 eye positions.

Interface (for experiments/run_all):
  experiments/volume_fig7/run.py [--quick] [--force] [--build DIR]
Writes results/volume/fig7.json (per eye: trimmed-mean times in ms, raw trials, samples; machine
context) and paper_figures/volume_fig7.png. Skips when both exist unless --force. --quick: a
20x20x40 cube, 128x128 pixels, 5 GPU / 3 CPU trials per eye (well under a minute).

Protocol: the synthetic "paper-250" cube (seed 1), layer highlight off (grey transfer function,
the paper's default display), 512x512 pixels, eye azimuths 0, 36, ..., 324 degrees at 25 degrees
elevation, distance framing the cube. GPU: 50 timed trials per eye after one warm-up, mean after
dropping min and max (the paper's protocol). CPU: the reference caster is slow on this 2-core
machine, so 5 trials per eye (same trimming). A trial's time is the fenced wall time of the exit
points and ray casting passes (readback excluded), as `cutaway volume --stats` reports it.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "volume_common"))
import volume_experiment as vx  # noqa: E402

PAPER = {"gpu_ms": {"min": 14.19, "max": 15.70, "mean": 14.99}, "cpu_ms": {"min": 9250, "max": 9737, "mean": 9486}}


def main():
    json_path = os.path.join(vx.RESULTS, "fig7.json")
    figure_path = os.path.join(vx.FIGURES, "volume_fig7.png")
    args = vx.begin(__doc__, [json_path, figure_path])
    if args is None:
        return
    plt = vx.require_matplotlib()
    quick = args.quick
    cube_options = ["--dims", "20", "20", "40"] if quick else ["--preset", "paper-250"]
    size = 128 if quick else 512
    trials = {"gpu": 5 if quick else 50, "cpu": 3 if quick else 5}
    azimuths = [36 * k for k in range(10)]

    with vx.Workspace(args) as work:
        cube = work.generate("fig7", *cube_options, "--seed", "1")
        eyes, last_stats = [], None
        for azimuth in azimuths:
            eye = {"azimuth_deg": azimuth, "elevation_deg": 25}
            for caster in ("gpu", "cpu"):
                stats = work.volume(cube, "--caster", caster, "--tf", "grey", "--camera", str(azimuth), "25", "0",
                                    "--size", str(size), str(size), "--warmup", "1", "--repeat", str(trials[caster]))
                times = vx.frame_times_ms(stats)
                eye[caster] = {"trimmed_mean_ms": vx.trimmed_mean(times), "trials_ms": times, "samples": stats["samples"],
                               "samples_per_second": stats["samples_per_second"],
                               "gl_query_valid": stats["gl_query_valid"]}
                if caster == "gpu":
                    last_stats = stats
            print(f"azimuth {azimuth:3d}: gpu {eye['gpu']['trimmed_mean_ms']:.2f} ms, cpu {eye['cpu']['trimmed_mean_ms']:.1f} ms")
            eyes.append(eye)

    summary = {}
    for caster in ("gpu", "cpu"):
        means = [e[caster]["trimmed_mean_ms"] for e in eyes]
        summary[caster] = {"min_ms": min(means), "max_ms": max(means), "mean_ms": sum(means) / len(means)}
    summary["cpu_over_gpu"] = summary["cpu"]["mean_ms"] / summary["gpu"]["mean_ms"]
    vx.write_json(json_path, {
        "experiment": "volume_fig7", "quick": quick,
        "protocol": {"cube": cube_options, "seed": 1, "size": [size, size], "transfer_function": "grey",
                     "eyes": len(azimuths), "trials_per_eye": trials, "warmup_per_eye": 1,
                     "statistic": "mean after dropping min and max of each eye's trials",
                     "note": "CPU caster uses fewer trials than the paper's 50: it is slow on this 2-core machine",
                     "time": "fenced wall clock of exit_points + ray_cast stages (readback excluded), ms",
                     "configuration": last_stats["configuration"]},
        "context": vx.machine_context(last_stats), "eyes": eyes, "summary": summary, "paper": PAPER})

    renderer = (last_stats["gl_renderer"] or "GPU").split(" (")[0]
    fig, ax = plt.subplots(figsize=(7, 4))
    for caster, marker in (("gpu", "o"), ("cpu", "s")):
        ax.plot(azimuths, [e[caster]["trimmed_mean_ms"] for e in eyes], marker=marker,
                label=f"{caster.upper()} caster ({renderer if caster == 'gpu' else 'C++ threads'}, "
                      f"mean {summary[caster]['mean_ms']:.1f} ms)")
        ax.axhline(PAPER[f"{caster}_ms"]["mean"], linestyle="--", color="grey", linewidth=0.8)
    ax.set_yscale("log")
    ax.set_xlabel("eye azimuth (degrees, elevation 25)")
    ax.set_ylabel("time per frame (ms, log scale)")
    ax.set_title(f"Fig. 7: ray casting {'20x20x40' if quick else '101x101x250'}, {size}x{size} px "
                 f"(dashed: paper's GPU 14.99 ms / CPU 9486 ms)", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figure_path, dpi=150)
    print("wrote", os.path.relpath(figure_path, vx.REPO))


if __name__ == "__main__":
    main()
