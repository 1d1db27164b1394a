"""Frame time against one parameter (aperture angle, primary fraction): stats per value, and a plot."""
import cutaway_experiment as cx


def sweep(exp, model, size, flag_values, base_options, repeat):
    """Renders `model` once per (label, options) in `flag_values`; returns rows of label + stage ms."""
    rows = []
    for value, options in flag_values:
        stats = exp.render(model, *base_options, *options, "--size", *size, "--warmup", 1, "--repeat", repeat)
        rows.append({"value": value, "stages_ms": stats["stages_ms"], "primary_cells": stats["primary_cells"]})
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
