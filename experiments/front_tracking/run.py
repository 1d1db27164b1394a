#!/usr/bin/python3
"""Front tracking over simulated time (issue 44): waterfloods run by OPM Flow, animated by `cutaway
animate` with --coherence none (the paper) and smooth, against the issue's targets.

Interface (for experiments/run_all):
  experiments/front_tracking/run.py [--quick] [--force] [--build DIR]
Writes results/front_tracking/: front_tracking.json (per model and mode the animation's summaries and
configuration, the targets decided from them, the animate-against-render timing, machine context),
stats_MODEL_MODE.json (each animation's full stats.json), MODEL_MODE.mp4 (short 640x360 videos),
front_dates_MODEL.png (the front at 4 dates, none above smooth), flicker_pops.png (cut_flicker and
pops per frame, both modes), fig11_aperture180_waterflood.png (the paper's figure 11 on a simulated
waterflood, one colour range over the steps) and README.md (generated from the data). Skips when they
exist unless --force. --quick: zaphirus only, 320x180, a few steps (results/quick/front_tracking/).

Protocol: each case is simulated once (generate --deck + flow, or SPE9 with a restart at every report
step; kept in BUILD/front_tracking_cases/). The metric runs animate each model's property over its
steps (FULL_MODELS: size, frames per report step) with the same frames in both modes, metrics on; the
videos are separate runs without metrics. The timing run draws each frame a second time as `render`
does (--time-against-render) in the same process: frame_over_render = animate's frames (upload, draw,
read-back, encoding, ffmpeg's finish) over render's draws of the same frames, frame 0 left out.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "figures"))
sys.path.insert(0, HERE)
import compose  # noqa: E402
import cutaway_experiment as cx  # noqa: E402
import front_cases  # noqa: E402
import front_report  # noqa: E402
import report_markdown as md  # noqa: E402

MODES = ("none", "smooth")
FULL_SIZE, QUICK_SIZE = (1920, 1080), (320, 180)
# Per model: the case, the property and its primary range (SWAT 0.5-1: the swept zone behind a
# waterflood's front; SGAS 0.05-1: gas out of solution), the report steps animated (None: all),
# frames per report step and size. SPE9's SWAT 0.5-1 is the issue's target; its water barely moves
# in 900 days (the aquifer below the oil: a few single cells change, each opening its own cut), and
# SPE9's moving front, the gas, is animated as well, at a smaller size to fit the run's time.
FULL_MODELS = {
    "zaphirus": {"case": "zaphirus", "property": "SWAT", "range": (0.5, 1.0), "steps": (0, 12), "frames_per_step": 4,
                 "size": FULL_SIZE},
    "petra": {"case": "petra", "property": "SWAT", "range": (0.5, 1.0), "steps": (0, 15), "frames_per_step": 4,
              "size": FULL_SIZE},
    "spe9": {"case": "spe9", "property": "SWAT", "range": (0.5, 1.0), "steps": None, "frames_per_step": 4,
             "size": FULL_SIZE},
    "spe9_gas": {"case": "spe9", "property": "SGAS", "range": (0.05, 1.0), "steps": None, "frames_per_step": 4,
                 "size": (960, 540)},
}
QUICK_MODELS = {"zaphirus": {"case": "zaphirus", "property": "SWAT", "range": (0.5, 1.0), "steps": (0, 6),
                             "frames_per_step": 4, "size": QUICK_SIZE}}
CAMERA = ("--camera", 35, 30, 0)
VIDEO = {"size": (640, 360), "fps": 12, "crf": 30}
TIMING_SIZE = FULL_SIZE


def print_text_px(panel_width):
    """--text-height for panels `panel_width` px wide of a figure of 4 panels a row (the dates
    figure, figure 11): its text prints at 7 pt once compose wraps the rows to its columns."""
    return compose.min_text_px(compose.figure_width_px(compose.columns_for([[None] * 4]), panel_width))


class FrontExperiment:
    def __init__(self, exp, build):
        self.exp, self.build = exp, build
        self.quick = exp.quick
        self.timing_size = QUICK_SIZE if exp.quick else TIMING_SIZE

    def out(self, name):
        """Every output of this experiment lies in results/front_tracking/ (figures included)."""
        return os.path.join(self.exp.results, name)

    def animate(self, egrid, model, mode, size, stats_path, mp4_path, extra=()):
        steps = () if model["steps"] is None else ("--steps", *model["steps"])
        command = [self.exp.cutaway, "animate", egrid, "--property", model["property"], "--range", *model["range"], *steps,
                   "--frames-per-step", model["frames_per_step"], "--coherence", mode, "--size", *size, *CAMERA,
                   "--out", mp4_path, "--stats", stats_path, *extra]
        subprocess.run([str(c) for c in command], check=True, stdout=subprocess.DEVNULL)
        with open(stats_path) as f:
            return json.load(f)

    def case(self, model):
        if model["case"] == "spe9":
            return front_cases.spe9_case(self.build, self.exp.force)
        return front_cases.generated_case(self.exp, self.build, model["case"], self.exp.force)

    def metric_runs(self, name, model, egrid, scratch):
        """Both modes at the experiment's size, metrics on; each stats.json kept in results."""
        runs = {}
        for mode in MODES:
            stats_path = self.out(f"stats_{name}_{mode}.json")
            runs[mode] = self.animate(egrid, model, mode, model["size"], stats_path, os.path.join(scratch, f"{name}_{mode}.mp4"))
            print(f"  {name} {mode}: pop_max {runs[mode]['pop_max']}, cut_flicker_max {runs[mode]['cut_flicker_max']:.4f}, "
                  f"exposure_min {runs[mode]['primary_exposure_min']}, {runs[mode]['frames_wall_s']:.0f} s", flush=True)
        return runs

    def video_runs(self, name, model, egrid, scratch):
        """The short videos (no metrics) and their PNG frames (for the dates figure)."""
        frames = {}
        for mode in MODES:
            frames[mode] = os.path.join(scratch, f"frames_{name}_{mode}")
            self.animate(egrid, model, mode, VIDEO["size"], os.path.join(scratch, f"video_{name}_{mode}.json"),
                         self.out(f"{name}_{mode}.mp4"),
                         ("--no-metrics", "--fps", VIDEO["fps"], "--crf", VIDEO["crf"], "--frames", frames[mode],
                          "--text-height", print_text_px(VIDEO["size"][0])))
        return frames

    def timing_run(self, name, model, egrid, scratch):
        """animate against render in one run (smooth, no metrics) at the experiment's size."""
        stats = self.animate(egrid, model, "smooth", self.timing_size, os.path.join(scratch, "timing.json"),
                             os.path.join(scratch, "timing.mp4"), ("--no-metrics", "--time-against-render"))
        return {"model": name, "size": list(self.timing_size), "frames": stats["frame_count"],
                "frame_over_render": stats["frame_over_render"], "frame_ms_median": stats["frame_ms_median"],
                "render_ms_median": front_report.median([f["render_ms"] for f in stats["frames"][1:]]),
                "encoder_finish_ms": stats["encoder_finish_ms"], "frames_wall_s": stats["frames_wall_s"],
                "gl_renderer": stats.get("gl_renderer"), "lp_num_threads": stats.get("lp_num_threads")}

    def fig11(self, name, model, egrid, steps, colour_range, scratch):
        """The paper's figure 11 (aperture 180) at 4 report steps, one colour range for all."""
        size = (480, 270) if self.quick else (1000, 562)
        panels = []
        for step in front_report.four_steps(model, len(steps)):
            image = os.path.join(scratch, f"fig11_{step}.png")
            # The panel's title gives the date and step: no caption in the frame repeats them.
            self.exp.render(egrid, *CAMERA, "--aperture-180", "--no-caption", "--property", model["property"], "--time-step", step, "--range",
                            *model["range"], "--colour-range", *colour_range, "--size", *size,
                            "--text-height", print_text_px(size[0]), image=image)
            panels.append((f"{steps[step]['date']} (report step {step})", image))
        title = (f"Fig. 11 on a simulated waterflood: aperture 180, {name} {model['property']} "
                 f"{model['range'][0]}-{model['range'][1]}, one colour range")
        return front_report.compose_panels([panels], title, self.out("fig11_aperture180_waterflood.png"))


