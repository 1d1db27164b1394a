"""Shared plumbing of the volume experiments (volume_fig7, volume_fig8, volume_renders).

Each experiment script accepts:
  --quick        tiny sizes and few trials (finishes in well under a minute)
  --force        recompute even when the outputs already exist (otherwise it skips)
  --build DIR    build folder holding bin/cutaway (default: <repo>/build)
and writes JSON to results/volume/ and figures to paper_figures/, printing the paths.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
# --quick is a smoke test: its outputs go to results/quick/ and paper_figures/quick/ so it never
# overwrites the reference results (decided before the paths are used, hence from sys.argv).
QUICK = "--quick" in sys.argv[1:]
RESULTS = os.path.join(REPO, "results", "quick", "volume") if QUICK else os.path.join(REPO, "results", "volume")
FIGURES = os.path.join(REPO, "paper_figures", "quick") if QUICK else os.path.join(REPO, "paper_figures")


def require_matplotlib():
    """matplotlib.pyplot with the Agg backend; re-runs the script under /usr/bin/python3 (where
    Debian's python3-matplotlib lives) when the python3 on PATH lacks it."""
    try:
        import matplotlib
    except ImportError:
        system = "/usr/bin/python3"
        if os.path.realpath(sys.executable) != os.path.realpath(system) and os.path.exists(system):
            os.execv(system, [system] + sys.argv)
        raise SystemExit("matplotlib is missing: apt-get install python3-matplotlib (scripts/install-deps.sh)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def parse_args(description):
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--quick", action="store_true", help="tiny sizes, few trials (< 1 minute)")
    parser.add_argument("--force", action="store_true", help="recompute even if the outputs exist")
    parser.add_argument("--build", default=os.path.join(REPO, "build"), help="build folder with bin/cutaway")
    args = parser.parse_args()
    args.cutaway = os.path.join(args.build, "bin", "cutaway")
    if not os.access(args.cutaway, os.X_OK):
        raise SystemExit(f"{args.cutaway}: not built (cmake --build {args.build} --target cutaway)")
    os.makedirs(RESULTS, exist_ok=True)
    os.makedirs(FIGURES, exist_ok=True)
    # llvmpipe's thread count is part of every timing: set it explicitly and record it.
    os.environ.setdefault("LP_NUM_THREADS", str(os.cpu_count() or 1))
    return args


def outputs_exist(args, paths):
    """True (and says so) when every output exists and --force was not given."""
    if not args.force and all(os.path.exists(p) for p in paths):
        print("up to date (use --force to recompute):", ", ".join(os.path.relpath(p, REPO) for p in paths))
        return True
    return False


def begin(doc, outputs):
    """Parses the command line (description: the script's first doc line); None when `outputs`
    (paths) all exist and --force was not given, else the arguments."""
    args = parse_args(doc.splitlines()[0])
    return None if outputs_exist(args, outputs) else args


def git_revision():
    try:
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "HEAD"], capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no", "--", ".", ":!results",
                                ":!paper_figures"],
                               capture_output=True, text=True).stdout.strip()
        return head + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def machine_context(stats):
    """Where and how a run was measured; `stats` is one `cutaway volume --stats` object."""
    return {"gl_renderer": stats.get("gl_renderer"), "lp_num_threads": os.environ.get("LP_NUM_THREADS", "unset"),
            "git_revision": git_revision(), "cpu_count": os.cpu_count(), "uname": " ".join(os.uname())}


class Workspace:
    """A scratch folder for generated cubes and per-run stats, removed afterwards."""

    def __init__(self, args):
        self.args = args
        self.path = tempfile.mkdtemp(prefix="cutaway-volume-")

    def __enter__(self):
        return self

    def __exit__(self, *_):
        shutil.rmtree(self.path, ignore_errors=True)

    def generate(self, name, *options):
        """`cutaway generate-seismic OPTIONS --out NAME.sgy`; returns the path."""
        out = os.path.join(self.path, name + ".sgy")
        subprocess.run([self.args.cutaway, "generate-seismic", *options, "--out", out], check=True, stdout=subprocess.DEVNULL)
        return out

    def volume(self, cube, *options, image=None):
        """`cutaway volume CUBE OPTIONS --stats ...`; returns the stats object."""
        stats_path = os.path.join(self.path, "stats.json")
        image = image or os.path.join(self.path, "image.png")
        subprocess.run([self.args.cutaway, "volume", cube, *options, "--out", image, "--stats", stats_path],
                       check=True, stdout=subprocess.DEVNULL)
        with open(stats_path) as f:
            return json.load(f)


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


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")
    print("wrote", os.path.relpath(path, REPO))
