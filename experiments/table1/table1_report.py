"""Table 1's numbers side by side (ours vs the paper) and the paper's observations decided from them."""
import cutaway_experiment as cx
import report_markdown as md

TABLE_STAGES = ("cut_surface", "secondary", "primary", "ssao", "mean_filter")
# "Nearly constant across models": largest over smallest at most this (screen-space stages).
CONSTANT_RATIO = 1.5


def build_table(ours, paper):
    """Per model: cells, ours/paper ms per stage and each stage's share of its own total."""
    table = {}
    for preset, row in ours.items():
        our_ms = row["stages_ms"]
        entry = {"cells": row["cells"], "paper_cells": paper[preset]["cells"], "primary_cells": row["primary_cells"],
                 "baseline_ms": row.get("baseline"), "total_over_baseline": row.get("total_over_baseline"),
                 "faces_secondary": row.get("faces_secondary"), "faces_baseline": row.get("faces_baseline"),
                 "gl_query_valid": bool(row.get("gl_query_valid")), "stages": {}}
        for stage in cx.STAGES + ("total",):
            paper_ms = paper[preset].get(stage)
            entry["stages"][stage] = {
                "ours_ms": our_ms[stage], "ours_share": our_ms[stage] / our_ms["total"],
                "paper_ms": paper_ms, "paper_share": paper_ms / paper[preset]["total"] if paper_ms is not None else None}
        table[preset] = entry
    return table


def _ratio(values):
    return max(values) / min(values) if min(values) > 0 else float("inf")


def observations(table):
    """Each of the paper's observations, with the numbers that decide it here."""
    models = sorted(table, key=lambda p: table[p]["cells"])
    ms = {s: [table[p]["stages"][s]["ours_ms"] for p in models] for s in TABLE_STAGES}
    dominant = [max(TABLE_STAGES, key=lambda s: table[p]["stages"][s]["ours_ms"]) for p in models]
    growth = {s: ms[s][-1] / ms[s][0] for s in ("cut_surface", "secondary")}
    result = [
        {"claim": "stage 2 (secondaries) is the largest stage for every model",
         "holds": all(d == "secondary" for d in dominant), "evidence": dict(zip(models, dominant))},
        {"claim": "stage 2 grows with model size (monotonic in cell count)",
         "holds": all(a < b for a, b in zip(ms["secondary"], ms["secondary"][1:])),
         "evidence": dict(zip(models, ms["secondary"]))},
        {"claim": "stage 1 grows more slowly than stage 2 (largest / smallest model)",
         "holds": growth["cut_surface"] < growth["secondary"], "evidence": growth},
    ]
    for stage in ("ssao", "mean_filter"):
        result.append({"claim": f"{stage} is nearly constant across models (max/min <= {CONSTANT_RATIO})",
                       "holds": _ratio(ms[stage]) <= CONSTANT_RATIO,
                       "evidence": {"max_over_min": _ratio(ms[stage]), **dict(zip(models, ms[stage]))}})
    return result


def stage_rows(table):
    """Per stage: 'our ms / paper ms (our share / paper share)' per model, models by cell count."""
    models = sorted(table, key=lambda p: table[p]["cells"])
    rows = []
    for stage in cx.STAGES + ("total",):
        cells = []
        for p in models:
            s = table[p]["stages"][stage]
            paper = "-" if s["paper_ms"] is None else f"{s['paper_ms']:g}"
            paper_share = "-" if s["paper_share"] is None else f"{100 * s['paper_share']:.0f}%"
            cells.append(f"{s['ours_ms']:.1f} / {paper} ({100 * s['ours_share']:.0f}% / {paper_share})")
        rows.append([cx.STAGE_LABELS[stage], *cells])
    rows.append(["baseline (plain shaded frame)", *(f"{table[p]['baseline_ms']:.1f} / -" for p in models)])
    return ["stage", *(f"{p} ({int(table[p]['cells']):,} cells)" for p in models)], rows


def observation_items(observations_):
    """One line per observation: whether it holds here and the numbers that decide it."""
    items = []
    for o in observations_:
        evidence = ", ".join(f"{k}: {v:.3g}" if isinstance(v, float) else f"{k}: {v}" for k, v in o["evidence"].items())
        items.append(f"{'holds' if o['holds'] else 'does NOT hold'}: {o['claim']} ({evidence})")
    return items


def visible_rows(visible, paper_path):
    """The output-sensitive renderer beside the paper's path: 'visible / all-faces' ms per stage,
    faces drawn and the total's speed-up (all-faces over visible)."""
    models = sorted(visible, key=lambda p: visible[p]["cells"])
    rows = [[cx.STAGE_LABELS[stage], *(f"{visible[p]['stages'][stage]['ours_ms']:.1f} / "
                                       f"{paper_path[p]['stages'][stage]['ours_ms']:.1f}" for p in models)]
            for stage in cx.STAGES + ("total",)]
    rows.append(["baseline (plain frame)", *(f"{visible[p]['baseline_ms']:.1f} / {paper_path[p]['baseline_ms']:.1f}"
                                             for p in models)])
    for key, label in (("faces_secondary", "stage 2 faces"), ("faces_baseline", "plain-frame faces")):
        rows.append([label, *(f"{int(visible[p][key] or 0):,} / {int(paper_path[p][key] or 0):,}" for p in models)])
    rows.append(["total speed-up", *(f"{paper_path[p]['stages']['total']['ours_ms'] / visible[p]['stages']['total']['ours_ms']:.2f}x"
                                     for p in models)])
    return ["stage", *models], rows


def markdown(table, observations_, context, size, poses):
    """The paper's path beside the paper's Table 1 as one markdown section (experiments/device/report.py)."""
    header, rows = stage_rows(table)
    lines = [f"# Table 1: stage times, ours on the paper's path (--draw all-faces; {context.get('gl_renderer')}, "
             f"LP_NUM_THREADS={context.get('LP_NUM_THREADS')}, {context.get('cpu_model', 'unknown CPU')}, {size}, {poses}-pose path, "
             f"medians) vs the paper (GTX 660, 1920x1080)", "",
             "Each cell: our ms / paper ms (our share of total / paper share). Generated by experiments/table1/run.py; "
             "git " + str(context.get("git_revision")) + ".", "", *md.table(header, rows),
             "", "The paper's total has no composite (post) stage; ours includes it.", "", "## The paper's observations here", ""]
    lines += [f"- {item}" for item in observation_items(observations_)]
    return "\n".join(lines) + "\n"


def visible_markdown(visible, paper_path):
    """The output-sensitive renderer beside the paper's path as one markdown section."""
    header, rows = visible_rows(visible, paper_path)
    lines = ["", "## Output-sensitive renderer (--draw visible) vs the paper's path (--draw all-faces), same run", "",
             "Each cell: visible ms / all-faces ms. Faces: stage 2 faces drawn at the last pose.", "", *md.table(header, rows)]
    return "\n".join(lines) + "\n"
