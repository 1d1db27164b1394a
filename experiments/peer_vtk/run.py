#!/usr/bin/python3
"""Peer comparison: our plain and cutaway frames against VTK 9.1 on the same grids, camera and size.

Interface (for experiments/run_all):
  experiments/peer_vtk/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/peer_vtk/peer_vtk.json (every round's numbers, the configuration, the model checks,
the machine context of both sides) and results/peer_vtk/README.md (the table), plus the camera
check images camera_check_<model>_{vtk,ours}.png beside them. Skips when both outputs exist unless
--force. --quick: 480x270, 3 timed frames, 1 round (results/quick/peer_vtk/). Needs python3-vtk9,
Xvfb and numpy/matplotlib for /usr/bin/python3 (scripts/install-deps.sh).

Protocol:
- Models: `cutaway generate --preset NAME --seed 1` (what preset:NAME renders) written to a GRDECL
  file in a scratch folder; both sides read that file. The VTK side reads it with a numpy GRDECL
  reader (grdecl_vtk.py) into hexahedra of the active cells, checked against `cutaway inspect
  --json` (active cells equal, volume within tolerance) before anything is timed.
- Camera: our default orbit pose (azimuth 35, elevation 30 degrees), the framing distance computed
  as `--camera AZ EL 0` computes it (orbit_camera.py) and passed explicitly to both sides; vertical
  fov 30 degrees; same near/far planes. Checked by the bounding boxes of the model's pixels in one
  image of each side (camera_check in the JSON).
- VTK (vtk_worker.py, offscreen W x H window without multisampling, as ours, on one Xvfb display
  kept for the whole run, GLX on Mesa llvmpipe): "surface"
  (vtkDataSetSurfaceFilter, PORO cell colours, cell edges; executes once) and "clip" (per frame
  vtkTableBasedClipDataSet by the plane through the centre facing the camera, then the surface
  filter; re-executed every frame, its time included). Frame = wall clock around Render() +
  WaitForCompletion() (glFinish).
- Ours: `cutaway render FILE --camera AZ EL DIST --size W H --baseline` with the main job's
  settings (scripts/run-main.sh: 1% primaries by PORO, 9x9 mean filter, SSAO on, ray-cast
  borders); `baseline_ms` is the plain frame, `stages_ms.total` the cutaway frame (fenced wall
  clock medians). Once per configuration (CONFIGURATIONS: default, per-cell frustum, paper path).
- Rounds interleave the sides (VTK surface + clip, then ours per draw mode, repeated); each round
  gives medians over its timed frames after warm-up; reported: median over rounds, min, max, and
  ours/VTK ratios (plain frame vs surface, cutaway vs clip), of the medians and round by round.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import x_server  # noqa: E402
import peer_report  # noqa: E402

SYSTEM_PYTHON = "/usr/bin/python3"  # where Debian's python3-vtk9 lives
WORKER = os.path.join(HERE, "vtk_worker.py")
XVFB_SCREEN = "1920x1080x24"  # one Xvfb for the whole run (experiments/common/x_server.py)
VTK_ATTEMPTS = 3  # a worker refused by the X server is run again (each failure is logged)
MODELS = ("petra", "sapphire")
SEED = 1  # generator_parameters.h default: the seed preset:NAME renders with
DEFAULT_POSE = (35.0, 30.0)  # render_options.h: --camera 35 30 0
PAPER_FLAGS = ("--primary-fraction", "0.01", "--mean-filter", "9", "--ssao", "on", "--border", "raycast")
# Ours, by name (the column "draw" of the table): the default renderer (visible faces, the default
# cut strategy "auto": one frustum per IJK box of adjacent primaries, or their union swept in
# O(pixels) from the device's threshold on, cut_strategy_choice.h), the same with the paper's one frustum per primary, and the
# paper's path (every face of every cell, one frustum per primary).
CONFIGURATIONS = (("visible", ()), ("visible, per-cell frustum", ("--strategy", "frustum")),
                  ("all-faces, per-cell frustum (paper)", ("--draw", "all-faces", "--strategy", "frustum")))
# Volume agreement of the VTK grid with `cutaway inspect` (relative): the numpy trilinear volume is
# the same formula as ours (only rounding differs); vtkMeshQuality's hexahedron volume and
# vtkCellSizeFilter's (tetrahedra) approximate a trilinear cell with non-planar faces.
VOLUME_TOLERANCE = {"trilinear_numpy": 1e-9, "vtk_mesh_quality_hex_volume": 1e-4, "vtk_cell_size_filter": 1e-3}
CAMERA_TOLERANCE_PX = 0.01  # of the image width: bounding boxes of the model's pixels on both sides


def protocol(quick):
    """Image size (px), warm-up and timed frames per side, and interleaved rounds."""
    if quick:
        return {"size": [480, 270], "vtk_warmup": 1, "vtk_repeat": 3, "ours_warmup": 1, "ours_repeat": 3, "rounds": 1}
    return {"size": [1920, 1080], "vtk_warmup": 2, "vtk_repeat": 5, "ours_warmup": 1, "ours_repeat": 5, "rounds": 5}


def configurations():
    """Our configurations, by name: flags added to PAPER_FLAGS."""
    return dict(CONFIGURATIONS)


def run_json(command, out_path, **kwargs):
    """Runs `command` (which writes JSON to `out_path`); returns the parsed file."""
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, **kwargs)
    with open(out_path) as f:
        return json.load(f)


def generate(exp, preset, scratch):
    """`cutaway generate --preset PRESET --seed SEED` into the scratch folder; returns the path."""
    path = os.path.join(scratch, preset + ".grdecl")
    subprocess.run([exp.cutaway, "generate", "--preset", preset, "--seed", str(SEED), "--quiet", "--out", path],
                   check=True, stdout=subprocess.DEVNULL)
    return path


def inspect(exp, grdecl):
    """`cutaway inspect FILE --json`."""
    result = subprocess.run([exp.cutaway, "inspect", grdecl, "--json"], check=True, capture_output=True, text=True)
    return json.loads(result.stdout)


def prepare_vtk(grdecl, size, scratch):
    """The worker's prepare step: .vtu of the active cells, checks and camera; returns (path, JSON)."""
    stem = os.path.splitext(grdecl)[0]
    out = stem + "_prepared.json"
    prepared = run_json([SYSTEM_PYTHON, WORKER, "prepare", grdecl, "--camera", *map(str, DEFAULT_POSE), "0",
                         "--size", *map(str, size), "--vtu", stem + ".vtu", "--json", out], out)
    return out, prepared