def measure(exp):
    """Simulates, animates and draws every model; returns the document (front_tracking.json)."""
    models = QUICK_MODELS if exp.quick else FULL_MODELS
    if not shutil.which("flow"):
        raise SystemExit("flow: not installed (scripts/install-deps.sh installs libopm-simulators-bin)")
    build = os.path.dirname(os.path.dirname(exp.cutaway))
    front = FrontExperiment(exp, build)
    document = {"experiment": "front_tracking", "quick": exp.quick, "protocol": front_report.protocol(CAMERA[1:], VIDEO, models),
                "models": {}}
    with tempfile.TemporaryDirectory(prefix="cutaway-front-") as scratch:
        for name, model in models.items():
            print(f"== {name}", flush=True)
            case = front.case(model)
            steps = front_cases.report_steps(exp, case["egrid"])
            runs = front.metric_runs(name, model, case["egrid"], scratch)
            frames = front.video_runs(name, model, case["egrid"], scratch)
            dates = front_report.dates_figure(name, model, steps, frames, front.out(f"front_dates_{name}.png"))
            document["models"][name] = front_report.model_entry(case, model, steps, runs, dates)
        waterflood = "zaphirus" if exp.quick else "petra"
        case = document["models"][waterflood]["case"]
        colour_range = document["models"][waterflood]["runs"]["smooth"]["colour_range"]
        document["fig11"] = {"model": waterflood, **front.fig11(waterflood, models[waterflood], case["egrid"],
                                                                 front_cases.report_steps(exp, case["egrid"]), colour_range,
                                                                 scratch)}
        document["timing"] = front.timing_run(waterflood, models[waterflood], document["models"][waterflood]["case"]["egrid"],
                                              scratch)
    document["targets"] = front_report.targets(document)
    document["context"] = exp.context({"gl_renderer": document["timing"]["gl_renderer"]})
    return document


def plot(exp, document):
    """The flicker and pops plot from the document (--report-only redraws it)."""
    front_report.flicker_pops_figure(document, os.path.join(exp.results, "flicker_pops.png"))


def report(exp, document):
    result = md.Report(front_report.TITLE, front_report.MEASURES, headline=front_report.headline(document))
    result.body += front_report.readme_body(document)
    return result


def main():
    cx.Experiment(__doc__, "front_tracking.json").run(measure, report, plot)


if __name__ == "__main__":
    main()
