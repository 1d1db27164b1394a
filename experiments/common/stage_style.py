"""One colour per cutaway stage, the same in every stage plot, and none a cut strategy's (a referee
read blue as "frustum" in one plot and "stage 1" in another, when both came from tab10): a colour
means a strategy (strategy_style.py) or a stage, never both. The total is black, drawn bold.

Also the plotting of stage times measured in rounds (the median per point, bars from the fastest
to the slowest round's total), shared by experiments/figures' sweeps, stage_over_path and scale.
"""
import math
import statistics

import cutaway_experiment as cx
import strategy_style

# stage (cx.STAGES): colour, in the pipeline's order. Hand-picked (mostly matplotlib's Dark2) to
# stay far from every strategy colour: tab10 and its neighbours are all taken there.
COLOURS = {"cut_surface": "#1b9e77", "culling": "#e6ab02", "secondary": "#e7298a", "primary": "#9400d3",
           "ssao": "#637939", "mean_filter": "#fa8072", "post": "#a6761d", "total": "#000000"}
TOTAL_LINEWIDTH = 2.2


def _lab(colour):
    """CIELAB (D65) of a '#rrggbb' colour."""
    rgb = [int(colour[k:k + 2], 16) / 255 for k in (1, 3, 5)]
    r, g, b = (((c + 0.055) / 1.055) ** 2.4 if c > 0.04045 else c / 12.92 for c in rgb)
    xyz = ((0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047, 0.2126 * r + 0.7152 * g + 0.0722 * b,
           (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883)
    fx, fy, fz = (t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116 for t in xyz)
    return 116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)


# Told apart at a glance (CIELAB distance, 2.3 = just noticeable): from each other and from every
# strategy's colour (Set1's blue, 4 from frustum's, would pass a test of equal strings).
MIN_DISTANCE = 25
assert set(COLOURS) == set(cx.STAGES) | {"total"}
_STAGE_COLOURS = [c for s, c in COLOURS.items() if s != "total"]
assert all(math.dist(_lab(a), _lab(b)) >= MIN_DISTANCE for a in _STAGE_COLOURS
           for b in [c for c, _ in strategy_style.STYLES.values()] + [c for c in COLOURS.values() if c != a])


def style(stage):
    """matplotlib keyword arguments (color, linewidth for the total) of `stage` (cx.STAGES or "total")."""
    return {"color": COLOURS[stage], **({"linewidth": TOTAL_LINEWIDTH} if stage == "total" else {})}


def median_stages(runs):
    """Each stage's median over `runs`, a list of {stage: ms} (one per round), the first's stages."""
    return {s: statistics.median(r[s] for r in runs) for s in runs[0]}


def rounds_note(rounds, separator="\n"):
    """What a point and a bar of plot_stages are, for stage times measured in `rounds` rounds."""
    return "one timed frame" if rounds <= 1 else f"median of {rounds} rounds;{separator}bars: the total's fastest to slowest round"


def plot_stages(ax, x, stages_ms, totals_by_round=None):
    """One line per stage (cx.STAGES order, COLOURS; total in bold black) of the per-x dicts
    `stages_ms` ({stage: ms}); stages missing from the first (a run from before the stage was
    timed) are left out. `totals_by_round`: per x the total of every round, drawn as a bar from
    the fastest to the slowest about the total (none where one round)."""
    for stage in cx.STAGES + ("total",):
        if stage in stages_ms[0]:
            ax.plot(x, [s[stage] for s in stages_ms], marker="o", markersize=3.5, label=cx.STAGE_LABELS[stage], **style(stage))
    if totals_by_round and max(len(t) for t in totals_by_round) > 1:
        totals = [s["total"] for s in stages_ms]
        ax.errorbar(x, totals, yerr=cx.min_max_bars(totals, totals_by_round), fmt="none", ecolor=COLOURS["total"], capsize=3,
                    linewidth=1)