def check_model(inspected, prepared):
    """The VTK grid against `cutaway inspect`: active cells and relative volume differences.
    Exits when a check fails (nothing would be comparable)."""
    total = inspected["volume"]["total"]
    volumes = {name: {"volume": v, "relative_difference": abs(v - total) / total, "tolerance": VOLUME_TOLERANCE[name]}
               for name, v in prepared["volume_model_units3"].items()}
    checks = {"active_cells": {"cutaway_inspect": inspected["active_cells"], "vtk_cells": prepared["vtk_cells"],
                               "numpy_reader": prepared["active_cells"]},
              "volume_cutaway_inspect": total, "volumes": volumes}
    failures = [name for name, v in volumes.items() if v["relative_difference"] > v["tolerance"]]
    if not inspected["active_cells"] == prepared["vtk_cells"] == prepared["active_cells"]:
        failures.append("active_cells")
    if failures:
        raise SystemExit(f"{prepared['grdecl']}: VTK grid disagrees with cutaway inspect ({failures}): {checks}")
    return checks


def vtk_round(x, prepared_path, scratch, warmup, repeat, modes=("surface", "clip"), image_dir=None):
    """One VTK process on the X display `x` rendering `modes` in turn, each `warmup` then `repeat`
    timed frames; returns the worker's JSON (with each mode's last frame as DIR/vtk_MODE.png if
    `image_dir`). A failed worker is run again, up to VTK_ATTEMPTS times, with its error logged."""
    out = os.path.join(scratch, "vtk_round.json")
    command = [SYSTEM_PYTHON, WORKER, "render", prepared_path, "--modes", *modes, "--warmup", str(warmup),
               "--repeat", str(repeat), "--json", out] + (["--image-dir", image_dir] if image_dir else [])
    for attempt in range(1, VTK_ATTEMPTS + 1):
        worker = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=x.env)
        if worker.returncode == 0:
            with open(out) as f:
                return json.load(f)
        print(f"VTK worker failed (exit {worker.returncode}, attempt {attempt}/{VTK_ATTEMPTS}, Xvfb "
              f"{'running' if x.alive() else 'gone'}): {worker.stderr.strip()[-400:]}", flush=True)
        if not x.alive():
            break
    raise SystemExit(f"VTK worker failed {attempt} time(s): {' '.join(command)}")


