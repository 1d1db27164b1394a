"""The paper's figures 7-15 as panels of `cutaway render` options (one PNG per figure).

A figure: name, title, rows of panels (caption, extra options[, model]); `panels` is a one-row
figure. Every panel shares the figure's camera (`camera`, else CAMERA) and size unless its options set them; `metrics`
asks render for the image metrics (exposure, border width), `caption_number` names the one each
caption shows; `zoom` adds a row of enlarged windows
where the panels differ (the figure's point is small: borders, the cut's staircase); `size`
overrides the figure size (grids of panels stay at least 1000 px wide per panel); `difference_to`
adds a last row: every other panel against that one (by index), the pixels that differ in red.
"""

CAMERA = ("--camera", 35, 30, 0)
# Figures about lines on the cut's walls (7, 12) look down at 45 degrees: at elevation 30 the
# lower walls of the default 60-degree aperture lean 30 degrees below the view rays, parallel to
# a level top, so the cut grazes the top layer over wide areas and every border method draws that
# grazing intersection in scattered pieces (fig. 7's ray-cast panel: 77% of its line pixels in
# pieces of 20 px or more at 30 degrees, 83% at 45 where the walls cut the layers steeply).
LINES_VIEW = ("--camera", 35, 45, 0)
SECOND_VIEW = ("--camera", 215, 45, 0)  # the far side, higher: the paper's second view of each model
# Fig. 14's two-property row: primaries in the high-porosity channels (a spatially coherent
# cluster in the generated models, as fig. 15's first window), shown among cells coloured by PERMX.
TWO_PROPERTIES_PORO = (0.30, 0.40)
FRONT_RANGE = (0.5, 1.0)  # fig. 11's primaries: SWAT behind the waterflood's front


def figure_specs(model, steps, swat_range):
    """Figures for `model` (preset:NAME); `steps`: SWAT time steps shown in figure 11, all coloured
    over `swat_range` (LO, HI) so one colour means one saturation in every panel. Figure 8 keeps
    the figure's 16:9 panels: at the grids' 1000x600 its four rows printed 255 mm tall, not 241."""
    return [
        {"name": "fig07_borders", "title": "Fig. 7: threshold vs ray-cast border lines", "metrics": True, "zoom": True,
         "camera": LINES_VIEW,
         "caption_number": "border_line_width",
         "panels": [("threshold borders", ["--border", "threshold"]), ("ray-cast borders", ["--border", "raycast"])]},
        # The three kernels at 33x33, where they differ (at the paper's 9x9 the distance-scaled
        # radius drops by one texel at most on a framed model). The difference row shows where they
        # differ in place of a zoom row (both made the figure too tall to print on one page).
        {"name": "fig08_mean_filter", "title": "Fig. 8: mean-filter kernels on the cut surface, 33x33 (cost: primary exposure)",
         "metrics": True, "caption_number": "primary_exposure", "difference_to": 1,
         "panels": [("no mean filter", ["--mean-filter", 0])] +
                   [(f"{kernel} kernel", ["--mean-filter", 33, "--mean-filter-kernel", kernel])
                    for kernel in ("full", "sampled", "distance-scaled")]},
        {"name": "fig09_ssao_saturation", "title": "Fig. 9: SSAO and saturation contrast",
         "panels": [("plain", ["--ssao", "off"]), ("SSAO", ["--ssao", "on"]), ("SSAO + saturation", ["--ssao", "on", "--saturation"])]},
        {"name": "fig10_freeze_view", "title": "Fig. 10: freeze view (the cut made at azimuth 35, then the model turned)",
         "panels": [("the cut made here (azimuth 35)", ["--camera", 35, 30, 0]),
                    ("turned to azimuth 80: cut follows", ["--camera", 80, 30, 0]),
                    ("turned to azimuth 80: cut frozen", ["--camera", 80, 30, 0, "--freeze-camera", 35, 30, 0])]},
        # One primary range for every step (the swept zone behind the flood front, SWAT 0.5-1), as
        # a reservoir engineer tracks a front: a top fraction taken anew at each step selects the
        # same number of cells whatever the water did.
        {"name": "fig11_aperture180_steps",
         "title": f"Fig. 11: aperture 180 degrees over the generator's SWAT steps ({model[7:]}), primaries SWAT 0.5-1",
         # The panel's title names the step: no caption in the frame repeats it.
         "panels": [(f"SWAT step {s}", ["--aperture-180", "--no-caption", "--property", "SWAT", "--step", s,
                                        "--range", *FRONT_RANGE, "--colour-range", *swat_range])
                    for s in steps]},
        {"name": "fig12_hidden_lines", "title": "Fig. 12: internal lines of secondaries shown / hidden", "zoom": True,
         "camera": LINES_VIEW,
         "panels": [("internal lines", []), ("hidden internal lines", ["--hide-internal-lines"])]},
        {"name": "fig13_silhouette", "title": "Fig. 13: silhouette of the primary cluster (cyan, doubled)",
         "panels": [("no silhouette", []), ("silhouette", ["--silhouette"])]},
    ]


