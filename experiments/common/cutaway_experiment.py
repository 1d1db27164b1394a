"""Shared plumbing of the experiments: the command line (experiment_options.py), where outputs go,
running `cutaway render` and `bench_cutaway`, machine context, the generated report
(report_markdown.py), and one plot style.

Every experiment script accepts --quick, --force, --report-only, --build DIR, --out DIR and
--data DIR (experiment_options.py says what each does). Full runs write DIR/results/<experiment>/
and DIR/paper_figures/; --quick runs write DIR/results/quick/<experiment>/ and
DIR/paper_figures/quick/ so a smoke test never overwrites the reference results. <experiment> is
the name of the folder holding the script.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import experiment_io as exio
import experiment_options as options
import report_markdown

REPO = exio.REPO
PRESETS = ("zaphirus", "petra", "opharine", "sapphire")
STAGES = ("cut_surface", "culling", "secondary", "primary", "ssao", "mean_filter", "post")
STAGE_LABELS = {"cut_surface": "stage 1: cut surface", "culling": "culling (visible path)", "secondary": "stage 2: secondaries",
                "primary": "stage 3: primaries", "ssao": "SSAO", "mean_filter": "mean filter",
                "post": "composite (post)", "total": "total"}  # their colours: stage_style.COLOURS
write_json = exio.write_json
TOOLS = {"cutaway": "cutaway", "bench": "bench_cutaway", "bench_cut_volumes": "bench_cut_volumes"}


class Experiment:
    """Paths and tools of one experiment run: `name` (the script's folder), `out` (the --out folder), `results` (folder for
    the JSON and README), `figures` (folder for PNGs), `data` (the shared-data folder, checked once
    measuring starts, when `needs_data`), `quick`, `force`, `report_only`, `args`, and the executables in `tools`.
    `data_file` is the JSON the report is generated from; `outputs` the files whose existence
    means the run is done (the README is always one)."""

    def __init__(self, doc, data_file, outputs=(), tools=("cutaway", "bench"), needs_data=False, add_options=None):
        parser = options.add_common_options(argparse.ArgumentParser(description=doc.splitlines()[0]))
        if add_options:
            add_options(parser)
        args = self.args = parser.parse_args()
        self.name = os.path.basename(os.path.dirname(os.path.abspath(sys.modules["__main__"].__file__)))
        self.quick, self.force, self.report_only = args.quick, args.force, args.report_only
        out = self.out = options.output_root(args.out)
        self.results = os.path.join(options.results_base(out, self.quick), self.name)
        self.figures = options.figures_folder(out, self.quick)
        self.needs_data, self.data = needs_data, None
        self.tools = {key: os.path.join(args.build, "bin", TOOLS[key]) for key in tools}
        self.cutaway, self.bench = self.tools.get("cutaway"), self.tools.get("bench")
        self.data_file = data_file
        self.outputs = [self.path(o) for o in (data_file, *outputs, "README.md")]
        self.load_at_start = os.getloadavg()
        # llvmpipe's thread count is part of every timing: set it explicitly and record it.
        os.environ.setdefault("LP_NUM_THREADS", str(os.cpu_count() or 1))

    def path(self, output):
        """results/<name>/FILE for .json/.md/.csv outputs, paper_figures/FILE for images."""
        return os.path.join(self.figures if output.endswith(".png") else self.results, output)

    def up_to_date(self):
        """True (and says so) when every output exists and --force was not given; otherwise checks
        the shared data (when needed) and the tools, and makes the output folders."""
        if not self.force and all(os.path.exists(p) for p in self.outputs):
            print("up to date (use --force to recompute):", ", ".join(exio.shown(p) for p in self.outputs))
            return True
        if self.needs_data:
            self.data = options.data_folder(self.args.data)
        for tool in self.tools.values():
            if not os.access(tool, os.X_OK):
                options.refuse("--build", f"expected {tool} (cmake --build BUILD --target {os.path.basename(tool)}), found none")
        os.makedirs(self.results, exist_ok=True)
        os.makedirs(self.figures, exist_ok=True)
        return False

    def stored(self):
        """The data of an earlier run (the JSON in results/<name>/), or None."""
        path = self.path(self.data_file)
        return exio.read_json(path) if os.path.exists(path) else None

    def run(self, measure, report, draw=None):
        """The experiment's life: --report-only redraws the figures and rewrites the README from the
        stored JSON; otherwise, unless up to date, `measure(self)` returns the document (None: skipped,
        nothing written), written as the JSON, then `draw(self, document)` makes the figures (from the
        document alone, so that --report-only can redraw them) and the README is written.
        `report(self, document)` returns a report_markdown.Report."""
        if self.report_only:
            document = self.stored()
            if document is None:
                options.refuse("--report-only", f"expected the data of an earlier run, found no {exio.shown(self.path(self.data_file))}")
            os.makedirs(self.figures, exist_ok=True)
        elif self.up_to_date():
            return
        else:
            document = measure(self)
            if document is None:
                return
            write_json(self.path(self.data_file), document)
        if draw:
            draw(self, document)
        self.write_report(report(self, document), document)

    def write_report(self, report, document):
        """results/<name>/README.md from `report` and the document's context."""
        path = self.path("README.md")
        with open(path, "w") as f:
            f.write(report_markdown.markdown(report, self.name, document, self.results, self.path(self.data_file)))
        exio.wrote(path)

    def render(self, model, *options, image=None, metrics=False):
        """`cutaway render MODEL OPTIONS`; returns its stats object. `image`: keep the PNG there."""
        with tempfile.TemporaryDirectory(prefix="cutaway-exp-") as scratch:
            stats_path = os.path.join(scratch, "stats.json")
            command = [self.cutaway, "render", model, *map(str, options), "--out", image or os.path.join(scratch, "frame.png"),
                       "--stats", stats_path] + ([] if metrics else ["--no-metrics"])
            subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
            with open(stats_path) as f:
                return json.load(f)

    def inspect(self, model, *options):
        """`cutaway inspect MODEL OPTIONS --json`, parsed."""
        out = subprocess.run([self.cutaway, "inspect", model, *map(str, options), "--json"], check=True,
                             stdout=subprocess.PIPE, text=True).stdout
        return json.loads(out)

    def benchmark(self, *flags, progress=False, tool="bench"):
        """`bench_cutaway FLAGS` (or the Google Benchmark program `tool` names in TOOLS) with JSON
        output; returns the parsed document (context + benchmarks). `progress`: let its console
        table through (one line per finished benchmark), for long runs."""
        with tempfile.TemporaryDirectory(prefix="cutaway-bench-") as scratch:
            out = os.path.join(scratch, "bench.json")
            subprocess.run([self.tools[tool], *map(str, flags), "--benchmark_out=" + out, "--benchmark_out_format=json"],
                           check=True, stdout=None if progress else subprocess.DEVNULL)
            with open(out) as f:
                return json.load(f)

    def context(self, stats=None):
        """Where and how the run was measured (from a render's stats or a benchmark's context), with
        the date and the machine's load average at the start of the run and now (call it once
        the measuring is over)."""
        stats = stats or {}
        return {"gl_renderer": stats.get("gl_renderer"), "lp_num_threads": os.environ.get("LP_NUM_THREADS", "unset"),
                "git_revision": exio.git_revision(), "cpu_count": os.cpu_count(), "cpu_model": cpu_model(),
                "uname": " ".join(os.uname()), "quick": self.quick, "date": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
                "memory_bytes": os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"),
                "load_average_at_start": list(self.load_at_start), "load_average_at_end": list(os.getloadavg())}


