"""One colour and one marker per cut-surface strategy, the same in every plot (issue 46: a reader
compares results/cut_strategies with the device reports and experiments/scale by colour).

Every strategy of the registry (src/cutaway/cut_surface/cut_surface_registry.cpp) and "auto"
(cut_strategy_choice.h) has an entry; a name without one stops the plot (add it here, with a
colour and a marker no other entry uses). Plots that show several models never mark the model
with a marker: they give each model its own panel, so a marker always means a strategy.
"""
import cutaway_experiment as cx

# name: (colour, marker), in the registry's order. Families share a hue range (frustum: blues and
# green, Chamfer masks: olive/brown/orange, jump flooding: reds and purples); the markers tell
# neighbours apart in print and for readers who do not see the colours.
STYLES = {
    "frustum": ("#1f77b4", "s"),
    "frustum-clusters": ("#17becf", "D"),
    "frustum-sweep": ("#2ca02c", "^"),
    "chamfer-3x3": ("#bcbd22", "v"),
    "chamfer-34": ("#8c564b", "<"),
    "chamfer-5x5": ("#ff7f0e", ">"),
    "jfa": ("#d62728", "o"),
    "jfa+1": ("#e377c2", "p"),
    "jfa+2": ("#9467bd", "h"),
    "1+jfa": ("#5254a3", "d"),
    "jfa2": ("#7b2d5b", "X"),
    "exact": ("#000000", "*"),
    "auto": ("#7f7f7f", "P"),
}
assert len({c for c, _ in STYLES.values()}) == len(STYLES) and len({m for _, m in STYLES.values()}) == len(STYLES)
# Legend labels where the name alone would mislead: "exact" runs on the CPU in every plot.
LABELS = {"exact": "exact (CPU reference)"}
# times_per_model spreads the strategies' points of one configuration sideways by at most this much
# either way (log10 units of the primary cells), so that equal times do not hide one another.
TIME_DODGE_DECADES = 0.12


def style(name):
    """matplotlib keyword arguments (color, marker) of strategy `name`."""
    if name not in STYLES:
        raise SystemExit(f"strategy_style: no colour and marker for cut strategy '{name}': add it to STYLES in "
                         "experiments/common/strategy_style.py")
    colour, marker = STYLES[name]
    return {"color": colour, "marker": marker}


def ordered(names):
    """`names` (any iterable, repeats allowed) once each, in the registry's order."""
    present = set(names)
    return [n for n in STYLES if n in present] + sorted(present - set(STYLES))


def handles(plt, names, **extra):
    """Legend handles: one line with its marker per strategy, in the registry's order."""
    return [plt.Line2D([], [], label=LABELS.get(n, n), **style(n), **extra) for n in ordered(names)]


def times_per_model(plt, points, title, ylabel):
    """Stage times of every strategy, one panel per model (2 columns): `points` is a list of
    (model, strategy, primary cells, ms); a line joins one model's primary fractions. Log axes, the
    same ms range in every panel; one legend below the panels. A strategy's points sit at most
    TIME_DODGE_DECADES beside their primary cells (said in the x label), so that strategies with
    equal times stay visible side by side. Returns the figure."""
    models = list(dict.fromkeys(p[0] for p in points))
    names = ordered(p[1] for p in points)
    columns = min(2, len(models))
    rows = -(-len(models) // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(cx.PLOT_WIDTH_IN, 1.2 + 2.6 * rows), sharey=True, squeeze=False)
    for ax, model in zip(axes.flat, models):
        mine = [p for p in points if p[0] == model]
        for name in ordered(p[1] for p in mine):
            dodge = 10 ** (TIME_DODGE_DECADES * (2 * names.index(name) / max(1, len(names) - 1) - 1))
            xy = sorted((cells * dodge, ms) for _, strategy, cells, ms in mine if strategy == name)
            ax.plot(*zip(*xy), "-", linewidth=1, markersize=5, **style(name))
        ax.set(xscale="log", yscale="log", title=model)
        ax.grid(True, which="both", linewidth=0.3)
    for ax in axes.flat[len(models):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel(f"primary cells (log scale; strategies\nspread sideways by at most {TIME_DODGE_DECADES:g} decades)")
    for ax in axes[:, 0]:
        ax.set_ylabel(ylabel)
    fig.suptitle(title)
    fig.legend(handles=handles(plt, (p[1] for p in points), linewidth=1), ncol=4, loc="lower center", frameon=False)
    return fig
