"""The figures experiment's README from figures.json: per figure its panels' frame times and image
metrics, and the two sweeps (frame time against aperture and against primary fraction)."""

import cutaway_experiment as cx
import report_markdown as md

SWEEP_STAGES = ("cut_surface", "secondary", "ssao", "mean_filter", "total")


def metric_cells(panel):
    """Primary exposure, context kept and border width where the panel measured them."""
    width = panel.get("border_line_width")
    return [f"{panel['primary_exposure']:.4f}" if panel.get("primary_exposure") is not None else "-",
            f"{panel['context_kept']:.3f}" if panel.get("context_kept") is not None else "-",
            f"{width['mean_px']:.2f} +- {width['stddev_px']:.2f}" if isinstance(width, dict) and "mean_px" in width else "-"]


def sweep_section(result, title, sweep, label):
    result.section(title, f"{sweep['model']}, {sweep['size'][0]}x{sweep['size'][1]}, median of {sweep['repeat']} "
                          f"timed frames per point in each of {sweep['rounds']} rounds over the values and strategies "
                          "(interleaved), then the median over the rounds; the fastest and slowest rounds' totals beside it. "
                          "`auto` draws with the strategy it picks for the primary count (column `drew`).")
    result.table(["strategy", label, "drew", "primary cells", *(cx.STAGE_LABELS[s] + " ms" for s in SWEEP_STAGES),
                  "total: fastest - slowest round ms"],
                 [[panel["requested"], f"{r['value']:g}", r["strategy"], f"{r['primary_cells']:,}",
                   *(md.ms(r["stages_ms"].get(s)) for s in SWEEP_STAGES),
                   f"{md.ms(min(r['total_ms_by_round']))} - {md.ms(max(r['total_ms_by_round']))}"]
                  for panel in sweep["strategies"] for r in panel["rows"]])


def report(exp, document):
    """Per figure a table of its panels, then the sweeps; links every figure."""
    aperture = document["time_vs_aperture"]["strategies"][0]["rows"]
    result = md.Report(
        "Figures 7-15 and frame time against aperture and primary fraction",
        f"Images like the paper's figures 7-15, each a grid of `cutaway render` panels ({document['model']}, "
        f"{document['size'][0]}x{document['size'][1]} unless the figure sets its own, camera azimuth/elevation "
        f"{document['camera'][0]}/{document['camera'][1]} unless the panel sets its own, the paper's defaults otherwise), "
        "with each panel's fenced frame time and, where the figure's point is one, its image metric (primary exposure, "
        "context kept, border-line width); and two sweeps of the frame time per stage: against the full aperture angle "
        "and against the primary fraction. The panel times come from few frames (the figures are images, not a timing "
        "protocol); the sweeps are the timing.",
        headline=f"frame {md.ms(aperture[0]['stages_ms']['total'])} ms at aperture {aperture[0]['value']:g} to "
                 f"{md.ms(aperture[-1]['stages_ms']['total'])} ms at {aperture[-1]['value']:g} degrees "
                 f"({document['time_vs_aperture']['model']}, {aperture[0]['strategy']})")
    for name, figure in document["figures"].items():
        result.section(figure["title"])
        result.table(["panel", "model", "total ms", "primary cells", "primary exposure", "context kept", "border width px"],
                     [[p["caption"].replace("\n", " "), p["model"], md.ms(p["stages_ms"]["total"]), f"{p['primary_cells']:,}",
                       *metric_cells(p)] for p in figure["panels"]], align="llrrrrr")
        result.figure(exp.path(name + ".png"))
    sweep_section(result, "Frame time against the full aperture angle", document["time_vs_aperture"], "aperture (deg)")
    sweep_section(result, "Frame time against the primary fraction", document["time_vs_primary_fraction"], "fraction")
    return result.figure(*(exp.path(f"{n}.png") for n in ("time_vs_aperture", "time_vs_primary_fraction")))
