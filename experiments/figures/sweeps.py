"""Frame time against one parameter (aperture angle, primary fraction): stats per value, and a plot."""
import cutaway_experiment as cx


def sweep(exp, model, size, flag_values, base_options, repeat):
    """Renders `model` once per (label, options) in `flag_values`; returns rows of label + stage ms."""
    rows = []
    for value, options in flag_values:
        stats = exp.render(model, *base_options, *options, "--size", *size, "--warmup", 1, "--repeat", repeat)
        rows.append({"value": value, "stages_ms": stats["stages_ms"], "primary_cells": stats["primary_cells"]})
    return rows, stats


def plot_sweep(exp, rows, xlabel, title, path, log_x=False):
    """One line per stage (total in bold black), the legend below the axes, clear of the curves."""
    plt = cx.pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.6))
    x = [r["value"] for r in rows]
    for stage in cx.STAGES + ("total",):
        style = {"color": "black", "linewidth": 2.2} if stage == "total" else {}
        ax.plot(x, [r["stages_ms"][stage] for r in rows], marker="o", label=cx.STAGE_LABELS[stage], **style)
    if log_x:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("time per frame (ms, median)")
    ax.set_ylim(bottom=0)
    ax.set_title(title)
    fig.legend(*ax.get_legend_handles_labels(), ncol=4, loc="lower center", frameon=False)
    fig.tight_layout(rect=(0, 0.13, 1, 1))
    fig.savefig(path)
    fig.savefig(path[:-4] + ".pdf")
    print("wrote", path)