def cpu_model():
    """The processor's name as /proc/cpuinfo gives it (llvmpipe's speed depends on it), or "unknown"."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def benchmark_context(document):
    """The benchmark JSON's context, reduced to what results record."""
    keep = ("gl_renderer", "gl_version", "LP_NUM_THREADS", "git_revision", "uname", "resolution", "host_name",
            "num_cpus", "mhz_per_cpu", "camera_path_az_el_aperture_deg", "warmup_passes", "timed_passes",
            "frame_settings", "cutaway_build_type", "date", "strategies", "apertures_deg")
    return {k: v for k, v in document["context"].items() if k in keep}


CPU_PATH_COUNTERS = ("seeds_ms", "gpu_ms", "cpu_path_ms", "transform_speedup", "stage_speedup")


def bench_args(name):
    """The arguments of a benchmark name 'BM_x/key:value/...' as ints."""
    return {k: int(v) for k, v in (part.split(":") for part in name.split("/")[1:] if ":" in part)}


def cpu_path_runs(document):
    """BM_cpu_path rows of a benchmark document (a GPU cone-field strategy against the CPU path it
    replaced) as dicts: preset, primary fraction, strategy and CPU_PATH_COUNTERS."""
    presets = document["context"]["presets"].split(",")
    strategies = document["context"]["strategies"].split(",")
    rows = []
    for bench in document["benchmarks"]:
        if bench["name"].startswith("BM_cpu_path/"):
            a = bench_args(bench["name"])
            rows.append({"preset": presets[a["preset"]], "primary_fraction": a["fraction_bp"] / 10000,
                         "strategy": strategies[a["strategy"]], **{k: bench[k] for k in CPU_PATH_COUNTERS}})
    return rows


