"""The paper's figures 7-15 as panels of `cutaway render` options (one PNG per figure).

A figure: name, title, model, and panels (caption, extra options). Every panel shares the
figure's model, camera and size; `metrics` asks render for the image metrics (exposure, border width).
"""

CAMERA = ("--camera", 35, 30, 0)


def figure_specs(model, steps):
    """Figures for `model` (preset:NAME); `steps`: SWAT time steps shown in figure 11."""
    return [
        {"name": "fig07_borders", "title": "Fig. 7: threshold vs ray-cast border lines", "metrics": True,
         "panels": [("threshold borders", ["--border", "threshold"]), ("ray-cast borders", ["--border", "raycast"])]},
        {"name": "fig08_mean_filter", "title": "Fig. 8: mean filter on the cut surface", "metrics": True,
         "panels": [("no mean filter", ["--mean-filter", 0]), ("9x9", ["--mean-filter", 9]), ("33x33", ["--mean-filter", 33])]},
        {"name": "fig09_ssao_saturation", "title": "Fig. 9: SSAO and saturation contrast",
         "panels": [("plain", ["--ssao", "off"]), ("SSAO", ["--ssao", "on"]), ("SSAO + saturation", ["--ssao", "on", "--saturation"])]},
        {"name": "fig10_freeze_view", "title": "Fig. 10: freeze view (cut made at azimuth 35, model turned)",
         "panels": [("cut from this view", ["--camera", 80, 30, 0]),
                    ("frozen cut from azimuth 35", ["--camera", 80, 30, 0, "--freeze-camera", 35, 30, 0])]},
        {"name": "fig11_aperture180_steps", "title": "Fig. 11: aperture 180 degrees over SWAT time steps",
         "panels": [(f"SWAT step {s}", ["--aperture-180", "--property", "SWAT", "--step", s]) for s in steps]},
        {"name": "fig12_hidden_lines", "title": "Fig. 12: internal lines of secondaries shown / hidden",
         "panels": [("internal lines", []), ("hidden internal lines", ["--hide-internal-lines"])]},
        {"name": "fig13_silhouette", "title": "Fig. 13: silhouette of the primary cluster",
         "panels": [("no silhouette", []), ("silhouette", ["--silhouette"])]},
        {"name": "fig15_only_layers", "title": "Fig. 15: only primaries / only secondaries",
         "panels": [("only primaries", ["--only", "primaries"]), ("only secondaries", ["--only", "secondaries"])]},
    ]


def models_figure(presets):
    """Fig. 14: the four models, each coloured by a different property."""
    properties = ("PORO", "PERMX", "NTG", "SWAT")  # SWAT: step 0 (sapphire has no FACIES)
    return {"name": "fig14_models", "title": "Fig. 14: the four synthetic models with properties",
            "panels": [(f"{p} ({prop})", ["--property", prop], f"preset:{p}") for p, prop in zip(presets, properties)]}