def camera_flags(camera):
    """`--camera AZ EL DIST` of a prepared orbit camera (distance in render units, explicit)."""
    return ["--camera", camera["azimuth_deg"], camera["elevation_deg"], repr(camera["distance"])]


def ours_round(exp, grdecl, camera, proto, flags):
    """One `cutaway render --baseline` run; returns plain and cutaway medians (ms), face counts as
    stats.json gives them (`baseline_faces_drawn`, `faces_drawn` per stage; None when absent) and
    the renderer string."""
    stats = exp.render(grdecl, *camera_flags(camera), "--size", *camera["size"], *PAPER_FLAGS, "--baseline",
                       "--warmup", proto["ours_warmup"], "--repeat", proto["ours_repeat"],
                       *flags)
    return {"plain_ms": stats["baseline_ms"], "cutaway_ms": stats["stages_ms"]["total"],
            "stages_ms": stats["stages_ms"], "plain_faces_drawn": stats.get("baseline_faces_drawn"),
            "cutaway_faces_drawn": stats.get("faces_drawn"), "cut_strategy": stats["strategy"]["name"],
            "face_fields": {k: v for k, v in stats.items() if "faces" in k}, "primary_cells": stats.get("primary_cells"),
            "gl_renderer": stats.get("gl_renderer"), "gl_version": stats.get("gl_version"),
            "lp_num_threads": stats.get("lp_num_threads"), "git_revision": stats.get("git_revision")}


def pixel_box(png, is_model):
    """[x0, y0, x1, y1] (px, inclusive) of the pixels where `is_model(rgba floats 0..1)` holds, or None."""
    import matplotlib.image
    import numpy as np

    image = matplotlib.image.imread(png)
    rows, cols = np.nonzero(is_model(image))
    return [int(cols.min()), int(rows.min()), int(cols.max()), int(rows.max())] if rows.size else None


def camera_check(exp, x, grdecl, prepared_path, camera, scratch):
    """Renders one VTK surface frame and our cutaway frame (kept as camera_check_<model>_{vtk,ours}.png)
    and compares the box of VTK's non-white pixels with the box of the pixels showing a cell in our
    `--cell-ids` image (so our colour bar does not count); exits when they differ by more than
    CAMERA_TOLERANCE_PX."""
    model = os.path.splitext(os.path.basename(grdecl))[0]
    vtk_png, ours_png = (exp.path(f"camera_check_{model}_{side}.png") for side in ("vtk", "ours"))
    vtk_round(x, prepared_path, scratch, 0, 1, modes=("surface",), image_dir=scratch)
    os.replace(os.path.join(scratch, "vtk_surface.png"), vtk_png)
    ids_png = os.path.join(scratch, "cell_ids.png")
    exp.render(grdecl, *camera_flags(camera), "--size", *camera["size"], *PAPER_FLAGS, "--cell-ids", ids_png,
               "--warmup", 0, "--repeat", 1, image=ours_png)
    boxes = {"vtk_surface": pixel_box(vtk_png, lambda rgb: (rgb[..., :3] < 0.98).any(axis=-1)),
             "ours_cell_ids": pixel_box(ids_png, lambda ids: (ids > 0).any(axis=-1))}
    if None in boxes.values():
        raise SystemExit(f"camera check: no model pixel in {[k for k, v in boxes.items() if v is None]} "
                         f"({vtk_png}, {ids_png})")
    offset = max(abs(a - b) for a, b in zip(boxes["vtk_surface"], boxes["ours_cell_ids"]))
    limit = CAMERA_TOLERANCE_PX * camera["size"][0]
    result = {"model_pixel_box": boxes, "max_offset_px": offset, "tolerance_px": limit,
              "images": [os.path.relpath(p, exp.out) for p in (vtk_png, ours_png)]}
    if offset > limit:
        raise SystemExit(f"camera mismatch between VTK and ours: {result}")
    return result


