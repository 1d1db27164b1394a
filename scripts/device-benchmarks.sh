#!/usr/bin/env bash
# cutaway's benchmarks on a lent NVIDIA machine (the workplace's `device` tool, EGL device platform).
# Runs there, in the repository root, with these carried from the build machine (prepared by
# scripts/device-prepare.sh): .device/bin (cutaway, bench_cutaway, bench_volume built here), .device/lib (their
# shared libraries except glibc and libstdc++), .gl (the glvnd EGL loader packages), .shared-data
# (the tests' real data; the GL tests part only).
#   scripts/device-benchmarks.sh GIT_REVISION SECONDS
# Writes into $OUT (a call brings back 8 files at most: run the parts over two calls with PARTS, e.g.
# PARTS="gl_tests render_sapphire table1 cpu_path main", then PARTS="cut_strategies scale orbit
# volume_bench volume_fig7 volume_fig8"; the whole script takes about 6-7 minutes on an H200):
# device.log, context.txt (GPU, driver, CPU),
# render_sapphire.json + .png (the main job's frame, metrics on: the invariants on another driver),
# bench_table1.json (experiments/table1's protocol: the paper's Table 1 on this GPU),
# gl_tests.log (cutaway_gl_tests and volume_tests on this GPU's driver),
# bench_cpu_path.json (GPU jump flooding against the CPU path it replaced), bench_main.json (the
# main job on the four presets, visible faces against all faces, plain frame beside it),
# bench_cut_strategies.json (experiments/cut_strategies' timing sweep), scale.jsonl (one
# `cutaway render` stats object per line, with its wall time), orbit_petra_720p.jsonl (the viewer
# experiment's camera path on petra at 1280x720, one `cutaway render` stats object per pose),
# bench_volume.json (the seismic ray casters on the paper's 101x101x250 cube, 512x512, GPU stages
# fenced and by timer query), volume.jsonl (Duan & Li's figures 7 and 8 with the commands of
# experiments/volume_fig7 and volume_fig8: one `cutaway volume` stats object per line, with
# "figure", "caster" and the eye's azimuth or the cube's growth step added). Parts run in that order; each is
# skipped when too little of SECONDS is left, and one that fails does not stop the others.
# PARTS="render_sapphire scale" (say) runs only the parts named (their first word). The EGL
# platform is render's auto choice (the device platform where a hardware EGL device is listed;
# NVIDIA's client extensions name it EGL_EXT_device_base), recorded in stats.json and the
# benchmark context with the renderer.
# experiments/device/report.py turns the files into results/device-<gpu>/.
set -u
revision=${1:?usage: device-benchmarks.sh GIT_REVISION SECONDS}
budget=${2:?usage: device-benchmarks.sh GIT_REVISION SECONDS}
out=${OUT:?OUT: the folder whose files come back}
start=$(date +%s)
elapsed() { echo $(($(date +%s) - start)); }
log() { echo "[$(elapsed) s] $*" | tee -a "$out/device.log"; }
left() { echo $((budget - $(elapsed))); }