def cutaway_runs(document):
    """BM_cutaway rows of a benchmark document as dicts: preset, pose (-1 = path), strategy, primary
    fraction, aperture (degrees, -1 = the path's own), stage ms (fenced), the stages' GL timer-query ms
    where the document has them (gpu_query_ms), counters."""
    presets = document["context"]["presets"].split(",")
    draws = document["context"].get("draws", "visible").split(",")
    strategies = document["context"].get("strategies", "").split(",")
    rows = []
    for bench in document["benchmarks"]:
        if not bench["name"].startswith("BM_cutaway/") or bench.get("error_occurred"):
            continue
        args = bench_args(bench["name"])
        row = {"preset": presets[args["preset"]], "pose": args["pose"], "label": bench.get("label"),
               "draw": draws[args.get("draw", 0)], "strategy": strategies[args.get("strategy", 0)],
               "primary_fraction": args.get("fraction_bp", 0) / 10000, "aperture": args.get("aperture", -1),
               "stages_ms": {s: bench.get(s, 0.0) for s in STAGES + ("total",)},
               "gpu_query_ms": {s: bench["gpu_ms_" + s] for s in STAGES + ("total",) if "gpu_ms_" + s in bench}}
        for key in ("baseline", "total_over_baseline", "primary_cells", "primary_pixels", "cells",
                    "aperture_deg", "faces_secondary", "faces_baseline", "readback_bytes"):
            if key in bench:
                row[key] = bench[key]
        # The timer queries' agreement with the wall clock: gpu_query_valid (gl_query_valid before it).
        for key in ("gpu_query_valid", "gl_query_valid"):
            if key in bench:
                row["gl_query_valid"] = bench[key]
                break
        rows.append(row)
    return rows


def device_label(context):
    """What measured a timing plot, for its title, from the data's context (or a render's stats):
    the GL renderer ("NVIDIA H200"), llvmpipe named as the software rasteriser it is, with the
    thread count and processor the data recorded (never this machine's: plots are redrawn elsewhere)."""
    context = context or {}
    renderer = report_markdown.first(context, "gl_renderer", "gl_renderer_ours") or "GL renderer not recorded"
    if "llvmpipe" not in renderer:
        return renderer.split("/")[0]  # NVIDIA's "NVIDIA H200/PCIe/SSE2": the GPU's name
    threads = report_markdown.first(context, "lp_num_threads", "LP_NUM_THREADS")
    cpus = report_markdown.first(context, "cpu_count", "num_cpus")
    if threads in (None, "unset"):
        threads = f"{cpus} threads (one per CPU)" if threads == "unset" and cpus else "thread count not recorded"
    else:
        threads = f"{threads} threads"
    cpu = report_markdown.first(context, "cpu_model")
    return f"llvmpipe (software rasteriser, {threads}" + (f" on {cpu}" if cpu else "") + "): not a GPU"


