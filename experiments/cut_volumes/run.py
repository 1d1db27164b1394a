#!/usr/bin/python3
"""Cut volumes and wells (issue 45): frame cost per kind and count, a panel per kind, a waterflood.

The cost in the main job's frame, a panel per volume kind, and a waterflood's front seen inside a
cut around its injector.

Interface (for experiments/run_all):
  experiments/cut_volumes/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/cut_volumes/cut_volumes.json (per benchmark case: frame and stage ms, ratio to the
frame without volumes, triangles, the issue's target; the panels' specs and stage ms; the
waterflood's steps, dates and colour range; machine context), results/cut_volumes/README.md,
paper_figures/cut_volumes.png and paper_figures/wells_waterflood.png.

Cost: bench_cut_volumes, the main job (1% primaries by PORO, 9x9 mean filter, SSAO, ray-cast
borders) on sapphire at 1920x1080, cases none, one box, one cylinder, one mesh, 8 and 32 boxes and
one well, in one process: 3 repetitions per case in random order, 5 timed frames each (medians). Targets: one box or well <= 1.10 x
the frame without volumes, 32 boxes <= 1.50 x.
Volume panels: preset:petra at 1280x720, `--primaries none` and one volume each (box, cylinder,
well around the generated deck's INJ2 with the deck's wells drawn, an icosahedron OBJ).
Waterflood: `cutaway generate --preset petra --deck`, `flow` on it, then SWAT at four report steps
(a tenth, a third, two thirds of the way and the last) with every well drawn and a cut around INJ2,
one colour range over the four.
--quick: zaphirus everywhere, the benchmark at 480x270 with 1 frame, panels at 640x360
(results/quick/cut_volumes/, paper_figures/quick/).
"""
import glob
import os
import subprocess
import sys
import tempfile
from statistics import median

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "figures"))
import compose  # noqa: E402
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import scenes  # noqa: E402

# Issue 45's targets: frame with the volumes over the frame without, same run.
TARGETS = {"box": 1.10, "well": 1.10, "boxes_32": 1.50}
# The far side, from above: the generated decks' injectors stand on the near flank from there.
# Aperture 0: the cut is the volume's own footprint, so each panel shows its volume's shape.
VIEW = ("--camera", 215, 40, 0, "--aperture", 0, 0)
INJECTOR = "INJ2"  # a generated deck's second injector: away from the model's edge on petra and zaphirus


def settings(quick):
    if quick:
        return {"bench_preset": "zaphirus", "bench_size": "480x270", "bench_frames": 1, "repetitions": 1, "panel_preset": "zaphirus",
                "panel_size": (640, 360), "flood_preset": "zaphirus"}
    return {"bench_preset": "sapphire", "bench_size": "1920x1080", "bench_frames": 5, "repetitions": 3, "panel_preset": "petra",
            "panel_size": (1280, 720), "flood_preset": "petra"}


def cost(exp, config):
    """bench_cut_volumes' cases as rows with their ratio to the case without volumes. The cases
    run in random order, `repetitions` times each (Google Benchmark's random interleaving), so a
    change in the machine's speed during the run spreads over every case instead of landing on
    the ones that ran at that moment; each row keeps the medians over its repetitions."""
    document = exp.benchmark("--preset", config["bench_preset"], "--size=" + config["bench_size"],
                             "--frames", config["bench_frames"], "--benchmark_repetitions=" + str(config["repetitions"]),
                             "--benchmark_enable_random_interleaving=true", tool="bench_cut_volumes")
    context = document["context"]
    names = dict(part.split(" = ") for part in context["volumes"].split(", "))
    runs = {}
    for run in document["benchmarks"]:
        if run.get("run_type", "iteration") == "iteration":
            runs.setdefault(names[run["name"].split("volumes:")[1].split("/")[0]], []).append(run)
    rows = [{"case": name, "volumes": int(reps[0]["volumes"]), "triangles": int(reps[0]["volume_triangles"]),
             "frame_ms": median([r["frame_ms"] for r in reps]), "frame_ms_per_repetition": [r["frame_ms"] for r in reps],
             "stages_ms": {s: median([r[s] for r in reps]) for s in cx.STAGES if s in reps[0]}}
            for name, reps in sorted(runs.items(), key=lambda item: list(names.values()).index(item[0]))]
    base = next(r for r in rows if r["case"] == "none")
    for row in rows:
        row["ratio_to_none"] = row["frame_ms"] / base["frame_ms"]
        row["cut_surface_added_ms"] = row["stages_ms"]["cut_surface"] - base["stages_ms"]["cut_surface"]
        if row["case"] in TARGETS:
            row["target"] = TARGETS[row["case"]]
            row["holds"] = row["ratio_to_none"] <= row["target"]
    return rows, cx.benchmark_context(document)


