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
    plt = cx.pyplot()
    fig, ax = plt.subplots()
    x = [r["value"] for r in rows]
    for stage in cx.STAGES + ("total",):
        ax.plot(x, [r["stages_ms"][stage] for r in rows], marker="o", label=cx.STAGE_LABELS[stage])
    if log_x:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("time per frame (ms, median)")
    ax.set_title(title)
    ax.legend(ncol=2)
    cx.save_figure(fig, path)
