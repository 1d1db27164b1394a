# --- bench_generate: speed and peak memory of the generator on the scale presets ---------------
# Included from benchmarks/CMakeLists.txt (after CUTAWAY_BENCH_DEFINITIONS is set). Run:
#   build/bin/bench_generate --preset scale-1m  --repetitions 3 --json results/generate/scale-1m.json
#   build/bin/bench_generate --preset scale-10m --repetitions 1 --warmup 0 --json results/generate/scale-10m.json
add_executable(bench_generate ${CMAKE_CURRENT_LIST_DIR}/bench_generate.cpp)
string(TOUPPER "${CMAKE_BUILD_TYPE}" _cutaway_build_type)
target_compile_definitions(bench_generate PRIVATE ${CUTAWAY_BENCH_DEFINITIONS}
  CUTAWAY_CXX_FLAGS="${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_cutaway_build_type}}")
target_link_libraries(bench_generate PRIVATE cutaway_bench_support cutaway_generators cutaway_grid cutaway_warnings
                                             nlohmann_json::nlohmann_json)