def generate_deck(exp, preset, folder):
    """`cutaway generate --preset PRESET --deck FOLDER`; returns the CASE.DATA path."""
    subprocess.run([exp.cutaway, "generate", "--preset", preset, "--deck", folder, "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    decks = glob.glob(os.path.join(folder, "*.DATA"))
    if len(decks) != 1:
        raise SystemExit(f"cutaway generate --deck {folder}: expected one CASE.DATA, found {decks}")
    return decks[0]


def volume_panels(exp, config, scratch):
    """One render per volume kind with --primaries none; returns (captioned images for compose,
    numbers, the last render's stats)."""
    model = "preset:" + config["panel_preset"]
    bounds = exp.inspect(model)["bounds"]
    deck = generate_deck(exp, config["panel_preset"], os.path.join(scratch, "panel_deck"))
    well = scenes.well_spec(INJECTOR, bounds, 0.07)
    panels = [("box", "box: a shaft through the middle third, down to 60% of the depth", [scenes.box_spec(bounds)], []),
              ("cylinder", "cylinder: a slanted core from a corner to the middle", [scenes.cylinder_spec(bounds)], []),
              ("well", f"well: a {float(well.split(',')[1]):.0f} m tube around {INJECTOR}, the deck's wells drawn",
               [well], ["--wells", deck]),
              ("mesh", "mesh: a closed icosahedron read from an OBJ file", [scenes.write_mesh_obj(bounds, scratch)], [])]
    return render_panels(exp, model, config["panel_size"], panels, scratch)


def render_panels(exp, model, size, panels, scratch):
    """Each panel titled in words; its --cut-volume specs are in the JSON and the report."""
    text_px = compose.min_text_px(compose.figure_width_px(2, size[0]))
    rows, numbers = [], []
    for kind, caption, specs, extra in panels:
        image = os.path.join(scratch, f"volume_{kind}.png")
        options = [*VIEW, "--primaries", "none", *(a for s in specs for a in ("--cut-volume", s)), *extra]
        stats = exp.render(model, *options, "--size", *size, "--text-height", text_px, image=image)
        shown = [s if not s.startswith("mesh:") else "mesh:" + os.path.basename(s[5:]) for s in specs]
        rows.append((caption, image))
        numbers.append({"kind": kind, "caption": caption, "specs": shown, "options": [str(o) for o in options if o not in specs],
                        "stages_ms": stats["stages_ms"]})
        print(f"  {kind}: {stats['stages_ms']['total']:.0f} ms")
    return rows, numbers, stats


def flood_steps(report_steps):
    """Four report steps (indices into the file's steps) for a 2 x 2 figure: a tenth of the way,
    while the front is still near the injector (but after the initial state), a third, two thirds
    and the last."""
    last = len(report_steps) - 1
    return sorted({max(1, last // 10), max(2, last // 3), max(3, 2 * last // 3), last})


def waterflood(exp, config, scratch):
    """The generated deck run by flow, SWAT at four steps inside a cut around the injector;
    returns (rows for compose, numbers)."""
    deck = generate_deck(exp, config["flood_preset"], os.path.join(scratch, "flood"))
    out = os.path.join(os.path.dirname(deck), "out")
    subprocess.run(["flow", deck, "--output-dir=" + out], check=True, stdout=subprocess.DEVNULL)
    case = os.path.join(out, os.path.splitext(os.path.basename(deck))[0] + ".EGRID")
    report_steps = exp.inspect(case)["report_steps"]
    steps = flood_steps(report_steps)
    ranges = [exp.inspect(case, "--time-step", k)["property_ranges"][f"SWAT@step {k}"] for k in steps]
    colour_range = (min(r["min"] for r in ranges), max(r["max"] for r in ranges))
    cut = scenes.well_spec(INJECTOR, exp.inspect(case)["bounds"], 0.1)
    size = config["panel_size"]
    text_px = compose.min_text_px(compose.figure_width_px(2, size[0]))
    rows, numbers = [], []
    for k in steps:
        image = os.path.join(scratch, f"flood_{k}.png")
        # The step and date in the panel's title, not over the frame, where the producers' labels go.
        options = [*VIEW, "--property", "SWAT", "--time-step", k, "--colour-range", *colour_range, "--wells", "all",
                   "--primaries", "none", "--cut-volume", cut, "--no-caption"]
        stats = exp.render(case, *options, "--size", *size, "--text-height", text_px, image=image)
        date = report_steps[k]["date"]
        rows.append((f"step {k}, {date}: {report_steps[k]['elapsed_days'] / 365.25:.1f} years of injection", image))
        numbers.append({"step": k, "date": date, "elapsed_days": report_steps[k]["elapsed_days"],
                        "options": [str(o) for o in options], "stages_ms": stats["stages_ms"]})
        print(f"  waterflood step {k} ({date}): {stats['stages_ms']['total']:.0f} ms")
    return rows, {"preset": config["flood_preset"], "case": os.path.basename(case), "report_steps": len(report_steps),
                  "cut": cut, "colour_range": list(colour_range), "steps": numbers}


def measure(exp):
    config = settings(exp.quick)
    rows, bench_context = cost(exp, config)
    for row in rows:
        print(f"  {row['case']}: {row['frame_ms']:.1f} ms frame, {row['ratio_to_none']:.3f} x none")
    with tempfile.TemporaryDirectory(prefix="cutaway-volumes-") as scratch:
        panel_rows, panels, stats = volume_panels(exp, config, scratch)
        layout = compose.compose([panel_rows], "Cut volumes alone (--primaries none), one of each kind, "
                                 f"preset:{config['panel_preset']}", exp.path("cut_volumes.png"))
        flood_rows, flood = waterflood(exp, config, scratch)
        radius = float(flood["cut"].split(",")[1])  # well:NAME,R (the spec itself is in the report)
        flood_layout = compose.compose([flood_rows], f"Waterflood of the generated {config['flood_preset']} deck (OPM Flow): "
                                       f"SWAT inside a {radius:.0f} m cut around {INJECTOR}", exp.path("wells_waterflood.png"))
    return {"experiment": "cut_volumes", "quick": exp.quick, "configuration": config, "targets": TARGETS,
            "cost": rows, "bench_context": bench_context, "panels": panels, "panels_layout": layout,
            "waterflood": {**flood, "layout": flood_layout},
            "context": {**exp.context(stats), "gl_version": stats.get("gl_version")}}


# Passes whose work depends on the image size only, not on what the volumes cut away: their spread
# across the cases of one run shows how much the machine's speed moved during it.
SCREEN_PASSES = ("ssao", "mean_filter", "post")


def cost_rows(rows):
    out = []
    for r in rows:
        verdict = "" if "target" not in r else f"<= {r['target']:.2f}: " + ("holds" if r["holds"] else "MISSED")
        stages = r["stages_ms"]
        out.append([r["case"], r["volumes"], f"{r['triangles']:,}", md.ms(r["frame_ms"]), md.ms(stages.get("cut_surface")),
                    md.ms(r.get("cut_surface_added_ms")), md.ms(stages.get("secondary")),
                    md.ms(sum(stages.get(s, 0) for s in SCREEN_PASSES)), f"{r['ratio_to_none']:.3f}", verdict])
    return out


def drift_sentence(rows):
    screen = [sum(r["stages_ms"].get(s, 0) for s in SCREEN_PASSES) for r in rows]
    return (f"SSAO + mean filter + composite, the same work in every case, took {min(screen):.0f} to {max(screen):.0f} ms "
            f"across the cases ({max(screen) / min(screen):.2f}x): how far the machine's speed moved during the run.")


def per_triangle_sentence(rows):
    """Stage 1's added time per volume triangle, case by case: what the cost grows with."""
    shares = [f"{r['case']} {r['cut_surface_added_ms'] / r['triangles']:.2f}" for r in rows if r["triangles"]]
    return "Stage 1 time added per volume triangle, ms: " + ", ".join(shares) + "."


def report(exp, document):
    config, rows, flood = document["configuration"], document["cost"], document["waterflood"]
    checked = [r for r in rows if "target" in r]
    missed = [r["case"] for r in checked if not r["holds"]]
    result = md.Report(
        "Cut volumes and wells: cost in the main job's frame, a panel per kind, a waterflood's front",
        f"`bench_cut_volumes` renders the main job (1% primaries by PORO, 9x9 mean filter, SSAO, ray-cast borders) on "
        f"{config['bench_preset']} at {config['bench_size']} with no volume, one box, one cylinder, one closed mesh (a "
        f"UV sphere read from an OBJ), 8 and 32 boxes and one well (the tube `well:INJ1` cuts around on the preset's "
        f"generated deck), in one process: {config.get('repetitions', 1)} repetition(s) per case in random order, "
        f"{config['bench_frames']} timed frame(s) each after a warm-up; medians of fenced wall times (over the frames, "
        "then over the repetitions); ratios within this one run. Targets (issue 45): one box or well <= 1.10 x the "
        "frame without volumes, 32 volumes <= 1.50 x.",
        headline=f"{len(checked) - len(missed)} of {len(checked)} cost targets hold" +
                 (f" (missed: {', '.join(missed)})" if missed else ""))
    result.section("Cost per volume kind and count",
                   "A volume adds its stage 1 work (cut_surface; added: over the frame without volumes) and changes "
                   "stage 2's (secondary) by what it cuts away. Stage 1 draws each volume's rear triangles, and bevelled walls "
                   "towards the camera along its silhouette (shaders/cut_surface/volume.geom): the walls' fill, which grows "
                   "with the silhouette's length on screen and the volume count, is most of its added time.")
    result.table(["volumes", "count", "triangles", "frame ms", "cut_surface ms", "added", "secondary ms",
                  "SSAO+filter+post ms", "frame / no volume", "target"], cost_rows(rows), align="lrrrrrrrrl")
    result.text(per_triangle_sentence(rows)).text(drift_sentence(rows))
    result.section("What the figures show",
                   f"`cut_volumes.png`: preset:{config['panel_preset']} at {config['panel_size'][0]}x{config['panel_size'][1]}, "
                   "camera azimuth 215, elevation 40, `--aperture 0 0` (the cut is each volume's own footprint), "
                   "`--primaries none` and one volume per panel; the well panel draws the generated deck's wells "
                   f"(`--wells DECK.DATA`) and cuts around {INJECTOR}. The volumes: " +
                   "; ".join(f"`--cut-volume {' '.join(p['specs'])}`" for p in document["panels"]) + ".",
                   f"`wells_waterflood.png`: `cutaway generate --preset {flood['preset']} --deck`, run by `flow`; SWAT of "
                   f"{flood['case']} at report steps {', '.join(str(s['step']) for s in flood['steps'])} of "
                   f"{flood['report_steps']} ({', '.join(s['date'] for s in flood['steps'])}), every well drawn "
                   f"(`--wells all`), `--primaries none --cut-volume {flood['cut']}`, one colour range "
                   f"{flood['colour_range'][0]:.3f}..{flood['colour_range'][1]:.3f} (the steps' min..max from "
                   "`cutaway inspect --json`).")
    return result.figure(exp.path("cut_volumes.png"), exp.path("wells_waterflood.png"))


def main():
    exp = cx.Experiment(__doc__, "cut_volumes.json", ["cut_volumes.png", "wells_waterflood.png"],
                        tools=("cutaway", "bench_cut_volumes"))
    exp.run(measure, report)


if __name__ == "__main__":
    main()
