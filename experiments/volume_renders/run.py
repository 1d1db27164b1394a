#!/usr/bin/env python3
"""Renders of the real F3 crop and the synthetic cube in the three transfer functions.

Interface (for experiments/run_all):
  experiments/volume_renders/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR] [--data DIR]
Writes paper_figures/volume_render_{f3,synthetic}_{grey,pseudo,layer}.png (colour bar included)
and results/volume_renders/renders.json (each render's stats and the machine context) with its
README.md. Skips when all exist unless --force. --quick: 256x256 pixels and a 40x40x80 synthetic
cube instead of 1024x1024 and "paper-250". Reads segy/f3.sgy from the shared data (--data).
"""
import math
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "volume_common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import volume_experiment as vx  # noqa: E402

TRANSFER_FUNCTIONS = ("grey", "pseudo", "layer")
CUBES = ("f3", "synthetic")


def image_name(cube, tf):
    return f"volume_render_{cube}_{tf}.png"


def images(exp):
    """(cube, transfer function) -> the figure's path."""
    return {(cube, tf): exp.path(image_name(cube, tf)) for cube in CUBES for tf in TRANSFER_FUNCTIONS}


# Renders printed two side by side at a journal's 182 mm width (90 mm each) carry 7 pt text:
# capitals 2.47 mm tall (29 px at 1024 px). 1024 px: every figure at least 1000 px wide, the print
# resolution of the gallery's panels (issue 46).
PRINTED_WIDTH_MM, CAPITALS_MM = 90.0, 2.47


def measure(exp):
    size = "256" if exp.quick else "1024"
    text_px = str(math.ceil(CAPITALS_MM / PRINTED_WIDTH_MM * int(size)))
    renders, last_stats = [], None
    with vx.Workspace(exp) as work:
        cubes = {"f3": os.path.join(exp.data, "segy", "f3.sgy"),
                 "synthetic": work.generate("synthetic", *(["--dims", "40", "40", "80"] if exp.quick else ["--preset", "paper-250"]),
                                            "--seed", "1")}
        for (cube, tf), image in images(exp).items():
            stats = work.volume(cubes[cube], "--tf", tf, "--size", size, size, "--camera", "40", "25", "0",
                                "--text-height", text_px, image=image)
            stats["input"]["path"] = os.path.basename(stats["input"]["path"])
            renders.append({"cube": cube, "transfer_function": tf, "image": os.path.relpath(image, exp.out), "stats": stats})
            last_stats = stats
            cx.exio.wrote(image)
    return {"experiment": "volume_renders", "quick": exp.quick, "context": exp.context(last_stats), "renders": renders}


def report(exp, document):
    """Per render: the cube, its dims, the transfer function and the fenced stage times."""
    renders = document["renders"]
    ray_cast = statistics.median(r["stats"]["stages_ms"]["ray_cast"] for r in renders)
    result = md.Report(
        "Seismic renders: the F3 crop and the synthetic cube in three transfer functions",
        "One `cutaway volume` frame (GPU caster, azimuth 40, elevation 25, distance framing the cube, colour bar "
        "included) of the real F3 crop (shared data, segy/f3.sgy) and of the synthetic cube, in each transfer "
        "function: grey, pseudo colour and the paper's layer highlight. The times are one frame each (fenced wall "
        "clock per stage): they show the cost of a render, not a timing protocol.",
        headline=f"{len(renders)} renders; ray cast median {md.ms(ray_cast)} ms")
    result.section("Renders")
    result.table(["cube", "dims", "transfer function", "size", "exit points ms", "ray cast ms", "read-back ms", "samples"],
                 [[r["cube"], "x".join(map(str, r["stats"]["input"]["dims"])), r["transfer_function"],
                   "x".join(map(str, r["stats"]["configuration"]["size"])),
                   md.ms(r["stats"]["stages_ms"].get("exit_points")), md.ms(r["stats"]["stages_ms"]["ray_cast"]),
                   md.ms(r["stats"]["stages_ms"].get("readback")), f"{r['stats']['samples']:,}"] for r in renders],
                 align="llllrrrr")
    return result.figure(*images(exp).values())


def main():
    names = [image_name(cube, tf) for cube in CUBES for tf in TRANSFER_FUNCTIONS]
    cx.Experiment(__doc__, "renders.json", names, tools=("cutaway",), needs_data=True).run(measure, report)


if __name__ == "__main__":
    main()
