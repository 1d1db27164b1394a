#!/usr/bin/python3
"""Images like the paper's figures 7-15, plus frame time vs aperture angle and vs primary fraction.

Interface (for experiments/run_all):
  experiments/figures/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes paper_figures/fig07_borders.png ... fig15_only_layers.png, time_vs_aperture.png,
time_vs_primary_fraction.png, and results/figures/figures.json (per panel: options, fenced stage ms,
primary cells, image metrics such as fig. 7's two border_line_width values and fig. 8's primary
exposure; the sweeps; machine context) with its README.md (figures_report.py). Skips when all exist unless --force. --quick: zaphirus
(and petra in fig. 14) at 1000x562, one frame per panel, sweeps at 320x180 with fewer points
(results/quick/figures/, paper_figures/quick/).

Protocol: preset:petra (32,760 cells), 1280x720, camera azimuth 35 / elevation 30 (45 for figures 7
and 12: figure_specs.LINES_VIEW), 1% primaries of PORO, the paper's defaults otherwise; one warm-up and three timed frames per panel (median).
Figures 14 (the four presets, two per row from two views, then two properties in one frame) and 15 (opharine, two PORO ranges; rows: full
cutaway, only primaries, only secondaries) are grids of 1000x600 panels. Figures 7 and 12
add a zoom row: the window where their panels differ, enlarged 3 times; figure 8 a row of each
kernel against the full kernel, the pixels that differ in red.
Sweeps on preset:opharine: full apertures 0..180 degrees at 1% primaries; fractions 0.1%..10% at 60 degrees;
for the default strategy (auto: the report names what it picked) and the paper's frustum;
five rounds over each sweep's values and strategies, interleaved, each point's median over the
rounds and its fastest and slowest round.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import compose  # noqa: E402
import figures_report  # noqa: E402
import figure_specs  # noqa: E402
import sweeps  # noqa: E402

FIGURES = ("fig07_borders", "fig08_mean_filter", "fig09_ssao_saturation", "fig10_freeze_view", "fig11_aperture180_steps",
           "fig12_hidden_lines", "fig13_silhouette", "fig14_models", "fig15_only_layers")
# Fig. 15's two PORO windows: the high-porosity channels and the tightest rock (both
# spatially coherent clusters in the generated models, as the paper's ranges are).
FIG15_RANGES = (("PORO 0.30-0.40", (0.30, 0.40)), ("PORO 0.00-0.12", (0.0, 0.12)))
# The sweeps' strategies: the default (auto names what it picked) and the paper's own, one frustum per primary.
SWEEP_STRATEGIES = ("auto", "frustum")
PANEL_NUMBERS = ("colour_bar_box", "stages_ms", "primary_cells", "primary_exposure", "context_kept", "border_line_width", "total_over_baseline")


def render_figure(exp, spec, model, size, scratch, quick_options):
    """Renders every panel, composes them (compose.compose) into paper_figures/<name>.png;
    returns the numbers."""
    size = spec.get("size", size)
    model = spec.get("model", model)
    rows, numbers = [], []
    spec_rows = spec.get("rows") or [spec["panels"]]
    # The colour bar's text prints at 7 pt too: its capitals are sized for the composed figure's width.
    text_px = compose.min_text_px(compose.figure_width_px(compose.columns_for(spec_rows), size[0]))
    for r, row in enumerate(spec_rows):
        rows.append([])
        for index, panel in enumerate(row):
            caption, options = panel[0], panel[1]
            panel_model = panel[2] if len(panel) > 2 else model
            image = os.path.join(scratch, f"{spec['name']}_{r}_{index}.png")
            camera = () if "--camera" in options else spec.get("camera", figure_specs.CAMERA)  # fig. 10 and 14 set their own
            stats = exp.render(panel_model, *camera, *options, "--size", *size, "--text-height", text_px, *quick_options, image=image,
                               metrics=spec.get("metrics", False))
            numbers.append({"caption": caption, "model": panel_model, "options": [str(o) for o in options],
                            **{k: stats[k] for k in PANEL_NUMBERS if k in stats}})
            shown = spec.get("caption_number")
            if shown == "border_line_width" and shown in stats:
                caption += f"\nborder width {stats[shown]['mean_px']:.2f} +- {stats[shown]['stddev_px']:.2f} px"
            elif shown == "primary_exposure" and shown in stats:
                caption += f"\nprimary exposure {100 * stats[shown]:.2f}%"  # 33x33 costs 0.02%
            rows[-1].append((caption, image))
            print(f"  {spec['name']}: {caption.splitlines()[0]}: total {stats['stages_ms']['total']:.1f} ms")
    after = difference_row(rows, numbers, spec["difference_to"]) if "difference_to" in spec else ()
    layout = compose.compose(rows, spec["title"], exp.path(spec["name"] + ".png"), zoom=spec.get("zoom", False), after=after)
    return {"title": spec["title"], "size": list(size), "colour_bar_text_px": text_px, **layout, "panels": numbers}


def difference_row(rows, numbers, reference):
    """One row: every panel but the `reference`-th (in reading order) against it, the differing
    pixels in red (compose.difference_image); each panel's share of differing model pixels goes
    into its numbers (`differs_from_reference`)."""
    panels = [panel for row in rows for panel in row]
    reference_caption, reference_path = panels[reference]
    reference_image = compose.load(reference_path)
    row = []
    for index, (caption, path) in enumerate(panels):
        if index == reference:
            continue
        image, share = compose.difference_image(compose.load(path), reference_image, numbers[index].get("colour_bar_box"))
        numbers[index]["differs_from_reference"] = {"reference": reference_caption.splitlines()[0], "model_pixel_share": share}
        row.append((f"{caption.splitlines()[0]} against {reference_caption.splitlines()[0]}:\n"
                    f"{100 * share:.2f}% of model pixels differ (red)", image))
    return [row]


def range_holding(ranges, primary_ranges):
    """(LO, HI) over the `ranges` (`cutaway inspect --json` property ranges): their 2nd..98th
    percentiles, widened to hold each primary range of `primary_ranges` within the values'
    extremes, as `render` widens one frame's colour range: one range for every panel of a figure,
    so one colour means one value in all of them and every primary keeps its own colour."""
    low, high = min(r["p2"] for r in ranges), max(r["p98"] for r in ranges)
    lowest, highest = min(r["min"] for r in ranges), max(r["max"] for r in ranges)
    for lo, hi in primary_ranges:
        low, high = min(low, max(lo, lowest)), max(high, min(hi, highest))
    return low, high


def common_colour_range(exp, model, prop, steps, primary_range):
    """`prop`'s colour range over every step of `steps` holding `primary_range` (range_holding)."""
    return range_holding([exp.inspect(model, "--time-step", step)["property_ranges"][f"{prop}@step {step}"] for step in steps],
                         [primary_range])


