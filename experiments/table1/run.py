#!/usr/bin/python3
"""Table 1 of the paper: per-stage frame times of the four models over the camera path.

Interface (for experiments/run_all):
  experiments/table1/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/table1/table1.json (our ms per stage and model for the paper's path, --draw all-faces,
and for the output-sensitive renderer, --draw visible; the paper's; shares; the observations decided
from the paper's path; machine context) and results/table1/README.md. Skips when both exist unless
--force. --quick: 480x270 pixels, 2 poses, 1 frame per pose (results/quick/table1/).

Protocol (SPEC.md section 3): 1920x1080, 9x9 mean filter, the top 1% of PORO as primaries, line
width 1 px, SSAO on, frustum-union cut (the paper's), ray-cast borders; bench_cutaway renders each
model over its 8-pose camera path (azimuth steps of 45 degrees, full aperture 30..120 degrees) after one
untimed pass, 5 timed frames per pose; times are fenced wall clock (glFinish) medians over the frames.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import table1_report  # noqa: E402

PAPER_MS = {  # SPEC.md section 3 (GeForce GTX 660, 1920x1080)
    "zaphirus": {"cells": 7500, "cut_surface": 1.13, "secondary": 6.5, "primary": 0.15, "ssao": 4.8, "mean_filter": 3.0, "total": 15.8},
    "petra": {"cells": 32760, "cut_surface": 1.9, "secondary": 11.1, "primary": 0.38, "ssao": 5.2, "mean_filter": 4.6, "total": 23.2},
    "opharine": {"cells": 76000, "cut_surface": 2.0, "secondary": 26, "primary": 0.7, "ssao": 4.6, "mean_filter": 4.7, "total": 38},
    "sapphire": {"cells": 208320, "cut_surface": 2.35, "secondary": 39.7, "primary": 1.78, "ssao": 5.33, "mean_filter": 4.6, "total": 53.9},
}


def measure(exp):
    """Both draw modes of the four models over the camera path, in one bench_cutaway process."""
    size = "480x270" if exp.quick else "1920x1080"
    poses = 2 if exp.quick else 8
    repeat = 1 if exp.quick else 5
    document = exp.benchmark("--presets=" + ",".join(cx.PRESETS), "--size=" + size, "--poses=" + str(poses),
                             "--fractions=0.01", "--mean_filters=9", "--borders=raycast", "--strategies=frustum",
                             "--draws=all-faces,visible", "--warmup=1", "--repeat=" + str(repeat),
                             "--benchmark_filter=BM_cutaway")
    runs = cx.cutaway_runs(document)
    tables = {}
    for draw in ("all-faces", "visible"):
        ours = {row["preset"]: row for row in runs if row["draw"] == draw}
        missing = [p for p in cx.PRESETS if p not in ours]
        if missing:
            raise SystemExit(f"bench_cutaway gave no {draw} result for {missing}")
        tables[draw] = table1_report.build_table(ours, PAPER_MS)
    return {
        "experiment": "table1", "quick": exp.quick,
        "protocol": {"size": size, "poses": poses, "frames_per_pose": repeat, "mean_filter": 9, "primary_fraction": 0.01,
                     "line_width_px": 1, "ssao": True, "strategy": "frustum", "border": "raycast",
                     "draws": {"all-faces": "the paper's path: every face of every secondary cell",
                               "visible": "output-sensitive: GPU culling against the frustum and the cut (SPEC.md section 6)"},
                     "statistic": "median over the timed frames (poses x frames per pose)",
                     "time": "fenced wall clock per stage (glFinish before and after), ms"},
        "context": {**exp.context(), **cx.benchmark_context(document)},
        "models": tables["all-faces"], "models_visible": tables["visible"],
        "observations": table1_report.observations(tables["all-faces"])}


def report(exp, document):
    """Ours beside the paper per stage and model, the paper's observations, then the output-sensitive renderer."""
    proto, table, visible = document["protocol"], document["models"], document["models_visible"]
    largest = max(table, key=lambda p: table[p]["cells"])
    frame = {draw: t[largest]["stages"]["total"]["ours_ms"] for draw, t in (("all-faces", table), ("visible", visible))}
    result = md.Report(
        "Table 1: stage times of the four models, ours against the paper's",
        f"Per-stage frame times of the cutaway renderer on the four synthetic models over an {proto['poses']}-pose camera "
        f"path at {proto['size']} ({proto['mean_filter']}x{proto['mean_filter']} mean filter, the top "
        f"{100 * proto['primary_fraction']:g}% of PORO as primaries, {proto['line_width_px']} px lines, SSAO on, "
        f"{proto['strategy']} cut, {proto['border']} borders; one untimed pass, then {proto['frames_per_pose']} timed "
        f"frames per pose), beside the paper's Table 1 (GeForce GTX 660, 1920x1080). Each number is the "
        f"{proto['statistic']} of the {proto['time']}. Two draw modes in the same run: the paper's path (every face of "
        "every secondary cell) and the output-sensitive renderer (GPU culling against the frustum and the cut).",
        headline=f"{largest} frame {md.ms(frame['all-faces'])} ms (paper's path), {md.ms(frame['visible'])} ms (visible faces)")
    header, rows = table1_report.stage_rows(table)
    result.section("The paper's path (--draw all-faces) against the paper",
                   "Each cell: our ms / paper ms (our share of the total / the paper's share). The paper's total has no "
                   "composite (post) stage; ours includes it.")
    result.table(header, rows)
    result.section("The paper's observations here").bullets(table1_report.observation_items(document["observations"]))
    header, rows = table1_report.visible_rows(visible, table)
    result.section("Output-sensitive renderer (--draw visible) against the paper's path (--draw all-faces)",
                   "Each cell: visible ms / all-faces ms, same run. Faces: stage 2 faces drawn at the last pose. "
                   "Speed-up: all-faces total over visible total.")
    return result.table(header, rows)


def main():
    cx.Experiment(__doc__, "table1.json").run(measure, report)


if __name__ == "__main__":
    main()
