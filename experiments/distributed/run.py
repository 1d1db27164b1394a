#!/usr/bin/python3
"""Distributed: one cutaway frame across 1, 2 and 4 MPI ranks (strong and weak scaling, memory per rank).

Interface (for experiments/run_all):
  experiments/distributed/run.py [--quick] [--force] [--report-only] [--build DIR] [--out DIR]
Writes results/distributed/distributed.json (every run's stats.json summary: per-rank cells, stage
medians, allreduce and IceT times, bytes per frame, peak and resident memory per rank; machine
context) and results/distributed/README.md (tables, what 2 cores can and cannot show, a model of a
1-billion-cell frame on a cluster from the measured costs, the Slurm command line).
--quick: petra and small generated models at 480x270 (results/quick/distributed/).

Every run is `mpirun -np N cutaway render MODEL --strategy frustum` (N = 1 too, so the 1-rank row
pays the same read-backs and IceT calls) with LP_NUM_THREADS=1 per rank, plus the single-process
command without mpirun as the baseline. Strong scaling: one model, 1, 2, 4 ranks. Weak scaling:
generated models of 1x, 2x, 4x the cells (the same NX x NY, NZ doubling) on 1, 2, 4 ranks, so each
rank holds the same K slab size. Largest model: preset:scale-100m across 4 ranks with the O(pixels)
frustum union (frustum-sweep), each rank generating only its blocks. Needs a build with CUTAWAY_MPI=ON and mpirun (openmpi-bin).
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402

RANKS = (1, 2, 4)
LARGEST_MODEL, LARGEST_STRATEGY = "preset:scale-100m", "frustum-sweep"
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1", "OMPI_MCA_mpi_yield_when_idle": "1",
           "LP_NUM_THREADS": "1"}


def run(exp, model, ranks, size, repeat, scratch, strategy="frustum"):
    """One render (under mpirun when ranks > 0); returns (stats, wall seconds)."""
    stats_path = os.path.join(scratch, f"stats-{ranks}.json")
    command = [exp.cutaway, "render", model, "--strategy", strategy, "--size", *size.split("x"), "--warmup", "1",
               "--repeat", str(repeat), "--no-metrics", "--out", os.path.join(scratch, "frame.png"), "--stats", stats_path]
    if ranks > 0:
        command = [shutil.which("mpirun") or "mpirun", "--oversubscribe", "-np", str(ranks), *command]
    started = time.monotonic()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, env={**os.environ, **MPI_ENV})
    wall = time.monotonic() - started
    with open(stats_path) as f:
        return json.load(f), wall


def summary(stats, wall, ranks):
    row = {"ranks": ranks, "active_cells": stats["active_cells"], "primary_cells": stats["primary_cells"],
           "stages_ms": stats["stages_ms"], "model_load_s": stats["model_load_s"], "command_wall_s": wall}
    d = stats.get("distributed")
    if d:
        per_rank = d["per_rank"]
        row.update({"allreduce_ms": d["allreduce_ms"], "composite_ms": d["composite_ms"],
                    "allreduce_wait_ms": d["allreduce_wait_ms"], "composite_wait_ms": d["composite_wait_ms"],
                    "cut_combine_stage_ms": d["cut_combine_stage_ms"], "composite_stage_ms": d["composite_stage_ms"],
                    "bytes_per_frame": d["bytes_per_frame"],
                    "per_rank": [{k: r[k] for k in ("rank", "active_cells", "primary_cells", "gpu_memory_bytes",
                                                     "block_geometry_bytes", "peak_rss_bytes", "rss_bytes_after_frames",
                                                     "stages_ms")} for r in per_rank],
                    "max_rank_active_cells": max(r["active_cells"] for r in per_rank),
                    "max_rank_geometry_ms": max(geometry_ms(r["stages_ms"]) for r in per_rank),
                    "max_rank_rss_after_frames": max(r["rss_bytes_after_frames"] for r in per_rank),
                    "max_rank_gpu_memory_bytes": max(r["gpu_memory_bytes"] for r in per_rank)})
    else:
        row["gpu_memory_bytes"] = stats.get("gpu_memory_bytes")
    return row


def geometry_ms(stages):
    """The stages whose work is split among the ranks (object space: per cell and face)."""
    return sum(stages.get(s, 0.0) for s in ("cut_surface", "culling", "secondary", "primary"))


def series(exp, model, size, repeat, scratch, label):
    """The single process, then 1, 2, 4 ranks on one model; returns the rows and the last stats."""
    rows = []
    stats, wall = run(exp, model, 0, size, repeat, scratch)
    rows.append({**summary(stats, wall, 0), "note": "single process, no mpirun"})
    for ranks in RANKS:
        stats, wall = run(exp, model, ranks, size, repeat, scratch)
        rows.append(summary(stats, wall, ranks))
        print(f"{label} {model} {ranks} ranks: {stats['stages_ms']['total']:.0f} ms, allreduce "
              f"{rows[-1]['allreduce_ms']:.1f} ms, composite {rows[-1]['composite_ms']:.1f} ms", flush=True)
    return rows, stats


def weak_models(exp, dims_list, scratch):
    paths = []
    for dims in dims_list:
        path = os.path.join(scratch, "weak-%dx%dx%d.grdecl" % dims)
        subprocess.run([exp.cutaway, "generate", "--dims", *map(str, dims), "--seed", "17", "--quiet", "--out", path],
                       check=True, stdout=subprocess.DEVNULL)
        paths.append(path)
    return paths


def mb(value):
    return f"{value / 2**20:.0f}"


SCALING_HEADER = ["ranks", "active cells (max per rank)", "frame ms (rank 0)", "slowest rank's cut+culling+stage 2+3 ms",
                  "cut allreduce ms (wait before it)", "IceT composite ms (wait before it)", "screen-space ms (rank 0)",
                  "bytes sent / frame (IceT, all ranks)", "resident MB after frames (max rank)", "wall s"]


def scaling_rows(rows):
    """One table row per run of a scaling series (SCALING_HEADER's columns)."""
    table = []
    for r in rows:
        s = r["stages_ms"]
        screen = s.get("ssao", 0) + s.get("post", 0) + s.get("mean_filter", 0)
        if r["ranks"] == 0:
            table.append(["1 (no MPI)", f"{r['active_cells']:,}", f"{s['total']:.0f}", f"{geometry_ms(s):.0f}", "-", "-",
                          f"{screen:.0f}", "-", "-", f"{r['command_wall_s']:.1f}"])
            continue
        table.append([r["ranks"], f"{r['active_cells']:,} ({r['max_rank_active_cells']:,.0f})", f"{s['total']:.0f}",
                      f"{r['max_rank_geometry_ms']:.0f}", f"{r['allreduce_ms']:.1f} ({r['allreduce_wait_ms']:.0f})",
                      f"{r['composite_ms']:.1f} ({r['composite_wait_ms']:.0f})", f"{screen:.0f}",
                      f"{r['bytes_per_frame']['icet_sent_all_ranks'] / 1e6:.1f} MB", mb(r["max_rank_rss_after_frames"]),
                      f"{r['command_wall_s']:.1f}"])
    return table


MEMORY_HEADER = ["ranks", "per rank: active cells", "primary cells", "slab geometry MB", "renderer GPU buffers MB",
                 "resident MB after frames", "peak resident MB (includes loading)"]


def memory_rows(rows):
    return [[f"{r['ranks']} (rank {p['rank']})", f"{p['active_cells']:,.0f}", f"{p['primary_cells']:,.0f}",
             mb(p["block_geometry_bytes"]), mb(p["gpu_memory_bytes"]), mb(p["rss_bytes_after_frames"]), mb(p["peak_rss_bytes"])]
            for r in rows if r["ranks"] != 0 for p in r["per_rank"]]


def cluster_model(strong, size):
    """A 1-billion-cell frame on 256 ranks, from this machine's measured costs (llvmpipe)."""
    one = next(r for r in strong if r["ranks"] == 1)
    four = next(r for r in strong if r["ranks"] == 4)
    w, h = (int(v) for v in size.split("x"))
    pixels = w * h
    ms_per_cell = one["max_rank_geometry_ms"] / one["active_cells"]
    # Resident bytes a slab costs per active cell: the 1- and 4-rank rows differ by 3/4 of the model.
    slope = (one["max_rank_rss_after_frames"] - four["max_rank_rss_after_frames"]) / max(1.0, one["max_rank_active_cells"] - four["max_rank_active_cells"])
    fixed = one["max_rank_rss_after_frames"] - slope * one["max_rank_active_cells"]
    screen_ms = sum(one["stages_ms"].get(s, 0) for s in ("ssao", "post", "mean_filter"))
    ranks, cells = 256, 1_000_000_000
    per_rank = cells / ranks
    hd = 1920 * 1080
    allreduce_message = 2 * 4 * hd
    icet_bytes_per_pixel = 2 * (16 + 4)  # two RGBA32F composites, float depth each
    radixk_sent = icet_bytes_per_pixel * hd * (1 - 1 / ranks)
    measured_icet = four["bytes_per_frame"]["icet_sent_all_ranks"] / 4 / pixels
    return {"ranks": ranks, "cells": cells, "cells_per_rank": per_rank,
            "measured_ms_per_active_cell_llvmpipe_1_thread": ms_per_cell,
            "measured_resident_bytes_per_active_cell": slope, "measured_fixed_resident_bytes_per_rank": fixed,
            "resident_bytes_per_rank": fixed + slope * per_rank,
            "geometry_ms_per_rank_llvmpipe": ms_per_cell * per_rank,
            "allreduce_message_bytes_1080p": allreduce_message, "allreduce_sent_per_rank_bytes": 2 * (ranks - 1) / ranks * allreduce_message,
            "icet_radixk_sent_per_rank_bytes_dense": radixk_sent,
            "measured_icet_bytes_sent_per_rank_per_pixel": measured_icet,
            "screen_space_ms_measured": screen_ms * hd / pixels}


def cluster_text(m):
    gb = 2**30
    return [
        f"Assume {m['ranks']} ranks (64 nodes x 4 GPUs, one rank per GPU) and a 1920x1080 frame.", "",
        f"- Cells per rank: {m['cells_per_rank'] / 1e6:.1f} M (K, J or I slabs; a 1000 x 1000 x 1000 grid has 1000 "
        "layers, so K slabs allow up to 1000 ranks).",
        f"- Memory per rank: measured here {m['measured_resident_bytes_per_active_cell']:.0f} resident bytes per active "
        f"cell of a slab plus {m['measured_fixed_resident_bytes_per_rank'] / 2**20:.0f} MB per process (GL driver, "
        f"targets), so about {m['resident_bytes_per_rank'] / gb:.1f} GB per rank while rendering. Loading keeps only "
        "the rank's slab: a preset is generated block by block, a GRDECL file read keeping only the slab's ZCORN, "
        "ACTNUM and property records (COORD is read whole and narrowed, and the file's text is held while it is "
        "parsed: split a 1-billion-cell model into INCLUDE files or use a parallel file system's page cache).",
        f"- Cut allreduce: 2 images x 4 bytes x 1920 x 1080 = {m['allreduce_message_bytes_1080p'] / 1e6:.1f} MB per rank; "
        f"a ring/Rabenseifner allreduce sends about 2(P-1)/P of it, {m['allreduce_sent_per_rank_bytes'] / 1e6:.1f} MB per "
        "rank, whatever P: about 2-4 ms at 10-25 GB/s (HDR InfiniBand) plus 2 log2(P) = 16 latencies.",
        f"- IceT radix-k: two RGBA32F + depth composites = {2 * 20} bytes per pixel; dense, each rank sends about "
        f"(1 - 1/P) of it, {m['icet_radixk_sent_per_rank_bytes_dense'] / 1e6:.0f} MB per frame; measured here "
        f"{m['measured_icet_bytes_sent_per_rank_per_pixel']:.1f} bytes per pixel per rank at 4 ranks (IceT sends only "
        "active pixels: run-length compression of the background). Kendall et al. 2010 composite 64 Mpixels in "
        "0.08 s on 32K cores; 2 Mpixels on 256 ranks is bandwidth-bound: ~5-10 ms at 10-25 GB/s.",
        f"- Time per stage: object-space work (cut, culling, stages 2 and 3) measured at "
        f"{m['measured_ms_per_active_cell_llvmpipe_1_thread'] * 1e3:.3f} us per active cell on one llvmpipe thread, so "
        f"{m['geometry_ms_per_rank_llvmpipe'] / 1e3:.1f} s per rank on llvmpipe for {m['cells_per_rank'] / 1e6:.1f} M "
        "cells; a GPU is two to three orders of magnitude faster (not measured here: no GPU was used), i.e. tens of "
        f"ms. Screen-space passes run once at rank 0: {m['screen_space_ms_measured']:.0f} ms at 1080p on llvmpipe "
        "(scaled per pixel from this run), a few ms on a GPU. The frame time is then max over ranks of the "
        "object-space work + allreduce + IceT + rank 0's screen-space passes; the allreduce and IceT stay bounded "
        "as P grows, the object-space work falls as 1/P.",
        "", "Slurm:", "",
        "```sh",
        "# 64 nodes x 4 GPUs, one rank per GPU; each rank's EGL device is the one GPU Slurm binds to it",
        "srun --mpi=pmix --nodes=64 --ntasks-per-node=4 --gpus-per-task=1 --gpu-bind=single:1 \\",
        "     build/bin/cutaway render model.grdecl --egl-platform device --size 1920 1080 \\",
        "     --strategy frustum --rank-slabs k --out frame.png --cell-ids ids.png --stats stats.json",
        "```", ""]


def measure(exp):
    """Strong and weak scaling, the largest model, the cluster model; None (skipped) without MPI."""
    if not shutil.which("mpirun"):
        raise SystemExit("mpirun not found (apt-get install openmpi-bin; build with CUTAWAY_MPI=ON)")
    cache = os.path.join(os.path.dirname(os.path.dirname(exp.cutaway)), "CMakeCache.txt")
    if os.path.exists(cache) and "CUTAWAY_MPI:BOOL=OFF" in open(cache).read():
        print(f"skipped: {cx.exio.shown(cache)} says CUTAWAY_MPI=OFF (this cutaway refuses mpirun)")
        return None
    size = "480x270" if exp.quick else "1920x1080"
    repeat = 1 if exp.quick else 3
    strong_models = ["preset:petra"] if exp.quick else ["preset:sapphire", "preset:scale-1m"]
    weak_dims = [(30, 30, 4), (30, 30, 8), (30, 30, 16)] if exp.quick else [(100, 125, 10), (100, 125, 20), (100, 125, 40)]
    with tempfile.TemporaryDirectory(prefix="cutaway-distributed-") as scratch:
        strong = {}
        for model in strong_models:
            strong[model], stats = series(exp, model, size, repeat, scratch, "strong")
        weak = []
        for ranks, path in zip(RANKS, weak_models(exp, weak_dims, scratch)):
            stats, wall = run(exp, path, ranks, size, repeat, scratch)
            weak.append({**summary(stats, wall, ranks), "model": os.path.basename(path)})
            print(f"weak {os.path.basename(path)} {ranks} ranks: {stats['stages_ms']['total']:.0f} ms", flush=True)
        largest = None
        if not exp.quick:
            # The O(pixels) frustum union: one frustum per primary would take minutes for 931K primaries.
            stats, wall = run(exp, LARGEST_MODEL, 4, size, 1, scratch, LARGEST_STRATEGY)
            largest = {**summary(stats, wall, 4), "model": LARGEST_MODEL, "strategy": LARGEST_STRATEGY}
    context = {**exp.context(stats), "lp_num_threads": MPI_ENV["LP_NUM_THREADS"], "gl_version": stats.get("gl_version")}
    return {"experiment": "distributed", "quick": exp.quick, "size": size, "context": context, "mpi_environment": MPI_ENV,
            "strong": strong, "weak": weak, "largest_across_4_ranks": largest,
            "cluster_model": cluster_model(strong[strong_models[-1]], size)}


def largest_text(largest, context):
    peaks = [r["peak_rss_bytes"] for r in largest["per_rank"]]
    memory = context.get("memory_bytes")
    return (f"{largest['active_cells']:,} active cells, {largest['max_rank_active_cells']:,.0f} on the largest rank; frame "
            f"{largest['stages_ms']['total']:.0f} ms; peak resident memory per rank {mb(min(peaks))}-{mb(max(peaks))} MB "
            f"({mb(sum(peaks))} MB in all" + (f", on a {memory / 2**30:.0f} GB machine" if memory else "") + "); resident "
            f"{mb(largest['max_rank_rss_after_frames'])} MB on the largest rank after the frame; wall "
            f"{largest['command_wall_s']:.0f} s (generation by block included).")


def report(exp, document):
    context, size, strong, weak = document["context"], document["size"], document["strong"], document["weak"]
    cores = context.get("cpu_count")
    memory_model = list(strong)[-1]
    frames = {r["ranks"]: r["stages_ms"]["total"] for r in strong[memory_model] if r["ranks"] > 0}
    result = md.Report(
        f"Distributed cutaway frame: 1, 2, 4 MPI ranks ({size})",
        "One cutaway frame rendered across 1, 2 and 4 MPI ranks, each rank holding one slab of whole layers: the cut "
        "depth max-reduced across ranks (allreduce), the G-buffer composited with IceT, rank 0 running the screen-space "
        "passes. Each row is `mpirun --oversubscribe -np N cutaway render MODEL --strategy frustum` with LP_NUM_THREADS=1 "
        "per rank (the first row the single-process command without mpirun); medians of the timed frames. Strong "
        "scaling: one model on 1, 2, 4 ranks; weak scaling: generated models of 1x, 2x, 4x the cells on 1, 2, 4 ranks. "
        "Frame ms is rank 0's fenced total (it waits for the slowest rank before the allreduce and the composite). The "
        "allreduce and IceT columns time the MPI and IceT calls alone, after a barrier; the barrier's wait (load "
        "imbalance, and waiting for a core) is in brackets.",
        headline=f"{memory_model.removeprefix('preset:')} frame on 1 / 2 / 4 ranks: "
                 + " / ".join(md.ms(frames[n]) for n in sorted(frames)) + " ms")
    result.section(f"What {cores} cores can and cannot show")
    result.text(f"With one llvmpipe thread per rank, wall-clock speed-up is "
                f"bounded by {cores}, and runs with more ranks than cores include waiting for a core. What the runs do "
                "show: each rank's share of the model (cells, faces, slab memory) falls as 1/N, the object-space stage "
                "time of the slowest rank falls with its share while it has a core of its own, and the exchange costs "
                "(read-backs, allreduce, IceT) are measured per frame. What they cannot show: speed-up beyond the core "
                "count, network costs (all ranks share memory here), or GPU-rate per-cell costs.")
    for name, rows in strong.items():
        result.section(f"Strong scaling: {name}").table(SCALING_HEADER, scaling_rows(rows))
    result.section("Weak scaling: generated " + ", ".join(r["model"].removeprefix("weak-").removesuffix(".grdecl")
                                                          for r in weak) + " on 1, 2, 4 ranks")
    result.table(SCALING_HEADER, scaling_rows(weak))
    result.section(f"Memory per rank: {memory_model}").table(MEMORY_HEADER, memory_rows(strong[memory_model]))
    result.text("Resident memory after the frames falls with the slab; the peak includes loading, where each rank first "
                "loads its block of an equal split (to count active cells per layer) and then its balanced slab with a "
                "one-cell halo: no rank holds the whole model. Slabs are balanced by active cells, not primaries: stage 1 "
                "(one frustum per primary) follows the primary column, so the rank holding most primaries sets the pace "
                "of stage 1 (the waits before the allreduce).")
    largest = document.get("largest_across_4_ranks")
    if largest:
        result.section(f"Largest model across 4 ranks: {largest['model']} (strategy {largest['strategy']})",
                       largest_text(largest, context))
    result.section("Model: a 1-billion-cell frame on a cluster")
    result.body += cluster_text(document["cluster_model"])
    return result


def main():
    cx.Experiment(__doc__, "distributed.json").run(measure, report)


if __name__ == "__main__":
    main()
