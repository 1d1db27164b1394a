#!/usr/bin/python3
"""Results of scripts/device-benchmarks.sh on a lent GPU machine, as results/device-<gpu>/.

  experiments/device/report.py RUN_DIR [RUN_DIR ...]
  experiments/device/report.py results/device-<gpu>     (the report and plot again from the files there)
RUN_DIR: the files one device call brought back (a later folder's file replaces an earlier one of
the same name; the calls' device.log files are joined). Copies the raw outputs (benchmark JSON,
render stats, scale.jsonl, context.txt, device.log, the GL test log, the rendered frame) into
results/device-<gpu>/ and writes its README.md: the paper's Table 1 on that GPU (experiments/table1's
protocol), the main job's frame against the plain frame and against drawing every face (the
paper's path), GPU jump flooding against the CPU path it replaced, stage 1 of every cut strategy
per model and primary fraction (with a plot, also drawn as paper_figures/cut_strategies_time_<gpu>.png), one frame per model from 1M to 100M cells with wall
time and memory, stage times fenced beside the GL timer queries, the seismic ray casters
(bench_volume, Duan & Li's figures 7 and 8), and the GL tests' summary. Every ratio is between two
configurations of the same call on the same GPU. Measures nothing itself.
"""
import json
import os
import shutil
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import strategy_style  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "volume_common"))
import volume_experiment as vx  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "table1"))
import table1_report  # noqa: E402
from run import PAPER_MS  # noqa: E402  (experiments/table1/run.py: the paper's Table 1)

RAW = ("context.txt", "device.log", "render_sapphire.json", "render_sapphire.png", "bench_table1.json", "bench_cpu_path.json",
       "bench_main.json", "bench_cut_strategies.json", "scale.jsonl", "gl_tests.log",
       "orbit_petra_720p.jsonl", "bench_volume.json", "volume.jsonl")
# Duan & Li's figure 7 (experiments/volume_fig7/run.py's PAPER: ms per frame over the 10 eyes).
PAPER_FIG7_MEAN_MS = {"gpu": 14.99, "cpu": 9486}
QUERY_NOTE = ("Fenced: wall clock between two glFinish calls; query: GL_TIME_ELAPSED of the same commands; "
              "medians over the timed frames. Queries agree: every query of every timed frame was within the "
              "wall clock's bounds (gl::query_agrees). On llvmpipe the queries mostly disagree (SPEC.md section 5: "
              "they do not time a software rasteriser's draws), so there a \"no\" is expected and the fenced time is "
              "the measurement; on a GPU a \"no\" marks a stage whose query is not to be read.")
CUT_COLUMNS = ("frustum", "frustum-clusters", "frustum-sweep", "chamfer-5x5", "jfa", "jfa2")


def gather(run_dirs):
    """{file name: path} over the run folders, later ones first."""
    found = {}
    for folder in run_dirs:
        for name in RAW:
            if os.path.exists(os.path.join(folder, name)):
                found[name] = os.path.join(folder, name)
    return found


def load_json(path):
    with open(path) as f:
        return json.load(f)


def gpu_name(files):
    with open(files["context.txt"]) as f:
        lines = f.read().splitlines()
    return lines[1].split(",")[0].strip()  # nvidia-smi's csv: header, then "NAME, driver, ..."


def ms(value):
    return f"{value:,.1f}" if value < 100 else f"{value:,.0f}"


def context_section(files, documents):
    with open(files["context.txt"]) as f:
        context = f.read().strip()
    lines = ["## Machine", "", "```", context, "```", ""]
    for name, document in documents.items():
        c = cx.benchmark_context(document)
        lines.append(f"- `{name}`: {c.get('gl_renderer')}, {c.get('gl_version')}, platform "
                     f"{document['context'].get('gl_platform')}, git {c.get('git_revision')}, {c.get('date')}, "
                     f"{c.get('resolution')}, {c.get('warmup_passes')} warm-up + {c.get('timed_passes')} timed passes per pose")
    return lines + [""]


