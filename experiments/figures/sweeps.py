"""Frame time against one parameter (aperture angle, primary fraction): stats per value, and a plot."""
import statistics

import cutaway_experiment as cx


def sweep(exp, model, size, flag_values, base_options, repeat, rounds=1):
    """Renders `model` once per (label, options) in `flag_values` in each of `rounds` rounds (the
    values interleaved, so a machine whose speed drifts slows every value alike: one pass gave the
    same setting 184 ms in one sweep and 130 ms in the other); returns rows of label + each stage's
    median over the rounds, and the last render's stats."""
    runs = [[] for _ in flag_values]
    for _ in range(rounds):
        for k, (value, options) in enumerate(flag_values):
            stats = exp.render(model, *base_options, *options, "--size", *size, "--warmup", 1, "--repeat", repeat)
            runs[k].append(stats)
    rows = []
    for (value, _), value_runs in zip(flag_values, runs):
        stages = {s: statistics.median(r["stages_ms"][s] for r in value_runs) for s in value_runs[0]["stages_ms"]}
        rows.append({"value": value, "stages_ms": stages, "primary_cells": value_runs[0]["primary_cells"],
                     "total_ms_by_round": [r["stages_ms"]["total"] for r in value_runs]})
    return rows, stats


def plot_sweep(sweep, xlabel, title, path, log_x=False):
    """One line per stage (total in bold black) of a sweep as the document holds it ({"rows": [{"value",
    "stages_ms"}]}), the legend below the axes, clear of the curves."""
    plt = cx.pyplot()
    fig, ax = plt.subplots(figsize=(cx.PLOT_WIDTH_IN, 4.6))
    cx.plot_stages(ax, [r["value"] for r in sweep["rows"]], [r["stages_ms"] for r in sweep["rows"]])
    if log_x:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("time per frame (ms, median)")
    ax.set_ylim(bottom=0)
    fig.suptitle(title)
    fig.legend(*ax.get_legend_handles_labels(), ncol=3, loc="lower center", frameon=False)
    cx.save_figure(fig, path)
    plt.close(fig)
