"""Figures, targets and the README of the front-tracking experiment, from the animations' stats."""
import datetime
import math
import os
import statistics

import compose
import cutaway_experiment as cx

# The targets: both modes keep every primary pixel visible; smooth lowers the largest
# cut flicker and the largest pop at least this many times; smooth keeps the context within this
# relative distance of none's; animate costs at most this many times render's frames.
FLICKER_RATIO, POP_RATIO, CONTEXT_TOLERANCE, ANIMATE_OVER_RENDER = 3.0, 3.0, 0.10, 1.2
UPLOAD_PER_ACTIVE_CELL = 4.0  # bytes: "switching time step costs at most one upload of 4 bytes per active cell"
MODE_COLOURS = {"none": "tab:red", "smooth": "tab:blue"}
# smooth above none, with a white edge: among none's dense spikes (spe9_gas) its thin line was lost.
MODE_ZORDER = {"none": 2, "smooth": 3}


def median(values):
    return statistics.median(values) if values else None


def protocol(camera, video, models):
    """The experiment's configuration, recorded with its results."""
    return {"camera": list(camera), "models": {n: {**m, "range": list(m["range"]), "size": list(m["size"])}
                                               for n, m in models.items()},
            "video": video,
            "context_share": "per frame: pixels showing a secondary cell's own surface (not primary, cut fill or "
                             "border line) over pixels showing any cell. The target compares its mean over the frames "
                             "at report steps after the first, where both modes show the same step's values and "
                             "primaries (between steps none still shows the step before while smooth moves on: a "
                             "growing front leaves smooth less context there by the values alone). The first frame is "
                             "reported apart: it has no frame before it to flicker against, and smooth shows there the "
                             "cuts of the cells entering in the frames after it already opening; the mean over all "
                             "frames is reported beside it",
            "targets": {"primary_exposure_min": 1.0, "cut_flicker_max none/smooth": FLICKER_RATIO,
                        "pop_max none/smooth": POP_RATIO, "context_share at report steps |smooth/none - 1|": CONTEXT_TOLERANCE,
                        "frame_over_render": ANIMATE_OVER_RENDER,
                        "upload bytes per active cell, any frame after the first, both modes": UPLOAD_PER_ACTIVE_CELL}}


def four_steps(model, step_count):
    """Four report steps spread over the animated ones (first and last included)."""
    first, last = model["steps"] or (0, step_count - 1)
    return sorted({round(first + (last - first) * k / 3) for k in range(4)})


def _date_at(steps, time_step):
    """The date at a fractional report step, interpolated between the two report dates, rounded
    as the frames' captions are (eclipse::date_at: halves away from zero; Python's round() takes
    halves to even, which put zaphirus's titles a day before their frames)."""
    lower = min(int(math.floor(time_step)), len(steps) - 1)
    upper = min(lower + 1, len(steps) - 1)
    a, b = (datetime.date.fromisoformat(steps[i]["date"][:10]) for i in (lower, upper))
    return a + datetime.timedelta(days=math.floor((b - a).days * (time_step - lower) + 0.5))


def compose_panels(rows, title, path):
    return compose.compose(rows, title, path)


def dates_figure(name, model, steps, frames, path):
    """2 x 4 panels: the video frames halfway between report steps at 4 dates, none above smooth
    (halfway is where the modes differ: none still shows the step before, smooth its way to the next)."""
    first, last = model["steps"] or (0, len(steps) - 1)
    frames_per_step = model["frames_per_step"]
    chosen = sorted({round(first + (last - 1 - first) * k / 3) for k in range(4)})
    rows, shown = [], []
    for mode in ("none", "smooth"):
        row = []
        for step in chosen:
            frame = (step - first) * frames_per_step + frames_per_step // 2
            time_step = first + frame / frames_per_step
            held = f", shows step {step}" if mode == "none" else ""
            row.append((f"{mode}: {_date_at(steps, time_step)} (step {time_step:g}{held})",
                        os.path.join(frames[mode], f"frame_{frame:05d}.png")))
            if mode == "none":
                shown.append({"frame": frame, "time_step": time_step, "date": str(_date_at(steps, time_step))})
        rows.append(row)
    compose.compose(rows, f"{name}: the front at 4 dates, {model['property']} {model['range'][0]}-{model['range'][1]} "
                          f"(top: --coherence none, bottom: smooth)", path)
    return shown


