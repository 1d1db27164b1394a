#!/usr/bin/env python3
"""Cut-surface strategies compared fairly: stage-1 time, error against the exact cone field, exposure, context.

Interface (for experiments/run_all):
  experiments/cut_strategies/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/cut_strategies/results.json (one row per preset x primary fraction x strategy, the
CPU paths the GPU transforms replace, the crossover, machine context), results/cut_strategies/README.md
and paper_figures/cut_strategies_time.png, cut_strategies_ratio.png and cut_strategies_error.png (+ .pdf).
Skips when all exist unless --force; --report-only redraws the plots and the README from results.json.
--quick: petra only, fractions 1% and 20%, 480x270 for both steps (results/quick/, paper_figures/quick/).

Protocol (SPEC.md section 2, issue 16):
- Time: ONE bench_cutaway process (Google Benchmark) over the product preset (zaphirus, petra,
  opharine, sapphire) x primary fraction (top 0.1%, 1%, 5%, 20% of PORO) x every registry strategy
  x aperture 60 degrees (`cutaway render`'s default), at 1920x1080, mean filter and SSAO off (they
  follow stage 1 and do not change its time), no plain-frame baseline, ray-cast borders, visible
  draw; the 2-pose camera path (azimuth/elevation 0/25 and 180/45 degrees), one untimed pass then
  one timed frame per pose: counters are medians of 2 frames. One frame per pose keeps the
  slowest configuration bounded (per-cell `frustum` at 20% of sapphire: about 2 min a frame on
  llvmpipe). A second process (BM_cpu_path only, CPU_PATH_REPEAT timed frames per pose) times jfa
  and jfa2 against the CPU path they replaced on the same frames' inputs, interleaved: the GPU
  seed pass alone, the GPU strategy (seed pass + transform), the CPU path (seed pass, read-back,
  CPU transform, upload); the transform speedup leaves out the seed pass both share. The
  primaries' screen footprint is the benchmark's `primary_pixels` (visible primary pixels of the
  timed frames at 1920x1080, median), taken from the `frustum` row (its exposure is 1.0: every
  primary pixel stays visible).
- Quality: one `cutaway render --exact-check` per configuration at QUALITY_SIZE (the exact cone
  field is a CPU reference), camera = the path's first pose, aperture 60: cut_vs_exact (wrong
  pixels beyond the tolerance against the exact cone field from the same seeds), primary_exposure,
  context_kept, primary_pixels (primaries-only frame at that size).
- readback_bytes must be 0 for every GPU strategy in both steps (the script fails otherwise).
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import strategy_style  # noqa: E402

APERTURE_DEG = 60          # `cutaway render`'s default full opening angle
POSES, WARMUP, REPEAT = 2, 1, 1
CPU_PATH_REPEAT = 5        # BM_cpu_path: 2 poses x 5 = 10 interleaved samples per configuration
FIRST_POSE = ("0", "25", "0")  # camera_path.h pose 0 (azimuth, elevation, framing distance)
# Compared with the paper's per-cell frustum union at matched accuracy: the near-exact cone-field
# transform (JFA^2, SPEC: at most 0.02% wrong) and the exact O(pixels) union of the frustums
# (frustum-sweep, equal to the rasterised union: frustum_sweep_gl_test). The Chamfer masks, wrong on
# most pixels, are timed and listed but not used for the crossover.
ALTERNATIVES = ("jfa2", "frustum-sweep")
CPU_REFERENCES = ("jfa", "jfa2")
WRONG_PERCENT_LINEAR_BELOW = 1e-4  # the error plot's wrong-pixel axis: linear below, log above (%)
RATIO_DODGE_DECADES = 0.08  # the ratio plot's sideways spread of one configuration's points, log10 units
FIGURES = ("cut_strategies_time.png", "cut_strategies_ratio.png", "cut_strategies_error.png")


def configuration(quick):
    if quick:
        return {"presets": ["petra"], "fractions": [0.01, 0.2], "size": (480, 270), "quality_size": (480, 270)}
    return {"presets": list(cx.PRESETS), "fractions": [0.001, 0.01, 0.05, 0.2], "size": (1920, 1080),
            "quality_size": (640, 360)}


def sweep_flags(config, strategies, repeat):
    """bench_cutaway flags shared by both processes: the configurations and the frame settings."""
    size = config["size"]
    return ["--presets=" + ",".join(config["presets"]), "--fractions=" + ",".join(map(str, config["fractions"])),
            "--strategies=" + ",".join(strategies), f"--apertures={APERTURE_DEG}", "--mean_filters=0",
            "--borders=raycast", "--draws=visible", f"--size={size[0]}x{size[1]}", f"--poses={POSES}",
            f"--warmup={WARMUP}", f"--repeat={repeat}", "--ssao=0", "--baseline=0"]


def checked(document):
    failed = [b["name"] + ": " + b.get("error_message", "") for b in document["benchmarks"] if b.get("error_occurred")]
    if failed:
        raise SystemExit("bench_cutaway reported errors:\n  " + "\n  ".join(failed))
    return document


def time_sweep(exp, config):
    """The strategy sweep (one bench_cutaway process, BM_cutaway rows keyed (preset, fraction,
    strategy)), then the GPU transforms against the CPU paths they replaced (a second process, BM_cpu_path
    only, CPU_PATH_REPEAT frames per pose: its ratios are what issue 16's target reads, and two frames
    per configuration left them at the machine's noise), keyed the same way; plus the first document."""
    document = checked(exp.benchmark(*sweep_flags(config, ["all"], REPEAT), "--cpu_references=none", progress=True))
    timed = {(r["preset"], r["primary_fraction"], r["strategy"]): r for r in cx.cutaway_runs(document)}
    strategies = document["context"]["strategies"].split(",")
    cpu_document = checked(exp.benchmark(*sweep_flags(config, CPU_REFERENCES, CPU_PATH_REPEAT),
                                         "--cpu_references=" + ",".join(CPU_REFERENCES), "--benchmark_filter=BM_cpu_path",
                                         progress=True))
    cpu = {(r["preset"], r["primary_fraction"], r["strategy"]): {k: r[k] for k in cx.CPU_PATH_COUNTERS}
           for r in cx.cpu_path_runs(cpu_document)}
    return document, timed, cpu, strategies


def quality(exp, config, preset, fraction, strategy):
    """One render with --exact-check at the quality size: the strategy's stats object."""
    w, h = config["quality_size"]
    return exp.render(f"preset:{preset}", "--primary-fraction", fraction, "--strategy", strategy, "--exact-check",
                      "--mean-filter", 0, "--size", w, h, "--camera", *FIRST_POSE,
                      "--aperture", APERTURE_DEG, APERTURE_DEG, "--warmup", 0, "--repeat", 1, metrics=True)


def merge_row(preset, fraction, strategy, timed, stats):
    device = stats["strategy"]["device"]
    row = {"preset": preset, "primary_fraction": fraction, "strategy": strategy, "device": device,
           "why": stats["strategy"]["why"], "cells": stats["active_cells"], "primary_cells": int(timed["primary_cells"]),
           "cut_surface_ms": timed["stages_ms"]["cut_surface"], "total_ms": timed["stages_ms"]["total"],
           "primary_pixels": int(timed["primary_pixels"]),
           "readback_bytes": int(timed["readback_bytes"]), "gl_query_valid": timed.get("gl_query_valid"),
           "quality": {"cut_vs_exact": stats["cut_vs_exact"], "primary_exposure": stats["primary_exposure"],
                       "context_kept": stats["context_kept"], "primary_pixels": stats["primary_pixels"],
                       "primary_cells": stats["primary_cells"], "readback_bytes": stats["readback_bytes"]}}
    if device == "gpu" and (row["readback_bytes"] != 0 or stats["readback_bytes"] != 0):
        raise SystemExit(f"{preset} {fraction} {strategy}: a GPU strategy read back {row['readback_bytes']} B "
                         f"(benchmark) / {stats['readback_bytes']} B (render) per frame; expected 0")
    return row


def best_threshold(points):
    """points: (key, alternative_cheaper). The single threshold T ("cheaper iff key >= T") that
    misclassifies the fewest points: (T or None for 'never', misclassified count)."""
    keys = sorted({k for k, _ in points})
    best = (None, sum(1 for _, cheaper in points if cheaper))  # never cheaper
    for t in keys:
        wrong = sum(1 for k, cheaper in points if (k >= t) != cheaper)
        if wrong < best[1]:
            best = (t, wrong)
    return best


def crossover(rows):
    """Per configuration and alternative: frustum ms / alternative ms (> 1: the alternative is
    cheaper); per alternative the best single threshold by primary count and by footprint."""
    by_config = {}
    for r in rows:
        by_config.setdefault((r["preset"], r["primary_fraction"]), {})[r["strategy"]] = r
    table = []
    for (preset, fraction), group in by_config.items():
        frustum = group.get("frustum")
        if frustum is None:
            continue
        entry = {"preset": preset, "primary_fraction": fraction, "primary_cells": frustum["primary_cells"],
                 "primary_pixels": frustum["primary_pixels"], "frustum_ms": frustum["cut_surface_ms"]}
        for name in ALTERNATIVES + ("frustum-clusters",):
            if name in group:
                entry[name] = {"ms": group[name]["cut_surface_ms"],
                               "frustum_over_it": frustum["cut_surface_ms"] / group[name]["cut_surface_ms"],
                               "wrong_fraction": group[name]["quality"]["cut_vs_exact"]["wrong_fraction"]}
        table.append(entry)
    table.sort(key=lambda t: (t["primary_cells"], t["preset"]))
    thresholds = {}
    for name in ALTERNATIVES:
        for key in ("primary_cells", "primary_pixels"):
            points = [(t[key], t[name]["frustum_over_it"] > 1) for t in table if name in t]
            value, wrong = best_threshold(points)
            thresholds.setdefault(name, {})[key] = {"cheaper_from": value, "misclassified": wrong, "configurations": len(points)}
    return table, thresholds


def targets(rows, cpu, table):
    """Issue 16's three targets, measured in this run."""
    jfa = [{"preset": preset, "primary_fraction": fraction, "strategy": name, **times}
           for (preset, fraction, name), times in sorted(cpu.items())]
    sapphire = []
    for t in table:
        if t["preset"] == "sapphire" and t["primary_cells"] >= 1000:
            best = min((n for n in ALTERNATIVES if n in t), key=lambda n: t[n]["ms"])
            sapphire.append({"primary_cells": t["primary_cells"], "best": best, "best_ms": t[best]["ms"],
                             "frustum_ms": t["frustum_ms"], "faster": t[best]["ms"] < t["frustum_ms"]})
    clusters = [{"preset": t["preset"], "primary_cells": t["primary_cells"],
                 "frustum_over_clusters": t["frustum-clusters"]["frustum_over_it"]}
                for t in table if t["primary_fraction"] == 0.2 and "frustum-clusters" in t]
    summary = {}
    for name in CPU_REFERENCES:
        for key in ("transform_speedup", "stage_speedup"):
            ratios = [j[key] for j in jfa if j["strategy"] == name]
            if ratios:
                summary.setdefault(name, {})[key] = {"median": statistics.median(ratios), "min": min(ratios), "max": max(ratios),
                                                     "configurations": len(ratios)}
    return {"gpu_jfa_vs_cpu_path": {"target": "GPU JFA >= 3x faster than the CPU JFA it replaces (1080p): the transform, "
                                              "without the GPU seed pass both paths share",
                                    "rows": jfa, "cpu_over_gpu": summary,
                                    "met": bool(summary.get("jfa")) and summary["jfa"]["transform_speedup"]["min"] >= 3},
            "near_exact_beats_frustum_on_sapphire": {
                "target": "best exact-or-near-exact GPU strategy faster than frustum from 1,000 primaries on sapphire",
                "rows": sapphire, "met": bool(sapphire) and all(s["faster"] for s in sapphire)},
            "clusters_vs_frustum_at_20pct": {"target": "frustum-clusters >= 5x faster than frustum at 20% primaries",
                                             "rows": clusters, "met": bool(clusters) and all(c["frustum_over_clusters"] >= 5 for c in clusters)}}


def crossover_rows(table):
    """Per configuration: frustum ms against the matched-accuracy alternatives and the clusters."""
    rows = []
    for t in table:
        def cell(n, k):
            return (md.ms(t[n]["ms"]) if k == "ms" else f"{t[n]['frustum_over_it']:.2f}") if n in t else "-"
        wrong = f" ({100 * t['jfa2']['wrong_fraction']:.3f}%)" if "jfa2" in t else ""
        rows.append([t["preset"], f"{100 * t['primary_fraction']:g}%", f"{t['primary_cells']:,}", f"{t['primary_pixels']:,}",
                     md.ms(t["frustum_ms"]), cell("jfa2", "ms") + wrong, cell("jfa2", "r"), cell("frustum-sweep", "ms"),
                     cell("frustum-sweep", "r"), cell("frustum-clusters", "ms"), cell("frustum-clusters", "r")])
    return rows


def threshold_items(thresholds):
    items = []
    for name, by_key in thresholds.items():
        for key, unit in (("primary_cells", "primary cells"), ("primary_pixels", "footprint pixels")):
            th = by_key[key]
            where = f"from **{th['cheaper_from']:,} {unit}**" if th["cheaper_from"] is not None else "never"
            items.append(f"`{name}` vs `frustum` by {unit}: cheaper {where}; {th['misclassified']} of "
                         f"{th['configurations']} configurations misclassified.")
    return items


def target_items(targets_):
    """Issue 16's targets as measured, one line each."""
    items = []
    j = targets_["gpu_jfa_vs_cpu_path"]
    for name, s in j["cpu_over_gpu"].items():
        t, w = s["transform_speedup"], s["stage_speedup"]
        items.append(f"GPU `{name}` against the CPU path it replaced (BM_cpu_path, a second process: same inputs, "
                     f"interleaved, medians of {POSES * CPU_PATH_REPEAT} frames per configuration): the transform (CPU: "
                     "read-back, CPU loop, upload; GPU: the compute passes and the write into the cut depth) CPU/GPU "
                     f"median {t['median']:.2f}x, range {t['min']:.2f}-{t['max']:.2f}x; with the shared GPU seed pass on "
                     f"both sides {w['median']:.2f}x ({w['min']:.2f}-{w['max']:.2f}x), over {t['configurations']} configurations.")
    items.append(f"Target GPU JFA >= 3x the CPU JFA (the transform, every configuration): **{'met' if j['met'] else 'missed'}**.")
    s = targets_["near_exact_beats_frustum_on_sapphire"]
    items.append("Best near-exact GPU strategy faster than `frustum` from 1,000 primaries on sapphire: **"
                 + (("met" if s["met"] else "missed") if s["rows"] else "not measured in this run") + "**" + "".join(
                     f"; {r['primary_cells']:,} primaries: {r['best']} {md.ms(r['best_ms'])} ms vs frustum "
                     f"{md.ms(r['frustum_ms'])} ms" for r in s["rows"]) + ".")
    c = targets_["clusters_vs_frustum_at_20pct"]
    items.append("`frustum-clusters` >= 5x faster than `frustum` at 20%: **" + ("met" if c["met"] else "missed") + "** ("
                 + "; ".join(f"{r['preset']} {r['frustum_over_clusters']:.1f}x" for r in c["rows"]) + ").")
    return items


def strategy_rows(rows):
    frustum_ms = {(r["preset"], r["primary_fraction"]): r["cut_surface_ms"] for r in rows if r["strategy"] == "frustum"}
    return [[r["preset"], f"{100 * r['primary_fraction']:g}%", f"{r['primary_cells']:,}", r["strategy"], r["device"],
             md.ms(r["cut_surface_ms"]), f"{r['cut_surface_ms'] / frustum_ms[(r['preset'], r['primary_fraction'])]:.3f}",
             md.ms(r["total_ms"]), f"{100 * r['quality']['cut_vs_exact']['wrong_fraction']:.3f}",
             f"{r['quality']['primary_exposure']:.4f}", f"{r['quality']['context_kept']:.3f}"] for r in rows]


def report(exp, result):
    config, rows, targets_ = result["protocol"], result["rows"], result["targets"]
    size, qsize = config["size"], config["quality_size"]
    jfa = targets_["gpu_jfa_vs_cpu_path"]["cpu_over_gpu"].get("jfa", {}).get("transform_speedup")
    out = md.Report(
        "Cut-surface strategies: stage-1 time, error against the exact cone field, exposure, context",
        f"Every cut-surface strategy of the registry on {', '.join(config['presets'])} at primary fractions "
        f"{', '.join(f'{100 * f:g}%' for f in config['fractions'])} of PORO. Time: one `bench_cutaway` process at "
        f"{size[0]}x{size[1]}, aperture {APERTURE_DEG} degrees, mean filter and SSAO off, {POSES} poses (0/25 and 180/45 "
        f"degrees), {WARMUP} untimed pass, {REPEAT} timed frame per pose: `cut_surface` is the median fenced wall time of "
        "stage 1 (seed pass, transform or frustums, and the normal/position resolve every strategy shares). Quality: one "
        f"`cutaway render --exact-check` per configuration at {qsize[0]}x{qsize[1]} (the exact cone field is a CPU "
        "reference), pose 0/25, same aperture. Footprint = `primary_pixels`, the visible primary pixels of the timed "
        f"frames at {size[0]}x{size[1]} (median) in the `frustum` row. Strategies are compared by ratios within one "
        "configuration (same model, fraction and poses, in the same process).",
        headline=f"jfa in GL vs the CPU transform it replaced: {jfa['median']:.2f}x median" if jfa else None)
    out.section("Crossover at matched accuracy",
                "frustum / alternative time per configuration (> 1: the alternative is cheaper). `jfa2` is the near-exact "
                "cone-field transform, `frustum-sweep` the exact union of the frustums in O(pixels); the Chamfer masks are "
                "wrong on most pixels and left out. The frustum family's walls are square pyramids, not the cone field's "
                "circular cones: their cone-field error measures that shape, not a fault.")
    out.table(["preset", "fraction", "primaries", "footprint px", "frustum ms", "jfa2 ms (wrong %)", "frustum/jfa2",
               "frustum-sweep ms", "frustum/sweep", "clusters ms", "frustum/clusters"], crossover_rows(result["crossover"]["table"]))
    out.text("Best single threshold \"the alternative is cheaper iff primaries (or footprint) >= T\" over all "
             "configurations of all models; fewer misclassified configurations = the better predictor:")
    out.bullets(threshold_items(result["crossover"]["thresholds"]))
    out.section("Targets (issue 16)").bullets(target_items(targets_))
    out.section("Every strategy, every configuration",
                f"cut ms and total ms (frame without SSAO and mean filter) at {size[0]}x{size[1]} (medians); wrong % = pixels "
                f"beyond the tolerance of the exact cone field, exposure and context kept at {qsize[0]}x{qsize[1]}.")
    out.table(["preset", "fraction", "primaries", "strategy", "device", "cut ms", "cut / frustum", "total ms", "wrong %",
               "exposure", "context kept"], strategy_rows(rows), align="lrrllrrrrrr")
    out.text("readback_bytes per frame: 0 for every GPU strategy in every run (checked by the script).")
    out.text("Where each strategy runs and why (from the registry):")
    out.bullets([f"`{name}` ({row['device']}): {row['why']}" for name, row in {r["strategy"]: r for r in rows}.items()])
    out.text("Plots: stage-1 time of every strategy, one panel per model, a line joining the model's primary fractions; "
             "frustum / strategy per configuration against primaries and against the footprint (every strategy, a point "
             f"per model and fraction: > 1, cheaper than frustum; a configuration's points spread sideways by at most "
             f"{RATIO_DODGE_DECADES} decades so that none hides another); the cut error of every strategy against the exact cone "
             f"field at {qsize[0]}x{qsize[1]} (wrong pixels and mean absolute depth error, a point per model and fraction). "
             "One colour and marker per strategy in every plot (experiments/common/strategy_style.py).")
    return out.figure(*(exp.path(f) for f in FIGURES))


def plot(exp, result):
    """cut_strategies_time.png: stage-1 time of every strategy, one panel per model;
    cut_strategies_ratio.png: frustum / strategy per configuration against primaries and footprint;
    cut_strategies_error.png: each strategy's cut error against the exact cone field. Colours and
    markers: experiments/common/strategy_style.py."""
    plt, rows = cx.pyplot(), result["rows"]
    size, device = result["protocol"]["size"], cx.device_label(result["context"])
    setting = f"{size[0]}x{size[1]}, aperture {APERTURE_DEG} deg"
    fig = strategy_style.times_per_model(
        plt, [(r["preset"], r["strategy"], r["primary_cells"], r["cut_surface_ms"]) for r in rows],
        f"Stage 1 (cut surface) of every strategy, {setting}\n{device}", "stage 1 ms (median, log scale)")
    cx.save_figure(fig, exp.path("cut_strategies_time.png"))
    plt.close(fig)
    plot_ratio(plt, rows, f"frustum / strategy, stage 1, {setting}\n{device}", exp.path("cut_strategies_ratio.png"))
    plot_error(plt, rows, result["protocol"], exp.path("cut_strategies_error.png"))


def plot_ratio(plt, rows, title, path):
    """frustum ms / strategy ms of every strategy but frustum, against primary cells and against the
    footprint, every configuration of every model a point (no lines: the points of one strategy come
    from four models). A configuration's points are spread sideways, at most RATIO_DODGE_DECADES
    either way, so that equal ratios do not hide one another."""
    frustum = {(r["preset"], r["primary_fraction"]): r for r in rows if r["strategy"] == "frustum"}
    fig, axes = plt.subplots(1, 2, figsize=(cx.PLOT_WIDTH_IN, 4.4), sharey=True)
    names = strategy_style.ordered(r["strategy"] for r in rows if r["strategy"] != "frustum")
    for ax, (key, label) in zip(axes, (("primary_cells", "primary cells"),
                                           ("primary_pixels", "footprint: primary pixels on screen"))):
        for i, name in enumerate(names):
            dodge = 10 ** (RATIO_DODGE_DECADES * (2 * i / (len(names) - 1) - 1))
            points = [(frustum[(r["preset"], r["primary_fraction"])][key] * dodge,
                       frustum[(r["preset"], r["primary_fraction"])]["cut_surface_ms"] / r["cut_surface_ms"])
                      for r in rows if r["strategy"] == name]
            ax.plot(*zip(*points), linestyle="none", markersize=4.5, alpha=0.9, **strategy_style.style(name))
        ax.axhline(1.0, color="black", linewidth=0.8)
        ax.set(xscale="log", yscale="log", xlabel=label + " (log scale)")
        ax.grid(True, which="both", linewidth=0.3)
    axes[0].set_ylabel("frustum ms / strategy ms (> 1: cheaper)")
    fig.suptitle(title)
    fig.legend(handles=strategy_style.handles(plt, names, linestyle="none"), ncol=4, loc="lower center", frameon=False)
    cx.save_figure(fig, path)
    plt.close(fig)


def plot_error(plt, rows, protocol, path):
    """Per strategy, every configuration a point: the share of pixels whose cut depth is wrong beyond
    the tolerance, and the mean absolute depth error, both against the exact cone field."""
    import matplotlib.ticker  # after cx.pyplot(), which finds matplotlib
    fig, axes = plt.subplots(1, 2, figsize=(cx.PLOT_WIDTH_IN, 4.2), sharey=True)
    names = strategy_style.ordered(r["strategy"] for r in rows)
    configurations = sorted({(r["preset"], r["primary_fraction"]) for r in rows})
    for y, name in enumerate(names):
        errors = [r["quality"]["cut_vs_exact"] for r in rows if r["strategy"] == name]
        # Spread a strategy's configurations over its row so that equal values stay countable.
        spread = [y + 0.5 * (i / max(1, len(configurations) - 1) - 0.5) for i in range(len(errors))]
        axes[0].plot([100 * e["wrong_fraction"] for e in errors], spread, linestyle="none", markersize=4,
                     **strategy_style.style(name))
        axes[1].plot([e["mean_abs_error"] for e in errors], spread, linestyle="none", markersize=4,
                     **strategy_style.style(name))
    tolerance = rows[0]["quality"]["cut_vs_exact"]["relative_tolerance"]
    # Wrong shares run from none through a few pixels in 230,400 (jump flooding) to nearly all: a
    # log axis from WRONG_PERCENT_LINEAR_BELOW up, linear (with 0) below it.
    axes[0].set_xscale("symlog", linthresh=WRONG_PERCENT_LINEAR_BELOW, linscale=0.5)
    axes[0].set_xticks([0] + [10.0 ** k for k in range(-3, 3)])  # none at the threshold: it would touch 0's label
    axes[0].xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(cx.plain_number))
    axes[0].set(xlabel=f"pixels wrong by more than {100 * tolerance:g}%\nof the depth range (%, log scale above "
                       f"{WRONG_PERCENT_LINEAR_BELOW:g})", xlim=(-WRONG_PERCENT_LINEAR_BELOW / 2, 150))
    axes[1].set(xscale="log", xlabel="mean absolute depth error\n(render units, log scale)")
    axes[0].set_yticks(range(len(names)), [strategy_style.LABELS.get(n, n) for n in names])
    axes[0].invert_yaxis()
    for ax in axes:
        ax.grid(True, which="both", axis="x", linewidth=0.3)
        ax.grid(False, axis="y")
    w, h = protocol["quality_size"]
    az, el, _ = protocol["quality_camera_az_el_dist"]
    fig.suptitle(f"Cut error against the exact cone field ({w}x{h}, pose {az}/{el}, aperture {APERTURE_DEG} deg),\n"
                 f"one point per model and primary fraction ({len(configurations)} per strategy); the frustum strategies\n"
                 f"cut the paper's frustum union, another surface than the cone field: their error is that difference;\n"
                 f"exact's own error is the depth buffer's quantisation, the floor of this measurement")
    cx.save_figure(fig, path)
    plt.close(fig)