# Print size (issue 46): plots are drawn PLOT_WIDTH_IN wide, a journal's double column
# (PRINT_WIDTH_MM), so a point in matplotlib is a point on paper. Capitals and digits of DejaVu
# Sans are 0.73 em tall: 9 pt prints them 2.3 mm tall and lower-case words with an ascender
# (t, d, l) 2.1 mm, above the 2.0 mm (and 7 pt) asked for; 8 pt left such words at 1.9 mm.
PRINT_WIDTH_MM = 182
PLOT_WIDTH_IN = PRINT_WIDTH_MM / 25.4
MIN_PLOT_TEXT_PT = 9


def pyplot():
    """matplotlib.pyplot (Agg) with the experiments' one style: PLOT_WIDTH_IN wide at 150 dpi
    (1075 px), no text below MIN_PLOT_TEXT_PT."""
    plt = exio.require_matplotlib()
    plt.rcParams.update({"figure.figsize": (PLOT_WIDTH_IN, 4), "figure.dpi": 150, "savefig.dpi": 150, "axes.grid": True,
                         "grid.alpha": 0.3, "axes.spines.top": False, "axes.spines.right": False, "font.size": 9,
                         "axes.labelsize": 9, "xtick.labelsize": 9, "ytick.labelsize": 9, "legend.fontsize": 9,
                         "legend.title_fontsize": 9, "axes.titlesize": 10, "figure.titlesize": 10, "lines.markersize": 5})
    return plt


def min_max_bars(centres, samples):
    """matplotlib's yerr for bars from each point's fastest to its slowest sample: `centres` the
    plotted values (medians), `samples` per point the values measured."""
    return [[c - min(s) for c, s in zip(centres, samples)], [max(s) - c for c, s in zip(centres, samples)]]


def print_size_problems(fig):
    """Texts of `fig` that print below MIN_PLOT_TEXT_PT when the figure is PRINT_WIDTH_MM wide."""
    import matplotlib.text
    scale = PRINT_WIDTH_MM / 25.4 / fig.get_figwidth()
    return [f"'{t.get_text()[:40]}' {t.get_fontsize() * scale:.1f} pt" for t in fig.findobj(matplotlib.text.Text)
            if t.get_visible() and t.get_text().strip() and t.get_fontsize() * scale < MIN_PLOT_TEXT_PT - 1e-6]


def plain_number(value, _position=None):
    """A log axis' tick label without a superscript (mathtext prints exponents at 70% of the
    size): 0.1, 1, 10, 100, 1k, 10k, 100k, 1M, ..."""
    for factor, suffix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if abs(value) >= factor:
            return f"{value / factor:g}{suffix}"
    return f"{value:g}"


def save_figure(fig, path):
    """Lays the figure out (room kept below the axes for figure legends, placed "lower center"),
    labels log axes with plain numbers, says which texts print too small, and writes it as PNG and,
    beside it, as vector PDF (for print)."""
    import matplotlib.ticker
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if axis.get_scale() == "log":
                axis.set_major_formatter(matplotlib.ticker.FuncFormatter(plain_number))
                axis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    renderer = fig.canvas.get_renderer()
    below = max((legend.get_window_extent(renderer).height / fig.bbox.height for legend in fig.legends), default=0)
    fig.tight_layout(rect=(0, below + (0.01 if below else 0), 1, 1))
    problems = print_size_problems(fig)
    if problems:
        print(f"{exio.shown(path)}: text below {MIN_PLOT_TEXT_PT} pt at {PRINT_WIDTH_MM} mm: " + "; ".join(problems[:5])
              + (f" and {len(problems) - 5} more" if len(problems) > 5 else ""), file=sys.stderr)
    fig.savefig(path)
    fig.savefig(os.path.splitext(path)[0] + ".pdf")
    exio.wrote(path)