def models_options(exp, presets):
    """Fig. 14's rows fitted to their data (`cutaway inspect --json`): NTG's primaries are its
    lowest-NTG cells, min to 2nd percentile (the shale; its top 1% is a tie at NTG 1.0 that holds a
    fifth of the cells, which hid the primaries among look-alike secondaries), coloured from its
    minimum to its 98th percentile so the primaries keep their own colours; SWAT halfway through
    the flood, the swept zone behind the front (figure_specs.FRONT_RANGE) as primaries (at step
    0 the water is connate nearly everywhere: one colour over 85% of the model; at the last step
    the top 1% took the colour of most of the flooded field); the two-property row's PERMX coloured over its whole range (the high-porosity channels
    are its most permeable cells: a 2-98% range put every primary at the bar's top)."""
    def ranges(preset, *options):
        return exp.inspect(f"preset:{preset}", *options)["property_ranges"]
    ntg = ranges(presets[2], "--property", "NTG")["NTG"]
    swat_steps = exp.inspect(f"preset:{presets[3]}", "--property", "SWAT")["dynamic_properties"]["SWAT"]
    permx = ranges(presets[0], "--property", "PERMX")["PERMX"]
    front_lo, front_hi = figure_specs.FRONT_RANGE
    # NTG's colours from its minimum (not its 2nd percentile): the primaries lie below that and
    # would all take the bar's lowest colour.
    return {"NTG": (f", primaries NTG {ntg['min']:.2f}-{ntg['p2']:.2f}",
                    ["--range", ntg["min"], ntg["p2"], "--colour-range", ntg["min"], ntg["p98"]]),
            "SWAT": (f" step {(swat_steps - 1) // 2}, primaries SWAT {front_lo:g}-{front_hi:g}",
                     ["--step", (swat_steps - 1) // 2, "--range", front_lo, front_hi]),
            "two_properties": ("", ["--colour-range", permx["min"], permx["max"]])}


def measure(exp):
    """Renders and composes every figure, runs the two sweeps and plots them; returns the numbers."""
    quick = exp.quick
    # Print panels are at least 1000 px wide, quick ones too (the image checks run on them); quick
    # runs render one frame per panel on the smallest models.
    model, size = ("preset:zaphirus", (1000, 562)) if quick else ("preset:petra", (1280, 720))
    grid_size = (1000, 562) if quick else (1000, 600)
    quick_options = ("--warmup", 0, "--repeat", 1) if quick else ()
    sweep_model = "preset:zaphirus" if quick else "preset:opharine"
    steps = (0, 2) if quick else (0, 1, 2, 3)
    presets = ("zaphirus", "zaphirus", "petra", "petra") if quick else cx.PRESETS
    layers_model = "preset:zaphirus" if quick else "preset:opharine"
    swat_range = common_colour_range(exp, model, "SWAT", steps, figure_specs.FRONT_RANGE)
    poro = exp.inspect(layers_model, "--property", "PORO")["property_ranges"]["PORO"]
    layers_colours = range_holding([poro], [window for _, window in FIG15_RANGES])
    specs = figure_specs.figure_specs(model, steps, swat_range) + [
        figure_specs.models_figure(presets, grid_size, models_options(exp, presets)),
        figure_specs.layers_figure(layers_model, FIG15_RANGES, layers_colours, grid_size)]
    numbers = {}
    with tempfile.TemporaryDirectory(prefix="cutaway-figures-") as scratch:
        for spec in sorted(specs, key=lambda s: s["name"]):
            numbers[spec["name"]] = render_figure(exp, spec, model, size, scratch, quick_options)

    apertures = (0, 60, 120, 180) if quick else (0, 30, 60, 90, 120, 150, 180)
    fractions = (0.003, 0.03) if quick else (0.001, 0.003, 0.01, 0.03, 0.1)
    repeat, rounds = (1, 1) if quick else (3, 5)
    sweep_size = (320, 180) if quick else size
    timed = {"model": sweep_model, "size": list(sweep_size), "repeat": repeat, "rounds": rounds}
    aperture_panels, stats = sweeps.sweep(exp, sweep_model, sweep_size, [(a, ["--aperture", a, a]) for a in apertures],
                                          figure_specs.CAMERA, repeat, rounds, SWEEP_STRATEGIES)
    fraction_panels, _ = sweeps.sweep(exp, sweep_model, sweep_size, [(f, ["--primary-fraction", f]) for f in fractions],
                                      figure_specs.CAMERA, repeat, rounds, SWEEP_STRATEGIES)
    return {
        "experiment": "figures", "quick": quick, "model": model, "size": list(size), "camera": list(figure_specs.CAMERA[1:]),
        "context": exp.context(stats), "configuration": stats["configuration"], "figures": numbers,
        "time_vs_aperture": {**timed, "strategies": aperture_panels},
        "time_vs_primary_fraction": {**timed, "strategies": fraction_panels}}


def plot(exp, document):
    """The two sweeps' plots, from the document (the composed figures are renders: measure makes them)."""
    device = cx.device_label(document["context"])
    for name, xlabel, setting, log_axes, format_value in (
            ("time_vs_aperture", "full aperture angle\n(degrees, horizontal = vertical)", "1% primaries", False,
             lambda v: f"{v:g} deg"),
            ("time_vs_primary_fraction", "primary fraction\n(of active cells, log scale)", "aperture 60 degrees", True,
             lambda v: f"{100 * v:g}%")):
        sweep = document[name]
        what = name.removeprefix("time_vs_").replace("_", " ")
        sweeps.plot_sweep(sweep, xlabel, f"Frame time vs {what} ({sweep['model']}, {sweep['size'][0]}x{sweep['size'][1]}, "
                                         f"{setting})\non {device}", exp.path(name + ".png"), format_value, log_x=log_axes,
                          log_y=log_axes)


def main():
    outputs = [f + ".png" for f in FIGURES] + ["time_vs_aperture.png", "time_vs_primary_fraction.png"]
    cx.Experiment(__doc__, "figures.json", outputs).run(measure, figures_report.report, plot)


if __name__ == "__main__":
    main()