for deb in .gl/*.deb; do dpkg -x "$deb" /; done
ldconfig
export LD_LIBRARY_PATH="$PWD/.device/lib:/usr/local/nvidia/lib64:${LD_LIBRARY_PATH:-}"
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"
export CUTAWAY_SHADER_DIR="$PWD/shaders" CUTAWAY_GIT_REVISION="$revision"
bin="$PWD/.device/bin"
scratch=$(mktemp -d)

{
    nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv
    echo "cpus: $(nproc), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
    echo "memory: $(grep MemTotal /proc/meminfo)"
    echo "uname: $(uname -a)"
    echo "git revision: $revision"
} >"$out/context.txt" 2>&1

# part NAME MIN_SECONDS COMMAND...: runs COMMAND (stdout and stderr to the log) unless fewer than
# MIN_SECONDS are left; stops it when the budget runs out.
part() {
    local name=$1 need=$2
    shift 2
    if [ -n "${PARTS:-}" ] && [[ " $PARTS " != *" ${name%% *} "* ]]; then return; fi
    if [ "$(left)" -lt "$need" ]; then
        log "$name: skipped ($(left) s left, needs $need)"
        return
    fi
    log "$name: start"
    timeout "$(left)" bash -c '"$@"' "$name" "$@" >>"$out/device.log" 2>&1
    log "$name: exit status $?"
}

bench() { "$bin/bench_cutaway" --size=1920x1080 --benchmark_out_format=json "$@"; }

# One `cutaway render` of a preset with one strategy, its stats and wall time appended to scale.jsonl.
scale() {
    local preset=$1 strategy=$2 t0 t1
    t0=$(date +%s%N)
    "$bin/cutaway" render "preset:$preset" --size 1920 1080 --warmup 1 --repeat 3 --no-metrics \
        --strategy "$strategy" --out "$scratch/frame.png" --stats "$scratch/stats.json" || return 1
    t1=$(date +%s%N)
    python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["command_wall_s"] = float(sys.argv[2]); print(json.dumps(s))' \
        "$scratch/stats.json" "$(((t1 - t0) / 1000000))e-3" >>"$out/scale.jsonl"
}
# The viewer experiment's camera path (experiments/viewer_responsiveness: petra, 1280x720, 24 turns of
# 15 degrees from azimuth 35 at elevation 30, primary range 0.325-0.4): the renderer's frame at each
# pose, without a window (the lent machine has no display). One stats object per pose, its azimuth added.
orbit() {
    local i az
    for i in $(seq 0 23); do
        az=$((35 + 15 * i))
        "$bin/cutaway" render preset:petra --range 0.325 0.4 --camera $((az % 360)) 30 0 --size 1280 720 --warmup 2 \
            --repeat 5 --no-metrics --out "$scratch/orbit.png" --stats "$scratch/orbit.json" || return 1
        python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["camera_az"] = int(sys.argv[2]); print(json.dumps(s))' \
            "$scratch/orbit.json" "$az" >>"$out/orbit_petra_720p.jsonl"
    done
}
# One `cutaway volume` frame series on CUBE at 512x512 with the grey transfer function and one
# warm-up frame (both volume experiments' settings), its stats appended to volume.jsonl as one line
# with FIELDS (a JSON object) merged in.
volume_series() {
    local fields=$1 cube=$2
    shift 2
    "$bin/cutaway" volume "$cube" --tf grey --size 512 512 --warmup 1 "$@" --out "$scratch/volume.png" \
        --stats "$scratch/volume.json" || return 1
    python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s.update(json.loads(sys.argv[2])); print(json.dumps(s))' \
        "$scratch/volume.json" "$fields" >>"$out/volume.jsonl"
}
# Figure 7 (experiments/volume_fig7): the paper-250 cube (seed 1) from 10 eyes at azimuths 0, 36, ...,
# 324 and elevation 25, GPU caster 50 timed frames, CPU caster 5.
volume_fig7() {
    local az caster
    "$bin/cutaway" generate-seismic --preset paper-250 --seed 1 --out "$scratch/fig7.sgy" >/dev/null || return 1
    for az in $(seq 0 36 324); do
        for caster in gpu cpu; do
            volume_series "{\"figure\": 7, \"caster\": \"$caster\", \"azimuth_deg\": $az}" "$scratch/fig7.sgy" \
                --caster "$caster" --camera "$az" 25 0 --repeat "$([ "$caster" = gpu ] && echo 50 || echo 5)" || return 1
        done
    done
    rm -f "$scratch/fig7.sgy"
}
# Figure 8 (experiments/volume_fig8): cubes growth-1 .. growth-10 (10k x 28k x 25k samples, seed 1)
# from azimuth 40, elevation 25, GPU caster, 20 timed frames each.
volume_fig8() {
    local step
    for step in $(seq 1 10); do
        "$bin/cutaway" generate-seismic --preset "growth-$step" --seed 1 --out "$scratch/fig8.sgy" >/dev/null || return 1
        volume_series "{\"figure\": 8, \"caster\": \"gpu\", \"step\": $step}" "$scratch/fig8.sgy" \
            --caster gpu --camera 40 25 0 --repeat 20 || return 1
        rm -f "$scratch/fig8.sgy"
    done
}
export -f bench scale orbit volume_series volume_fig7 volume_fig8
export bin scratch out

# The GL tests read ../shared/data beside the repository (their compiled-in path).
gl_tests() {
    local data
    data="$(dirname "$PWD")/shared/data"
    [ -e "$data" ] || { mkdir -p "$(dirname "$data")" && ln -s "$PWD/.shared-data" "$data"; }
    for tests in cutaway_gl_tests volume_tests; do
        "$bin/$tests" --gtest_brief=1 >>"$out/gl_tests.log" 2>&1
        echo "$tests exit $?" >>"$out/gl_tests.log"
    done
}
export -f gl_tests

part gl_tests 30 gl_tests
part render_sapphire 20 "$bin/cutaway" render preset:sapphire --size 1920 1080 --warmup 2 \
    --repeat 9 --baseline --stats "$out/render_sapphire.json" --out "$out/render_sapphire.png"
part table1 30 bench --presets=zaphirus,petra,opharine,sapphire --poses=8 --fractions=0.01 --mean_filters=9 \
    --borders=raycast --strategies=frustum --draws=all-faces,visible --warmup=1 --repeat=5 \
    --benchmark_filter=BM_cutaway --benchmark_out="$out/bench_table1.json"
part cpu_path 30 bench --benchmark_filter=BM_cpu_path --presets=petra,sapphire --fractions=0.01,0.2 \
    --strategies=jfa,jfa2 --cpu_references=jfa,jfa2 --apertures=60 --poses=2 --warmup=1 --repeat=3 \
    --benchmark_out="$out/bench_cpu_path.json"
part main 40 bench --presets=zaphirus,petra,opharine,sapphire --draws=visible,all-faces --poses=8 --warmup=1 \
    --repeat=3 --cpu_references=none --benchmark_out="$out/bench_main.json"
part cut_strategies 60 bench --presets=zaphirus,petra,opharine,sapphire --fractions=0.001,0.01,0.05,0.2 \
    --strategies=frustum,frustum-clusters,frustum-sweep,chamfer-3x3,chamfer-34,chamfer-5x5,jfa,jfa+1,jfa+2,1+jfa,jfa2 \
    --apertures=60 --mean_filters=0 --borders=raycast --draws=visible --poses=2 --warmup=2 --repeat=5 \
    --cpu_references=none --ssao=0 --baseline=0 --benchmark_out="$out/bench_cut_strategies.json"

for preset in scale-1m scale-10m; do
    for strategy in frustum-clusters frustum-sweep; do part "scale $preset $strategy" 40 scale "$preset" "$strategy"; done
done
part "scale scale-100m auto" 200 scale scale-100m auto  # the default (it draws frustum-sweep there)
part orbit 30 orbit
part volume_bench 30 "$bin/bench_volume" --volume_dims=101x101x250 --volume_size=512 --benchmark_out_format=json \
    --benchmark_out="$out/bench_volume.json"
part volume_fig7 40 volume_fig7
part volume_fig8 40 volume_fig8
log "done"
