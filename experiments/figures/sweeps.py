"""Frame time against one parameter (aperture angle, primary fraction), for each cut strategy asked
for: stats per value, and a plot with one panel per strategy."""
import itertools

import cutaway_experiment as cx
import stage_style


def sweep(exp, model, size, flag_values, base_options, repeat, rounds, strategies):
    """Renders `model` once per (label, options) in `flag_values` and per strategy of `strategies`
    in each of `rounds` rounds (values and strategies interleaved, so a machine whose speed drifts
    slows every point alike: one pass gave the same setting 184 ms in one sweep and 130 ms in the
    other). Returns per strategy its rows (label, each stage's median over the rounds, the rounds'
    totals, the strategy the renderer drew with: "auto" names the one it picked) and the last
    render's stats."""
    points = list(itertools.product(strategies, flag_values))
    runs = [[] for _ in points]
    for _ in range(rounds):
        for k, (strategy, (_, options)) in enumerate(points):
            stats = exp.render(model, *base_options, *options, "--strategy", strategy, "--size", *size,
                               "--warmup", 1, "--repeat", repeat)
            runs[k].append(stats)
    by_strategy = {strategy: [] for strategy in strategies}
    for (strategy, (value, _)), value_runs in zip(points, runs):
        stages = stage_style.median_stages([r["stages_ms"] for r in value_runs])
        by_strategy[strategy].append({"value": value, "stages_ms": stages, "primary_cells": value_runs[0]["primary_cells"],
                                      "strategy": value_runs[0]["strategy"]["name"],
                                      "total_ms_by_round": [r["stages_ms"]["total"] for r in value_runs]})
    return [{"requested": s, "rows": rows} for s, rows in by_strategy.items()], stats


def strategy_names(rows, format_value, separator=", "):
    """What a panel's renderer drew with: one name, or each name with the values it drew."""
    groups = [(name, [r["value"] for r in group]) for name, group in itertools.groupby(rows, key=lambda r: r["strategy"])]
    if len(groups) == 1:
        return groups[0][0]
    return separator.join(f"{name} at {format_value(values[0])}" +
                     (f"-{format_value(values[-1])}" if len(values) > 1 else "") for name, values in groups)


def plot_sweep(sweep, xlabel, title, path, format_value, log_x=False, log_y=False):
    """Per strategy of the sweep ({"strategies": [{"requested", "rows": [{"value", "stages_ms",
    "strategy", "total_ms_by_round"}]}]}) a panel: one line per stage, the total in bold black with
    bars from the fastest to the slowest round; the panel names the strategy the renderer drew with.
    The panels share their time axis (apart, 0-250 ms beside 0-900 ms read as alike); log_y where
    one panel's total spans a decade more than the other's, whose stages would be squeezed flat on a
    linear axis. The legend below the axes, clear of the curves."""
    plt = cx.pyplot()
    panels = sweep["strategies"]
    fig, axes = plt.subplots(1, len(panels), figsize=(cx.PLOT_WIDTH_IN, 4.8), sharey=True, squeeze=False)
    for ax, panel in zip(axes[0], panels):
        rows = panel["rows"]
        x = [r["value"] for r in rows]
        stage_style.plot_stages(ax, x, [r["stages_ms"] for r in rows], [r["total_ms_by_round"] for r in rows])
        if log_x:
            ax.set_xscale("log")
        if log_y:
            ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        drawn = strategy_names(rows, format_value, ",\n")  # a line per strategy: the title stays within its axes
        ax.set_title(f"{panel['requested']}" + (f"\n(drew {drawn})" if drawn != panel["requested"] else " (the paper's)"
                                                 if panel["requested"] == "frustum" else ""), fontsize="medium")
    if not log_y:
        axes[0][0].set_ylim(bottom=0)  # after every panel's curves: the shared top fits them all
    axes[0][0].set_ylabel(f"time per frame (ms{', log scale' if log_y else ''}, {stage_style.rounds_note(sweep['rounds'])})")
    fig.suptitle(title)
    fig.legend(*axes[0][0].get_legend_handles_labels(), ncol=3, loc="lower center", frameon=False)
    cx.save_figure(fig, path)
    plt.close(fig)