SUMMARIES = ("pop_max", "pop_reversals_total", "cut_flicker_max", "primary_exposure_min", "context_share_mean",
             "frame_count", "frames_wall_s", "frame_ms_median", "report_steps_read")


def model_entry(case, model, steps, runs, dates):
    entry = {"case": case, "report_steps": len(steps), "first_date": steps[0]["date"], "last_date": steps[-1]["date"],
             "range": list(model["range"]), "dates_figure": dates, "runs": {}}
    for mode, stats in runs.items():
        frames = stats["frames"]
        at_steps = [f["context_share"] for f in frames[1:] if "context_share" in f and float(f["time_step"]).is_integer()]
        entry["runs"][mode] = {
            **{k: stats.get(k) for k in SUMMARIES},
            "context_share_at_steps": statistics.mean(at_steps) if at_steps else None,
            "context_share_first_frame": frames[0].get("context_share"),
            "colour_range": stats["property"]["colour_range"], "primary_range": stats["property"]["primary_range"],
            "hysteresis_band": stats["property"]["hysteresis_band"], "strategy": stats["strategy"],
            "upload": _upload_per_active_cell(frames, stats["active_cells"]),
            "configuration": stats["configuration"], "size": stats["size"],
            "per_frame": {"time_step": [f["time_step"] for f in frames],
                          "cut_flicker": [f.get("cut_flicker") for f in frames],
                          "pops": [f.get("pop_in", 0) + f.get("pop_out", 0) for f in frames],
                          "primary_cells": [f["primary_cells"] for f in frames],
                          "context_share": [f.get("context_share") for f in frames],
                          "cells_opening": [f.get("cells_opening") for f in frames]}}
    entry["largest_flicker"] = {mode: _largest_flicker(run["per_frame"]) for mode, run in entry["runs"].items()}
    return entry


def _upload_per_active_cell(frames, active_cells):
    """Bytes uploaded per active cell: the largest over the frames at report steps after the first
    (where a step switch happens in both modes) and over all frames after the first."""
    per_cell = [(float(f["time_step"]).is_integer(), f["upload_bytes"] / active_cells) for f in frames[1:] if "upload_bytes" in f]
    at_steps = [b for is_step, b in per_cell if is_step]
    return {"step_switch_max": max(at_steps) if at_steps else None,
            "frame_max": max(b for _, b in per_cell) if per_cell else None}


def _largest_flicker(series):
    """The frame with the largest cut flicker: its time and the primary counts around it."""
    flicker = series["cut_flicker"]
    frame = max((f for f in range(1, len(flicker)) if flicker[f] is not None), key=lambda f: flicker[f])
    return {"frame": frame, "time_step": series["time_step"][frame], "cut_flicker": flicker[frame],
            "primaries_before": series["primary_cells"][frame - 1], "primaries_after": series["primary_cells"][frame]}


def _flicker_after_first_switch(series):
    """The largest cut flicker over the frames after report step 1: the first switch from step 0
    (no primaries yet in a waterflood) to step 1 is a single event that decides the maximum."""
    shown = [f for t, f in zip(series["time_step"][1:], series["cut_flicker"][1:]) if t > 1 and f is not None]
    return max(shown) if shown else None


def _ratio(none, smooth):
    if smooth == 0:
        return math.inf if none > 0 else 1.0
    return none / smooth


def _after_first_switch(none, smooth):
    """Cut flicker max over the frames after report step 1, both modes and their ratio (reported
    beside the target, which takes every frame)."""
    n, m = (_flicker_after_first_switch(run["per_frame"]) for run in (none, smooth))
    return {"none": n, "smooth": m, "ratio": _ratio(n, m) if n is not None and m is not None else None}