def measure(exp):
    """The timing sweep, the CPU paths, one quality render per configuration; returns the document."""
    config = configuration(exp.quick)
    document, timed, cpu, strategies = time_sweep(exp, config)
    rows = []
    for preset in config["presets"]:
        for fraction in config["fractions"]:
            for strategy in strategies:
                stats = quality(exp, config, preset, fraction, strategy)
                row = merge_row(preset, fraction, strategy, timed[(preset, fraction, strategy)], stats)
                rows.append(row)
                q = row["quality"]
                print(f"{preset} {fraction} {strategy:16s} {row['primary_cells']:7d} primaries: cut {row['cut_surface_ms']:9.1f} ms, "
                      f"wrong {100 * q['cut_vs_exact']['wrong_fraction']:.3f}%, exposure {q['primary_exposure']:.4f}, "
                      f"context {q['context_kept']:.3f}", flush=True)
    table, thresholds = crossover(rows)
    bench_context = cx.benchmark_context(document)
    context = {**exp.context(), **bench_context}
    result = {"experiment": "cut_strategies", "quick": exp.quick,
              "command": "experiments/cut_strategies/run.py" + (" --quick" if exp.quick else "") + " --force",
              "protocol": {**config, "aperture_deg": APERTURE_DEG, "poses": POSES, "warmup_passes": WARMUP,
                           "timed_frames_per_pose": REPEAT, "cpu_path_frames_per_pose": CPU_PATH_REPEAT, "mean_filter": 0, "quality_camera_az_el_dist": FIRST_POSE,
                           "statistic": "median over the timed frames (poses x repeat)",
                           "time": "fenced wall time of the cut_surface stage, ms (bench_cutaway)",
                           "cut_error": "cut_vs_exact of cutaway render --exact-check at quality_size",
                           "alternatives_at_matched_accuracy": list(ALTERNATIVES)},
              "context": context, "rows": rows,
              "cpu_path": [{"preset": p, "primary_fraction": f, "strategy": s, **times} for (p, f, s), times in cpu.items()],
              "crossover": {"table": table, "thresholds": thresholds}}
    result["targets"] = targets(rows, cpu, table)
    return result


def main():
    cx.Experiment(__doc__, "results.json", list(FIGURES)).run(measure, report, plot)


if __name__ == "__main__":
    main()