def spread(values):
    """Median over rounds, min, max and the rounds' values (ms)."""
    return {"median": statistics.median(values), "min": min(values), "max": max(values), "rounds": values}


def per_round_ratios(ours, vtk):
    """Ours over VTK, round by round, from two spreads over the same interleaved rounds."""
    return [o / v for o, v in zip(ours["rounds"], vtk["rounds"])]


def summarise_vtk(vtk_rounds):
    """Per VTK mode: spread of the rounds' medians (ms), polygons drawn, and for clip the filter
    time (ms, median over all timed frames) after checking both filters ran in every timed frame."""
    by_mode = {mode: [{m["mode"]: m for m in r["modes"]}[mode] for r in vtk_rounds] for mode in ("surface", "clip")}
    executions = {n for m in by_mode["clip"] for n in m["filter_executions_per_frame"]}
    if executions != {2}:
        raise SystemExit(f"VTK clip mode: filters executed {sorted(executions)} times per frame, expected 2 (clip, surface)")
    summary = {mode: {**spread([m["median_ms"] for m in modes]), "faces_drawn": modes[0]["faces_drawn"]}
               for mode, modes in by_mode.items()}
    summary["clip"]["filter_ms_median"] = statistics.median(t for m in by_mode["clip"] for t in m["filter_ms"])
    return summary


def summarise_ours(rounds):
    """Spread over rounds of our plain and cutaway frame (ms), and the first round's face counts."""
    return {"plain_ms": spread([r["plain_ms"] for r in rounds]), "cutaway_ms": spread([r["cutaway_ms"] for r in rounds]),
            "plain_faces_drawn": rounds[0]["plain_faces_drawn"], "cutaway_faces_drawn": rounds[0]["cutaway_faces_drawn"],
            "cut_strategy": rounds[0]["cut_strategy"]}


def measure_model(exp, x, preset, proto, draws, scratch):
    """Everything about one model: checks, camera, interleaved rounds, summaries and ratios."""
    grdecl = generate(exp, preset, scratch)
    inspected = inspect(exp, grdecl)
    prepared_path, prepared = prepare_vtk(grdecl, proto["size"], scratch)
    checks = check_model(inspected, prepared)
    camera = prepared["camera"]
    camera_result = camera_check(exp, x, grdecl, prepared_path, camera, scratch)
    vtk_rounds, ours_rounds = [], {name: [] for name in draws}
    for index in range(proto["rounds"]):
        print(f"{preset}: round {index + 1}/{proto['rounds']}", flush=True)
        vtk_rounds.append(vtk_round(x, prepared_path, scratch, proto["vtk_warmup"], proto["vtk_repeat"]))
        for name, flags in draws.items():
            ours_rounds[name].append(ours_round(exp, grdecl, camera, proto, flags))
    vtk = summarise_vtk(vtk_rounds)
    ours = {draw: summarise_ours(rounds) for draw, rounds in ours_rounds.items()}
    # Also per round: both sides of a round ran minutes apart, so its ratio is less exposed to the
    # machine's slow and fast spells than the ratio of the medians.
    ratios = {draw: {"plain_over_vtk_surface": s["plain_ms"]["median"] / vtk["surface"]["median"],
                     "cutaway_over_vtk_clip": s["cutaway_ms"]["median"] / vtk["clip"]["median"],
                     "plain_over_vtk_surface_rounds": per_round_ratios(s["plain_ms"], vtk["surface"]),
                     "cutaway_over_vtk_clip_rounds": per_round_ratios(s["cutaway_ms"], vtk["clip"])}
              for draw, s in ours.items()}
    return {"model": f"preset:{preset} (cutaway generate --preset {preset} --seed {SEED})", "dims": prepared["dims"],
            "active_cells": inspected["active_cells"], "faces_by_class": inspected["faces"], "checks": checks,
            "render_frame": prepared["frame"], "camera": camera, "camera_check": camera_result,
            "vtk": vtk, "ours": ours, "ratios": ratios,
            "rounds": {"vtk": vtk_rounds, "ours": ours_rounds}, "vtk_prepare_s": prepared["prepare_s"]}


