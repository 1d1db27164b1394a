# The benchmarks' own flags (benchmarks/bench_cli.h) and their timer-query counters
# (benchmarks/stage_counters.h), run as the scripts run them.
# -DBENCH_CUTAWAY=... -DBENCH_VOLUME=...

# run(NAME EXPECTED_CODE ARGS...): runs ARGS, checks the exit code; leaves NAME_out and NAME_err.
function(run name expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected)
    message(FATAL_ERROR "${name}: expected exit code ${expected}, found ${code}\nstderr: ${err}")
  endif()
  set(${name}_out "${out}" PARENT_SCOPE)
  set(${name}_err "${err}" PARENT_SCOPE)
endfunction()

# refused(NAME PATTERN ARGS...): exit 2 and stderr exactly one line matching PATTERN.
function(refused name pattern)
  run(${name} 2 ${ARGN})
  if(NOT ${name}_err MATCHES "^${pattern}[^\n]*\n$")
    message(FATAL_ERROR "${name}: expected one line matching '${pattern}', found:\n${${name}_err}")
  endif()
endfunction()

# counters(NAME COUNTERS...): every counter is a key of NAME_out (a Google Benchmark JSON report).
function(counters name)
  foreach(counter ${ARGN})
    string(FIND "${${name}_out}" "\"${counter}\": " found)
    if(found EQUAL -1)
      message(FATAL_ERROR "${name}: expected the counter ${counter} in:\n${${name}_out}")
    endif()
  endforeach()
endfunction()

# --help: the program's flags, then Google Benchmark's.
run(help 0 ${BENCH_CUTAWAY} --help)
string(FIND "${help_out}" "--presets" ours)
string(FIND "${help_out}" "--benchmark_filter" theirs)
if(ours EQUAL -1 OR theirs EQUAL -1 OR theirs LESS ours)
  message(FATAL_ERROR "help: expected bench_cutaway's --presets, then Google Benchmark's --benchmark_filter:\n${help_out}")
endif()

refused(border "bench_cutaway: --borders: expected one of raycast\\|threshold, found 'nope'" ${BENCH_CUTAWAY} --borders=nope)
refused(size "bench_cutaway: --size: expected WxH" ${BENCH_CUTAWAY} --size=1920x)
refused(strategy "bench_cutaway: --strategies: expected one of all\\|auto\\|" ${BENCH_CUTAWAY} --strategies=jfa,nope)
refused(unknown "bench_cutaway: [^\n]*--nope" ${BENCH_CUTAWAY} --nope=1)
refused(dims "bench_volume: --volume_dims: expected INLINESxCROSSLINESxSAMPLES" ${BENCH_VOLUME} --volume_dims=20x20)

# The spellings scripts/device-benchmarks.sh and experiments/cut_strategies pass still parse, into
# the same product: 4 presets x 4 fractions x 11 strategies.
run(sweep 0 ${BENCH_CUTAWAY} --size=1920x1080 --presets=zaphirus,petra,opharine,sapphire --fractions=0.001,0.01,0.05,0.2
    --strategies=frustum,frustum-clusters,frustum-sweep,chamfer-3x3,chamfer-34,chamfer-5x5,jfa,jfa+1,jfa+2,1+jfa,jfa2
    --apertures=60 --mean_filters=0 --borders=raycast --draws=visible --poses=2 --warmup=2 --repeat=5
    --cpu_references=none --ssao=0 --baseline=0 --benchmark_list_tests=true)
string(REGEX MATCHALL "BM_cutaway/[^\n]*" listed "${sweep_out}")
list(LENGTH listed count)
if(NOT count EQUAL 176)
  message(FATAL_ERROR "sweep: expected 176 BM_cutaway benchmarks, found ${count}:\n${sweep_out}")
endif()

# Counters: each stage fenced and by timer query, and whether the queries agreed.
run(frame 0 ${BENCH_CUTAWAY} --presets=zaphirus --size=160x90 --poses=1 --strategies=frustum --cpu_references=none
    --baseline=0 --warmup=0 --repeat=1 --benchmark_format=json)
counters(frame cut_surface gpu_ms_cut_surface total gpu_ms_total gpu_query_valid)
run(cast 0 ${BENCH_VOLUME} --volume_dims=16x16x24 --volume_size=32 --benchmark_filter=gpu/grey/naive
    --benchmark_min_time=0.01 --benchmark_format=json)
counters(cast ray_cast gpu_ms_ray_cast exit_points gpu_ms_exit_points gpu_query_valid)