def main_job_section(document):
    """The main job (bench_cutaway defaults: 1% PORO primaries, 9x9 mean filter, SSAO, 8 poses)
    per model: visible faces against every face, and against the plain frame."""
    runs = [r for r in cx.cutaway_runs(document) if r["pose"] == -1]
    baselines = {b["label"]: b["real_time"] for b in document["benchmarks"] if b["name"].startswith("BM_baseline/")}
    lines = ["## The main job against the plain frame and the paper's path", "",
             "`bench_cutaway` defaults (1% PORO primaries, 9x9 mean filter, SSAO, ray-cast borders, the 8-pose camera "
             "path), medians of 8 poses x 3 frames. `visible`: stage 2 draws the faces the GPU culling keeps; "
             "`all-faces`: every face of every cell (the paper's path). Plain frame: `BM_baseline` (exposed faces, "
             "shaded, same poses).", "",
             "| model | cut strategy | cutaway ms (visible) | fps | all-faces ms | all-faces / visible | plain frame ms | "
             "cutaway / plain | stage 2 faces visible / all |", "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    keyed = {(r["preset"], r["strategy"], r["draw"]): r for r in runs}
    for (preset, strategy, draw), r in keyed.items():
        if draw != "visible" or strategy != "frustum-clusters":
            continue
        every = keyed.get((preset, strategy, "all-faces"))
        total, base = r["stages_ms"]["total"], baselines.get(preset)
        lines.append(f"| {preset} | {strategy} | {ms(total)} | {1000 / total:.0f} | {ms(every['stages_ms']['total'])} | "
                     f"{every['stages_ms']['total'] / total:.2f} | {ms(base)} | {total / base:.1f} | "
                     f"{int(r['faces_secondary']):,} / {int(every['faces_secondary']):,} |")
    lines += ["", "The same, every strategy, cutaway ms with visible faces (stage 1 in brackets):", "",
              "| model | " + " | ".join(document["context"]["strategies"].split(",")) + " |",
              "|---|" + "---:|" * len(document["context"]["strategies"].split(","))]
    for preset in document["context"]["presets"].split(","):
        cells = []
        for strategy in document["context"]["strategies"].split(","):
            r = keyed.get((preset, strategy, "visible"))
            cells.append(f"{ms(r['stages_ms']['total'])} ({ms(r['stages_ms']['cut_surface'])})" if r else "-")
        lines.append(f"| {preset} | " + " | ".join(cells) + " |")
    return lines + [""]


def table1_section(document):
    """The paper's Table 1 on this GPU (experiments/table1's protocol and report)."""
    runs = cx.cutaway_runs(document)
    tables = {draw: table1_report.build_table({r["preset"]: r for r in runs if r["draw"] == draw}, PAPER_MS)
              for draw in ("all-faces", "visible")}
    observations = table1_report.observations(tables["all-faces"])
    context = cx.benchmark_context(document)
    text = table1_report.markdown(tables["all-faces"], observations, context, context.get("resolution"), 8)
    text = text.replace("# Table 1", "## Table 1", 1).replace("Generated by experiments/table1/run.py",
                                                              "experiments/table1/run.py's protocol (5 frames per pose)")
    text += table1_report.visible_markdown(tables["visible"], tables["all-faces"]).replace("\n## ", "\n### ")
    return text.splitlines() + [""]


def cpu_path_section(document):
    lines = ["## GPU jump flooding against the CPU path it replaced", "",
             "`BM_cpu_path` (aperture 60 degrees, 2 poses x 3 frames, interleaved): seed pass alone, the GPU strategy "
             "(seed pass, compute passes, resolve), and the CPU path (seed pass, 8.3 MB read-back, single-threaded CPU "
             "transform, upload). Transform speedup = (CPU path - seeds) / (GPU - seeds).", "",
             "| model | fraction | strategy | seeds ms | GPU ms | CPU path ms | transform speedup | stage speedup |",
             "|---|---:|---|---:|---:|---:|---:|---:|"]
    rows = cx.cpu_path_runs(document)
    speedups = [r["transform_speedup"] for r in rows if r["strategy"] == "jfa"]
    for r in rows:
        lines.append(f"| {r['preset']} | {r['primary_fraction'] * 100:g}% | {r['strategy']} | {ms(r['seeds_ms'])} | "
                     f"{ms(r['gpu_ms'])} | {ms(r['cpu_path_ms'])} | {r['transform_speedup']:.0f}x | {r['stage_speedup']:.0f}x |")
    if speedups:
        lines += ["", f"GPU `jfa` transform against the CPU path: {min(speedups):.0f}-{max(speedups):.0f}x "
                      f"(median {statistics.median(speedups):.0f}x) over {len(speedups)} configurations."]
    return lines + [""]


def cut_strategies_section(document):
    runs = {(r["preset"], r["primary_fraction"], r["strategy"]): r for r in cx.cutaway_runs(document)}
    readback = sorted({int(r.get("readback_bytes", 0)) for r in runs.values()})
    lines = ["## Cut strategies: stage 1 per model and primary fraction", "",
             "experiments/cut_strategies' timing sweep (aperture 60 degrees, mean filter and SSAO off, 2 poses x 5 "
             "frames, median `cut_surface` ms: seed pass, transform or frustums, resolve). In brackets: frustum ms / "
             f"strategy ms (> 1: cheaper than the paper's per-cell frustum union). Read-back per frame over every row: "
             f"{', '.join(str(b) for b in readback)} bytes.", "",
             "| model | fraction | primaries | " + " | ".join(CUT_COLUMNS) + " |", "|---|---:|---:|" + "---:|" * len(CUT_COLUMNS)]
    keys = sorted({(p, f) for p, f, _ in runs}, key=lambda k: runs[(k[0], k[1], "frustum")]["primary_cells"])
    for preset, fraction in keys:
        frustum = runs[(preset, fraction, "frustum")]["stages_ms"]["cut_surface"]
        cells = []
        for strategy in CUT_COLUMNS:
            t = runs[(preset, fraction, strategy)]["stages_ms"]["cut_surface"]
            cells.append(ms(t) if strategy == "frustum" else f"{ms(t)} ({frustum / t:.1f})")
        lines.append(f"| {preset} | {fraction * 100:g}% | {int(runs[(preset, fraction, 'frustum')]['primary_cells']):,} | "
                     + " | ".join(cells) + " |")
    return lines + [""]


def plot_cut_strategies(document, gpu, path):
    """Stage 1 of every strategy against primary cells, one panel per model (the layout, colours
    and markers of experiments/cut_strategies' plot: experiments/common/strategy_style.py)."""
    plt = cx.pyplot()
    points = [(r["preset"], r["strategy"], r["primary_cells"], r["stages_ms"]["cut_surface"]) for r in cx.cutaway_runs(document)]
    fig = strategy_style.times_per_model(plt, points, f"Stage 1 (cut surface) of every strategy, "
                                         f"{cx.benchmark_context(document).get('resolution')}, aperture 60 deg\non an {gpu}",
                                         "stage 1 ms (median, log scale)")
    cx.save_figure(fig, path)
    plt.close(fig)


def fenced_and_query(bench, stage):
    """"fenced / query" ms of a stage in a benchmark row ("-" where the row lacks it)."""
    if stage not in bench:
        return "-"
    query = bench.get("gpu_ms_" + stage)
    return ms(bench[stage]) + (" / " + ms(query) if query is not None else "")


def agrees(bench):
    return {1: "yes", 0: "no"}.get(bench.get("gpu_query_valid"), "-")


def query_section(document):
    """The main job's stages per model (visible faces, frustum-clusters), fenced beside the GL timer
    queries (bench_cutaway's gpu_ms_<stage> counters; absent in documents from before them)."""
    rows = [b for b in document["benchmarks"] if b["name"].startswith("BM_cutaway/") and "gpu_query_valid" in b
            and not b.get("error_occurred")]
    if not rows:
        return []
    runs = {(r["preset"], r["strategy"], r["draw"]): r for r in cx.cutaway_runs(document)}
    stages = cx.STAGES + ("total",)
    lines = ["## Stage times: fenced against the GL timer queries", "",
             "`bench_main.json`, visible faces, `frustum-clusters`: each stage as fenced ms / timer-query ms. " + QUERY_NOTE,
             "", "| model | " + " | ".join(stages) + " | queries agree |", "|---|" + "---:|" * len(stages) + "---|"]
    for bench in rows:
        args = cx.bench_args(bench["name"])
        run = runs.get((document["context"]["presets"].split(",")[args["preset"]],
                        document["context"]["strategies"].split(",")[args["strategy"]],
                        document["context"].get("draws", "visible").split(",")[args.get("draw", 0)]))
        if run is None or run["strategy"] != "frustum-clusters" or run["draw"] != "visible":
            continue
        lines.append(f"| {run['preset']} | " + " | ".join(fenced_and_query(bench, s) for s in stages) + f" | {agrees(bench)} |")
    return lines + [""]


def volume_bench_section(document):
    """bench_volume: the casters on the paper's cube, the GPU's stages fenced beside their queries."""
    stages = ("exit_points", "ray_cast", "readback")
    context = document["context"]
    lines = ["## Seismic ray casting: bench_volume", "",
             f"`bench_volume.json`: cube {context.get('volume_dims')}, {context.get('image_size')} pixels, CPU caster "
             f"with {context.get('cpu_threads')} threads. Time: the GPU's fenced `ray_cast` stage, the CPU's whole cast. "
             "GPU stages as fenced ms / timer-query ms. " + QUERY_NOTE, "",
             "| benchmark | ms per frame | M samples/s | " + " | ".join(stages) + " | queries agree |",
             "|---|---:|---:|" + "---:|" * len(stages) + "---|"]
    for bench in document["benchmarks"]:
        if bench.get("error_occurred"):
            continue
        lines.append(f"| {bench['name'].split('/iterations')[0].removesuffix('/manual_time')} | {ms(bench['real_time'])} | "
                     f"{bench['samples_per_second'] / 1e6:,.0f} | " + " | ".join(fenced_and_query(bench, s) for s in stages)
                     + f" | {agrees(bench)} |")
    return lines + [""]


def volume_figures_section(path):
    """Duan & Li's figures 7 and 8 from volume.jsonl (experiments/volume_fig7 and volume_fig8's
    commands and statistic: the median of the timed frames; the paper's numbers are means)."""
    with open(path) as f:
        rows = [json.loads(line) for line in f if line.strip()]
    fig7 = [r for r in rows if r["figure"] == 7]
    fig8 = [r for r in rows if r["figure"] == 8]
    lines = ["## Seismic figures 7 and 8 (Duan & Li)", "",
             "`volume.jsonl`: `cutaway volume` at 512x512, grey transfer function, one warm-up frame, with the volume "
             "experiments' cubes, views and frame counts; a frame's time is the fenced exit points + ray cast stages, "
             "the median of the timed frames as the experiments report it (the paper's numbers are means after dropping "
             "the minimum and the maximum). Query: the same stages' "
             "GL timer queries (medians); queries agree: every stage's query agreed with its fenced time.", ""]
    if fig7:
        lines += ["### Figure 7: paper-250 cube (101x101x250), 10 eyes at elevation 25", "",
                  "| azimuth | GPU median ms | GPU query ms | GPU queries agree | CPU median ms | CPU / GPU |", "|---:|---:|---:|---|---:|---:|"]
        eyes = {}
        for r in fig7:
            eyes.setdefault(r["azimuth_deg"], {})[r["caster"]] = r
        medians = {"gpu": [], "cpu": []}
        for azimuth, by_caster in sorted(eyes.items()):
            gpu, cpu = by_caster.get("gpu"), by_caster.get("cpu")
            if gpu is None or cpu is None:
                continue
            gpu_ms, cpu_ms = statistics.median(vx.frame_times_ms(gpu)), statistics.median(vx.frame_times_ms(cpu))
            medians["gpu"].append(gpu_ms)
            medians["cpu"].append(cpu_ms)
            query = sum(v for k, v in gpu["gl_query_ms"].items() if k in ("exit_points", "ray_cast"))
            lines.append(f"| {azimuth} | {ms(gpu_ms)} | {ms(query)} | {'yes' if gpu['gl_query_valid'] else 'no'} | "
                         f"{ms(cpu_ms)} | {cpu_ms / gpu_ms:.0f} |")
        if medians["gpu"]:
            lines += ["", "Median over the eyes: GPU " + ms(statistics.median(medians["gpu"])) + " ms, CPU "
                      + ms(statistics.median(medians["cpu"])) + f" ms (CPU caster: {fig7[-1]['configuration']['cpu_threads']} "
                      f"threads); the paper's means: GPU {PAPER_FIG7_MEAN_MS['gpu']} ms, CPU {PAPER_FIG7_MEAN_MS['cpu']} ms.", ""]
    if fig8:
        lines += ["### Figure 8: GPU caster as the cube grows (step k = 1..10: k x 10 inlines, k x 28 crosslines, "
                  "k x 25 time samples), azimuth 40", "",
                  "| step | dims | M voxels | median ms per frame | query ms | queries agree | M samples/s |",
                  "|---:|---|---:|---:|---:|---|---:|"]
        for r in sorted(fig8, key=lambda r: r["step"]):
            dims = r["input"]["dims"]
            query = sum(v for k, v in r["gl_query_ms"].items() if k in ("exit_points", "ray_cast"))
            lines.append(f"| {r['step']} | {'x'.join(map(str, dims))} | {dims[0] * dims[1] * dims[2] / 1e6:.2f} | "
                         f"{ms(statistics.median(vx.frame_times_ms(r)))} | {ms(query)} | "
                         f"{'yes' if r['gl_query_valid'] else 'no'} | {r['samples_per_second'] / 1e6:,.0f} |")
        lines.append("")
    return lines


def scale_section(path):
    with open(path) as f:
        rows = [json.loads(line) for line in f if line.strip()]
    lines = ["## One frame per model, 1M to 100M cells", "",
             "`cutaway render preset:NAME` at 1920x1080 with the main job's settings, 1 warm-up and 3 timed frames "
             "(stats: medians), as in experiments/scale. Wall: the whole command (model generated in memory on the "
             "CPU, renderer set-up, 4 frames). Peak: the process's peak resident set per active cell.", "",
             "| model | cut strategy | active cells | frame ms | cut surface ms | culling ms | stage 2 ms | stage 3 ms | "
             "generate s | set-up s | wall s | GPU buffers MB | peak bytes / active cell |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for s in rows:
        st, m, cells = s["stages_ms"], s["memory_bytes"], s["active_cells"]
        lines.append(f"| {s['model'].split()[0].removeprefix('preset:')} | {s['strategy']['name']} | {cells:,} | "
                     f"{ms(st['total'])} | {ms(st['cut_surface'])} | {ms(st['culling'])} | {ms(st['secondary'])} | "
                     f"{ms(st['primary'])} | {s['model_load_s']:.1f} | {s['renderer_setup_s']:.1f} | "
                     f"{s['command_wall_s']:.1f} | {m['gpu_buffers'] / 2**20:,.0f} | {m['peak_resident'] / cells:.0f} |")
    return lines + [""]


def orbit_section(path):
    """The renderer's frame along the viewer experiment's camera path (petra, 1280x720)."""
    with open(path) as f:
        rows = [json.loads(line) for line in f if line.strip()]
    totals = [r["stages_ms"]["total"] for r in rows]
    unfenced = [r["frame_ms_unfenced"] for r in rows]
    stages = {s: statistics.median(r["stages_ms"][s] for r in rows) for s in rows[0]["stages_ms"] if s != "total"}
    median = statistics.median(totals)
    return ["## The viewer's camera path on petra at 1280x720", "",
            f"`orbit_petra_720p.jsonl`: `cutaway render preset:petra --size 1280 720` at each of the {len(rows)} poses of "
            "experiments/viewer_responsiveness (turns of 15 degrees from azimuth 35 at elevation 30, primary range "
            f"0.325-0.4: {int(rows[0]['primary_cells']):,} primaries; the main job's settings), 2 warm-up and 5 timed frames "
            "per pose. The lent machine has no display, so this is the renderer's frame without the viewer's window, "
            "panel and swap.", "",
            f"- frame (stats total, fenced), median over the poses: {ms(median)} ms ({1000 / median:.0f} frames per "
            f"second); poses' medians {ms(min(totals))}-{ms(max(totals))} ms",
            f"- the same frame with one fence at its end (`frame_ms_unfenced`): median {ms(statistics.median(unfenced))} ms",
            "- stages, medians over the poses: " + ", ".join(f"{s} {ms(t)}" for s, t in stages.items()) + " ms", ""]


def gl_tests_section(path):
    """The GL test binaries run on this GPU (their gtest summary and failures, from the log)."""
    with open(path) as f:
        lines = f.read().splitlines()
    keep = [line for line in lines if line.startswith(("[  PASSED", "[  FAILED", "[==========]")) or " exit " in line
            or "Failure" in line or "Expected" in line or "identity:" in line]
    return ["## The GL tests on this GPU", "",
            "`gl_tests.log`: `cutaway_gl_tests` and `volume_tests` (the build's test binaries, the real data of "
            "shared/data carried along) run on this GPU's driver. Their summary, failures and identity counts:", "",
            "```", *keep, "```", ""]


def render_section(stats):
    return ["## The main job's frame on this driver", "",
            f"`render_sapphire.png` / `.json`: `cutaway render preset:sapphire --baseline`, metrics on: "
            f"{stats['primary_cells']:,} primaries, primary exposure {stats['primary_exposure']:.4f}, secondary pixels in "
            f"front of the cut {stats['secondary_pixels_in_front_of_cut']}, read-back {stats['readback_bytes']} bytes per frame; "
            f"frame {ms(stats['stages_ms']['total'])} ms against the plain frame's {ms(stats['baseline_ms'])} ms "
            f"(medians of {stats['repeat']}).", ""]


def copy_raw(files, out):
    """The run folders' raw outputs into `out`, their device.log files joined in call order."""
    os.makedirs(out, exist_ok=True)
    for name, path in files.items():
        if name != "device.log" and os.path.realpath(os.path.dirname(path)) != os.path.realpath(out):
            shutil.copyfile(path, os.path.join(out, name))
    logs = []
    for folder in sys.argv[1:]:
        if os.path.exists(os.path.join(folder, "device.log")):
            with open(os.path.join(folder, "device.log")) as f:
                logs.append(f"### call {os.path.basename(os.path.normpath(folder))}\n" + f.read())
    with open(os.path.join(out, "device.log"), "w") as log:
        log.write("".join(logs))


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    files = gather(sys.argv[1:])
    if "context.txt" not in files:
        raise SystemExit("no context.txt in " + ", ".join(sys.argv[1:]) + ": not a device-benchmarks.sh output folder")
    gpu = gpu_name(files)
    out = os.path.join(cx.REPO, "results", "device-" + gpu.lower().replace(" ", "-"))
    if any(os.path.realpath(folder) != os.path.realpath(out) for folder in sys.argv[1:]):
        copy_raw(files, out)
    documents = {n: load_json(files[n]) for n in ("bench_table1.json", "bench_main.json", "bench_cpu_path.json",
                                                  "bench_cut_strategies.json")
                 if n in files}
    lines = [f"# cutaway on an {gpu} (generated by experiments/device/report.py; do not edit)", "",
             "Measured with scripts/device-benchmarks.sh on a machine lent for one session (binaries built on Debian 12, "
             "run there with their libraries carried). The EGL platform of each run is listed below (before 3a59d19 the "
             "device platform went unrecognised and NVIDIA's driver served the surfaceless one). Times are "
             "fenced wall-clock medians; GL timer queries are kept beside them in the JSON. Compare ratios within one "
             "table (one process, same GPU); the llvmpipe results elsewhere in results/ come from another machine.", ""]
    lines += context_section(files, documents)
    if "render_sapphire.json" in files:
        lines += render_section(load_json(files["render_sapphire.json"]))
    if "bench_table1.json" in documents:
        lines += table1_section(documents["bench_table1.json"])
    if "bench_main.json" in documents:
        lines += main_job_section(documents["bench_main.json"])
        lines += query_section(documents["bench_main.json"])
    if "bench_cpu_path.json" in documents:
        lines += cpu_path_section(documents["bench_cpu_path.json"])
    if "bench_cut_strategies.json" in documents:
        lines += cut_strategies_section(documents["bench_cut_strategies.json"])
        plot_cut_strategies(documents["bench_cut_strategies.json"], gpu, os.path.join(out, "cut_strategies.png"))
        # The gallery's GPU timing figure beside its llvmpipe one (cut_strategies_time.png), named by its GPU.
        gallery = os.path.join(cx.REPO, "paper_figures", f"cut_strategies_time_{os.path.basename(out)[len('device-'):]}.png")
        plot_cut_strategies(documents["bench_cut_strategies.json"], gpu, gallery)
        lines += ["![stage 1 per strategy against primary cells](cut_strategies.png)", "",
                  f"The same plot is in the gallery as `paper_figures/{os.path.basename(gallery)}`.", ""]
    if "scale.jsonl" in files:
        lines += scale_section(files["scale.jsonl"])
    if "orbit_petra_720p.jsonl" in files:
        lines += orbit_section(files["orbit_petra_720p.jsonl"])
    if "bench_volume.json" in files:
        lines += volume_bench_section(load_json(files["bench_volume.json"]))
    if "volume.jsonl" in files:
        lines += volume_figures_section(files["volume.jsonl"])
    if "gl_tests.log" in files:
        lines += gl_tests_section(files["gl_tests.log"])
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write("\n".join(lines))
    print("wrote", os.path.relpath(out, cx.REPO))


if __name__ == "__main__":
    main()