def machine_context(exp, models):
    """Both renderers' strings, LP_NUM_THREADS, git revision (of the working tree, and as the
    executable reports its own), uname, date, VTK version."""
    first = models[0]
    ours = next(iter(first["rounds"]["ours"].values()))[0]
    vtk_mode = first["rounds"]["vtk"][0]["modes"][0]
    return {**exp.context({"gl_renderer": ours["gl_renderer"]}), "gl_renderer_ours": ours["gl_renderer"],
            "gl_version_ours": ours["gl_version"], "gl_renderer_vtk": vtk_mode["gl_renderer"],
            "vtk_window_class": vtk_mode["window_class"], "vtk_version": first["rounds"]["vtk"][0]["vtk_version"],
            "lp_num_threads_vtk": first["rounds"]["vtk"][0]["lp_num_threads"], "lp_num_threads_ours": ours["lp_num_threads"],
            "date": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "xvfb": f"one Xvfb -screen 0 {XVFB_SCREEN} for the run",
            "cutaway_executable": exp.cutaway, "git_revision_of_executable": ours["git_revision"]}


def compute(exp):
    """Measures every model; returns the whole result document."""
    proto = protocol(exp.quick)
    draws = configurations()
    with tempfile.TemporaryDirectory(prefix="cutaway-peer-vtk-") as scratch, x_server.display(XVFB_SCREEN) as x:
        models = [measure_model(exp, x, preset, proto, draws, scratch) for preset in MODELS]
    return {"experiment": "peer_vtk", "quick": exp.quick,
            "protocol": {**proto, "camera_pose_deg": DEFAULT_POSE, "fovy_deg": models[0]["camera"]["fovy_deg"],
                         "ours_flags": list(PAPER_FLAGS) + ["--baseline"], "configurations": {name: list(flags) for name, flags in draws.items()},
                         "vtk_modes": {"surface": "vtkDataSetSurfaceFilter, PORO cell colours, edges on; executes once",
                                       "clip": "vtkTableBasedClipDataSet (plane through the centre, normal away from "
                                               "the eye) -> vtkDataSetSurfaceFilter, re-executed every frame"},
                         "time": "wall clock per frame, ms: VTK Render()+WaitForCompletion(); ours fenced (glFinish) "
                                 "medians from stats.json; per round the median over timed frames, then the median "
                                 "over rounds"},
            "context": machine_context(exp, models), "models": models}


def report(exp, document):
    result = peer_report.report(document)
    return result.figure(*(exp.path(f"camera_check_{m}_{side}.png") for m in MODELS for side in ("vtk", "ours")))


def main():
    cx.exio.require_matplotlib()  # re-runs under /usr/bin/python3 when needed (numpy, matplotlib, vtk live there)
    exp = cx.Experiment(__doc__, "peer_vtk.json")
    exp.figures = exp.results  # the camera-check images stay beside the numbers
    exp.run(compute, report)


if __name__ == "__main__":
    main()