def targets(document):
    """Each target per model, with the numbers that decide it."""
    result = {}
    for name, entry in document["models"].items():
        none, smooth = entry["runs"]["none"], entry["runs"]["smooth"]
        flicker = _ratio(none["cut_flicker_max"], smooth["cut_flicker_max"])
        pops = _ratio(none["pop_max"], smooth["pop_max"])
        context = smooth["context_share_at_steps"] / none["context_share_at_steps"] - 1 if none["context_share_at_steps"] else math.inf
        result[name] = {
            "primary_exposure_min": {"none": none["primary_exposure_min"], "smooth": smooth["primary_exposure_min"],
                                     "holds": none["primary_exposure_min"] == 1.0 and smooth["primary_exposure_min"] == 1.0},
            "cut_flicker_max": {"none": none["cut_flicker_max"], "smooth": smooth["cut_flicker_max"], "ratio": flicker,
                                "holds": flicker >= FLICKER_RATIO},
            "pop_max": {"none": none["pop_max"], "smooth": smooth["pop_max"], "ratio": pops, "holds": pops >= POP_RATIO},
            "pop_reversals_total": {mode: run.get("pop_reversals_total") for mode, run in entry["runs"].items()},
            "cut_flicker_after_first_switch": _after_first_switch(none, smooth),
            "context_share_at_steps": {"none": none["context_share_at_steps"], "smooth": smooth["context_share_at_steps"],
                                       "relative_change": context, "holds": abs(context) <= CONTEXT_TOLERANCE,
                                       "all_frames": {"none": none["context_share_mean"], "smooth": smooth["context_share_mean"]},
                                       "first_frame": {"none": none["context_share_first_frame"],
                                                       "smooth": smooth["context_share_first_frame"]}},
            "upload_per_active_cell": {mode: run["upload"]["frame_max"] for mode, run in entry["runs"].items()}}
        uploads = result[name]["upload_per_active_cell"]
        uploads["holds"] = all(b is not None and b <= UPLOAD_PER_ACTIVE_CELL for b in uploads.values())
    timing = document["timing"]
    result["animate_over_render"] = {"model": timing["model"], "ratio": timing["frame_over_render"],
                                     "holds": timing["frame_over_render"] <= ANIMATE_OVER_RENDER}
    return result


def flicker_pops_figure(document, path):
    """Per model (rows): cut_flicker (left) and pops in + out (right) per frame against the
    fractional report step, both modes, smooth drawn over none; sized to print at the page width."""
    plt = cx.pyplot()
    from matplotlib import patheffects
    names = list(document["models"])
    fig, axes = plt.subplots(len(names), 2, figsize=(cx.PLOT_WIDTH_IN, 1.0 + 1.9 * len(names)), squeeze=False)
    for r, name in enumerate(names):
        for mode, run in document["models"][name]["runs"].items():
            series = run["per_frame"]
            t = series["time_step"]
            line = {"label": mode, "color": MODE_COLOURS[mode], "zorder": MODE_ZORDER[mode], "linewidth": 0.9,
                    "path_effects": [patheffects.withStroke(linewidth=2.4, foreground="white")] if mode == "smooth" else []}
            axes[r][0].plot(t[1:], series["cut_flicker"][1:], **line)
            axes[r][1].plot(t[1:], series["pops"][1:], **line)
        axes[r][0].set_title(f"{name}: cut flicker")
        axes[r][0].set_ylabel("pixels changed (share)")
        axes[r][1].set_title(f"{name}: primary pops")
        axes[r][1].set_ylabel("cells in + out")
        axes[r][1].yaxis.set_major_locator(plt.MaxNLocator(integer=True))  # pops are whole cells
    for ax in axes[-1]:
        ax.set_xlabel("report step (fractional)")
    # The legend below the panels: inside one it covered that panel's peaks.
    fig.legend(*axes[0][1].get_legend_handles_labels(), title="--coherence", ncol=2, loc="lower center", frameon=False)

    cx.save_figure(fig, path)
    plt.close(fig)


def _mark(holds):
    return "pass" if holds else "FAIL"


def _per_model(document, parts):
    """One bullet per model: its name and parts(entry) joined by semicolons."""
    return [f"- {name}: " + "; ".join(parts(entry)) for name, entry in document["models"].items()]


def _number(value, digits=4):
    if value is None:
        return "-"
    if isinstance(value, float) and math.isinf(value):
        return "inf"
    return f"{value:.{digits}g}" if isinstance(value, float) else str(value)


