"""Shared parts of the volume experiments (volume_fig7, volume_fig8, volume_renders): a scratch
folder that generates cubes and runs `cutaway volume`, per-trial frame times and the paper's
trimmed mean. Their command line, output folders and reports are every experiment's
(experiments/common/cutaway_experiment.py: each writes results/<experiment>/ and paper_figures/).
"""
import json
import math
import os
import shutil
import statistics
import subprocess
import tempfile


class Workspace:
    """A scratch folder for generated cubes and per-run stats, removed afterwards; `exp` an
    Experiment whose `cutaway` runs."""

    def __init__(self, exp):
        self.cutaway = exp.cutaway
        self.path = tempfile.mkdtemp(prefix="cutaway-volume-")

    def __enter__(self):
        return self

    def __exit__(self, *_):
        shutil.rmtree(self.path, ignore_errors=True)

    def generate(self, name, *options):
        """`cutaway generate-seismic OPTIONS --out NAME.sgy`; returns the path."""
        out = os.path.join(self.path, name + ".sgy")
        subprocess.run([self.cutaway, "generate-seismic", *options, "--out", out], check=True, stdout=subprocess.DEVNULL)
        return out

    def volume(self, cube, *options, image=None):
        """`cutaway volume CUBE OPTIONS --stats ...`; returns the stats object."""
        stats_path = os.path.join(self.path, "stats.json")
        image = image or os.path.join(self.path, "image.png")
        subprocess.run([self.cutaway, "volume", cube, *options, "--out", image, "--stats", stats_path],
                       check=True, stdout=subprocess.DEVNULL)
        with open(stats_path) as f:
            return json.load(f)


def gl_caster_name(context):
    """The fragment-shader caster's legend name, by what ran it: "GPU caster" only on a GPU; on
    llvmpipe the same shader runs on the CPU, so a plot must not call it a GPU."""
    renderer = str((context or {}).get("gl_renderer", ""))
    if "llvmpipe" in renderer:
        return "GL caster on llvmpipe (a CPU)"
    return "GPU caster" + (f" ({renderer.split('/')[0]})" if renderer else "")


def log_time_axis(ax, times_ms, cx):
    """A log time axis from the 1-2-5 step at or below the fastest time to the one at or above the
    slowest (no empty decade), ticks labelled at 1, 2 and 5 of each decade in plain numbers."""
    import matplotlib.ticker  # after cx.pyplot(), which finds matplotlib

    def step(value, up):
        decade = 10 ** math.floor(math.log10(value))
        steps = [decade * m for m in (1, 2, 5, 10)]
        return min(s for s in steps if s >= value) if up else max(s for s in steps if s <= value)

    ax.set_yscale("log")
    ax.set_ylim(step(min(times_ms), False), step(max(times_ms), True))
    ax.yaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1, 2, 5)))
    ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(cx.plain_number))
    ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())


def frame_times_ms(stats, stages=("exit_points", "ray_cast")):
    """Per-trial render time (sum of the given fenced stages; the CPU caster has only ray_cast)."""
    series = [stats["stages_ms_all"][s] for s in stages if s in stats["stages_ms_all"]]
    return [sum(values) for values in zip(*series)]


def trimmed_mean(values):
    """The paper's protocol: mean after dropping the minimum and the maximum (plain mean below 3)."""
    values = sorted(values)
    if len(values) >= 3:
        values = values[1:-1]
    return statistics.fmean(values)
