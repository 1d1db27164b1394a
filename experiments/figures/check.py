#!/usr/bin/python3
"""Image checks on the paper figures that experiments/figures/run.py wrote (issue 15); ctest runs
them on the committed paper_figures/ (test figure_checks), CI on paper_figures/quick/ after
`experiments/run_all --quick`.

  experiments/figures/check.py [--quick]
Reads paper_figures[/quick]/fig*.png and results[/quick]/figures/figures.json. Exit 0 when every
check holds, 1 naming each that fails, 77 (ctest: skipped) without numpy/matplotlib or figures.
Each threshold is named with its reason below. The renderer's own checks (no see-through, cut-wall
luminance, framing, colour-bar layout, silhouette colour) run in cutaway_gl_tests on frames
rendered there; these look at what the figures show.
"""
import argparse
import json
import os
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

# Print resolution: a panel is at least 1000 px wide (issue 15).
MIN_PANEL_WIDTH = 1000
# Fig. 11 (aperture 180 over time steps) keeps context: at least a third of every panel shows the
# model (the cut with the rear shell kept showed 5.4% before issue 15).
MIN_FIG11_MODEL_SHARE = 0.33
# Fig. 12's two panels (internal lines shown / hidden) differ visibly: at least 2% of the pixels
# change by more than 24/255 in some channel (the same picture gives 0).
MIN_FIG12_CHANGED = 0.02
# Fig. 13's silhouette has its own colour: cyan pixels (blue and green high, red low) appear only
# with --silhouette, at least 500 of them.
MIN_SILHOUETTE_PIXELS = 500


def fail(failures, message):
    failures.append(message)
    print("FAIL:", message)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="check paper_figures/quick/ and results/quick/")
    args = parser.parse_args()
    try:
        import numpy as np
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as error:
        print("skipped:", error)
        return 77
    figures = os.path.join(REPO, "paper_figures", "quick") if args.quick else os.path.join(REPO, "paper_figures")
    numbers_path = os.path.join(REPO, "results", *(["quick"] if args.quick else []), "figures", "figures.json")
    if not os.path.exists(numbers_path):
        print("skipped: no", os.path.relpath(numbers_path, REPO), "(run experiments/figures/run.py first)")
        return 77
    with open(numbers_path) as f:
        numbers = json.load(f)["figures"]
    failures = []
    panels_of = {}
    for name, figure in sorted(numbers.items()):
        width = figure.get("panel_size", [0])[0]
        if width < MIN_PANEL_WIDTH:
            fail(failures, f"{name}: panels {width} px wide, expected at least {MIN_PANEL_WIDTH} (print resolution)")
        image = plt.imread(os.path.join(figures, name + ".png"))[..., :3]
        panels_of[name] = image
    # The composed figure holds panels at native size: cut them back out by the recorded layout.
    def panels(name):
        image, figure = panels_of[name], numbers[name]
        w, h = figure["panel_size"]
        return [image[y:y + h, x:x + w] for x, y in figure["panel_boxes"]]

    if "fig11_aperture180_steps" in numbers:
        for i, panel in enumerate(panels("fig11_aperture180_steps")):
            share = float((panel.min(axis=2) < 0.94).mean())  # not the white background
            print(f"fig11 panel {i}: model on {100 * share:.1f}% of the panel")
            if share < MIN_FIG11_MODEL_SHARE:
                fail(failures, f"fig11 panel {i}: the model covers {100 * share:.1f}% (< {100 * MIN_FIG11_MODEL_SHARE:.0f}%: context lost)")
    if "fig12_hidden_lines" in numbers:
        shown, hidden = panels("fig12_hidden_lines")[:2]
        changed = float((np.abs(shown - hidden).max(axis=2) > 24 / 255).mean())
        print(f"fig12: {100 * changed:.2f}% of the pixels change when internal lines are hidden")
        if changed < MIN_FIG12_CHANGED:
            fail(failures, f"fig12: hiding internal lines changes {100 * changed:.2f}% of the pixels (< {100 * MIN_FIG12_CHANGED:.0f}%)")
    if "fig13_silhouette" in numbers:
        plain, outlined = panels("fig13_silhouette")[:2]

        def cyan(p):
            return int(((p[..., 0] < 0.2) & (p[..., 1] > 0.6) & (p[..., 2] > 0.85)).sum())
        added = cyan(outlined) - cyan(plain)
        print(f"fig13: {added} cyan silhouette pixels")
        if added < MIN_SILHOUETTE_PIXELS:
            fail(failures, f"fig13: {added} cyan silhouette pixels (< {MIN_SILHOUETTE_PIXELS}): the silhouette lacks its own colour")
    print("figure checks:", "all hold" if not failures else f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