TITLE = "Front tracking over simulated time (issue 44)"
MEASURES = ("Each model's simulation (OPM Flow) animated by `cutaway animate CASE.EGRID --property P --range LO HI` "
            "with the same frames under `--coherence none` (the paper: a step shown until the next, primaries "
            "selected anew) and `smooth` (values interpolated, hysteresis, paced entries and exits, the cut opening "
            "at a bounded speed where primaries appear).")


def headline(document):
    """One phrase for the results index: how many model targets hold, the waterflood's ratios."""
    decided = targets(document)  # from the stored runs: a report of older data gains the columns added since
    checks = [v["holds"] for name in document["models"] for v in decided[name].values() if isinstance(v, dict) and "holds" in v]
    flood = document["fig11"]["model"]
    f, q = decided[flood]["cut_flicker_max"]["ratio"], decided[flood]["pop_max"]["ratio"]
    later = decided[flood]["cut_flicker_after_first_switch"]["ratio"]
    return (f"{sum(checks)} of {len(checks)} targets hold; {flood}: flicker {f:.2f}x ({later:.2f}x after the first "
            f"switch), pops {q:.2f}x lower with smooth")


def readme_body(document):
    """The report's sections (markdown lines) after its title, measures and machine."""
    p, t = document["protocol"], targets(document)
    lines = ["Context: " + p["context_share"] + ".", "",
             "## Targets", "",
             "| model | property, size, frames | exposure min none / smooth | cut flicker max none / smooth (ratio) "
             "| pop max none / smooth (ratio) | cells turning back none / smooth (not a target) "
             "| flicker max after report step 1 none / smooth (ratio; not a target) "
             "| context share at report steps none / smooth (change); first frame; all frames |",
             "|---|---|---|---|---|---|---|---|"]
    for name, entry in document["models"].items():
        m, model = t[name], p["models"][name]
        e, f, q, c = m["primary_exposure_min"], m["cut_flicker_max"], m["pop_max"], m["context_share_at_steps"]
        back = m["pop_reversals_total"]
        shown = entry["runs"]["none"]["per_frame"]["time_step"]
        later = m["cut_flicker_after_first_switch"]
        lines.append(f"| {name} ({entry['report_steps']} report steps {entry['first_date'][:10]} .. {entry['last_date'][:10]}; "
                     f"steps {min(shown):g}-{max(shown):g} animated) | "
                     f"{model['property']} {model['range'][0]:g}-{model['range'][1]:g}, {model['size'][0]}x{model['size'][1]}, "
                     f"{entry['runs']['none']['frame_count']} frames ({model['frames_per_step']} per step) | "
                     f"{_number(e['none'])} / {_number(e['smooth'])} {_mark(e['holds'])} | "
                     f"{_number(f['none'], 3)} / {_number(f['smooth'], 3)} ({_number(f['ratio'], 3)}x) {_mark(f['holds'])} | "
                     f"{q['none']} / {q['smooth']} ({_number(q['ratio'], 3)}x) {_mark(q['holds'])} | "
                     f"{_number(back['none'])} / {_number(back['smooth'])} | "
                     f"{_number(later['none'], 3)} / {_number(later['smooth'], 3)} ({_number(later['ratio'], 3)}x) | "
                     f"{_number(c['none'], 3)} / {_number(c['smooth'], 3)} ({100 * c['relative_change']:+.1f}%) {_mark(c['holds'])}; "
                     f"{_number(c['first_frame']['none'], 3)} / {_number(c['first_frame']['smooth'], 3)}; "
                     f"{_number(c['all_frames']['none'], 3)} / {_number(c['all_frames']['smooth'], 3)} |")
    timing, a = document["timing"], t["animate_over_render"]
    lines += ["", f"Targets: exposure min 1.0 in both modes; none/smooth ratio of cut flicker max and of pop max at least "
                  f"{FLICKER_RATIO:g}; context share of smooth within {100 * CONTEXT_TOLERANCE:.0f}% of none's. Cut flicker: the share "
                  "of model pixels whose state (cut away or not) changed since the previous frame; pops: cells entering and "
                  "leaving the drawn primary set. Cells turning back (summed over the run): a cell leaving the primary set "
                  "after it entered in an earlier frame, or entering after it left, the \"cells [that] arbitrary pop in and "
                  "out\" of the paper's open problem; a front that only advances has none. In a waterflood the switch from "
                  "step 0 (no primaries yet) to step 1 is one "
                  "event that decides both modes' flicker maximum; the column after the pops gives the maximum over the "
                  "frames after step 1, where the front moves on (not a target of the issue).", "",
              "Where each largest flicker happens (fractional report step, primary cells before and after):", ""]
    lines += _per_model(document, lambda entry: [f"{mode} {_number(w['cut_flicker'], 3)} at step {w['time_step']:g} "
                                                 f"({w['primaries_before']} -> {w['primaries_after']} primaries)"
                                                 for mode, w in entry["largest_flicker"].items()])
    lines += ["", "Smooth spreads a step's many entries and exits over its frames (pops and flicker fall about as many "
                  "times as there are frames per step), and each cell that enters opens its own cut over the frames of two "
                  "report steps before it enters (at most 8 frames; from where its view rays enter the model, or beside primaries from "
                  "their walls, to the cell's rear; the frames ahead are made before they are shown), so it is drawn as "
                  "a primary the frame it is selected; a cell that leaves closes its cut over as many frames after; the "
                  "seed strategies' cone slope follows the primaries' centroid a share per frame. A single cell entering "
                  "in a new place so flips its cut a share at a time. The opening's length and pace are empirical "
                  "choices on zaphirus and SPE9 (src/cutaway/temporal/cell_openings.h). Pops are whole cells and "
                  "cannot be split over frames: a 3x lower pop max needs none's to be at least 3. Where none's is lower (a "
                  "front that adds a cell or two per report step), smooth can at most halve it, by entering those cells "
                  "in different frames.", "",
                  f"Upload per switch of report step (bytes per active cell, largest over the run; target at most "
                  f"{UPLOAD_PER_ACTIVE_CELL:g} at any frame after the first, both modes):", ""]
    lines += [line + f"; {_mark(t[name]['upload_per_active_cell']['holds'])}" for name, line in zip(document["models"], _per_model(
        document, lambda entry: [f"{mode} {_number(run['upload']['step_switch_max'], 3)} at report steps, "
                                 f"{_number(run['upload']['frame_max'], 3)} at any frame" for mode, run in entry["runs"].items()]))]
    lines += ["", "None uploads the step's values (4 bytes per active cell) and selects the primaries on the GPU from "
                  "them; smooth uploads the blended values every frame at 16 bits (2 bytes per active cell: they only "
                  "colour), the primary flags (1 bit per active cell) and 8 bytes per cell whose cut opens or closes."]
    lines += ["",
              "## animate against render", "",
              f"{timing['model']}, {timing['size'][0]}x{timing['size'][1]}, {timing['frames']} frames, smooth, same run "
              f"(`--time-against-render`): animate's frames (upload, draw, read-back, H.264 encoding, ffmpeg's finish) "
              f"cost {a['ratio']:.3f}x render's draws of the same frames (target <= {ANIMATE_OVER_RENDER:g}: "
              f"{_mark(a['holds'])}); median frame {timing['frame_ms_median']:.1f} ms against {timing['render_ms_median']:.1f} ms.",
              "", "## Files", "",
              "- `stats_MODEL_MODE.json`: each metric run's stats.json (per frame: time_step, primary_exposure, pop_in, "
              "pop_out, pop_reversals, cut_flicker, context_share, cells_opening, upload_bytes, ms; summaries; configuration; machine)",
              f"- `MODEL_MODE.mp4`: the videos, {p['video']['size'][0]}x{p['video']['size'][1]}, {p['video']['fps']} fps, "
              f"crf {p['video']['crf']}",
              "- `front_dates_MODEL.png`: the front at 4 dates halfway between report steps, none above smooth",
              "- `flicker_pops.png` (and .pdf): cut flicker and pops per frame, both modes",
              f"- `fig11_aperture180_waterflood.png`: the paper's figure 11 (aperture 180) at 4 report steps of "
              f"{document['fig11']['model']}, one colour range for all steps", "",
              "![flicker and pops](flicker_pops.png)", "",
              "![figure 11 on a waterflood](fig11_aperture180_waterflood.png)", ""]
    for name in document["models"]:
        lines += [f"![{name} front at 4 dates](front_dates_{name}.png)", ""]
    return lines