MODEL_PROPERTIES = ("PORO", "PERMX", "NTG", "SWAT")
COUNT_WORDS = {1: "one", 2: "two", 3: "three", 4: "four"}  # fig. 14's rows (sapphire has no FACIES)


def models_figure(presets, size, row_options):
    """Fig. 14: the four models, each coloured by a different property, two per row, the first of
    each row from CAMERA and the second from SECOND_VIEW (so both sides of the fields are seen);
    a last row shows two properties in one frame from both views (the paper's ZMap row;
    shared/data has no ZMap model, so the first preset stands in): cells coloured by PERMX,
    primaries picked by PORO's high-porosity window (`render --select-by PORO`). Three rows of two
    print 190 mm tall at 182 mm wide, within a page. `row_options`: per property of
    MODEL_PROPERTIES (and "two_properties"), (caption suffix, options) fitting it to its model's
    data (models_options)."""
    panels = []
    for index, (p, prop) in enumerate(zip(presets, MODEL_PROPERTIES)):
        suffix, options = row_options.get(prop, ("", []))
        view = (CAMERA, SECOND_VIEW)[index % 2]
        panels.append((f"{p} ({prop}{suffix}), azimuth {view[1]}", ["--property", prop, *options, *view], f"preset:{p}"))
    rows = [panels[:2], panels[2:]]
    lo, hi = TWO_PROPERTIES_PORO
    _, colour = row_options.get("two_properties", ("", []))
    rows.append([(f"{presets[0]}: PERMX colours, primaries PORO {lo:.2f}-{hi:.2f}, azimuth {view[1]}",
                  ["--property", "PERMX", "--select-by", "PORO", "--range", lo, hi, *colour, *view], f"preset:{presets[0]}")
                 for view in (CAMERA, SECOND_VIEW)])
    models = sorted(set(presets), key=presets.index)
    return {"name": "fig14_models",
            "title": f"Fig. 14: the {COUNT_WORDS.get(len(models), len(models))} synthetic models ({', '.join(models)}) with "
                     "properties; last row: two properties",
            "rows": rows, "size": size}


def layers_figure(model, ranges, colour_range, size):
    """Fig. 15: full cutaway, only primaries, only secondaries (rows) for two PORO value ranges
    (columns, `ranges`: (caption, (lo, hi)) pairs), every panel coloured over `colour_range`
    (LO, HI): the columns' frames would each widen their own range to hold their primaries, and
    the same cell would take two colours side by side."""
    layers = (("full cutaway", []), ("only primaries", ["--only", "primaries"]), ("only secondaries", ["--only", "secondaries"]))
    rows = [[(f"{layer}, {caption}", ["--range", lo, hi, "--colour-range", *colour_range, *options]) for caption, (lo, hi) in ranges]
            for layer, options in layers]
    return {"name": "fig15_only_layers", "title": f"Fig. 15: only primaries / only secondaries ({model[7:]}, two PORO ranges, one colour scale; grey: the shell behind hidden primaries)",
            "rows": rows, "model": model, "size": size}
