# `cutaway render` as a user runs it: a frame with stats.json holding the DESIGN.md keys, and a
# clear message with the documented exit code for each kind of bad input.
file(MAKE_DIRECTORY ${OUT})
set(REEK ${DATA}/grdecl/reek/reek_sim_grid.grdecl ${DATA}/grdecl/reek/reek_sim_poro.grdecl)

execute_process(COMMAND ${CUTAWAY} render ${REEK} --size 320 240 --repeat 1 --baseline
                        --out ${OUT}/reek.png --stats ${OUT}/reek.json --cell-ids ${OUT}/reek_ids.png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/reek.png)
  message(FATAL_ERROR "render failed (${rc}): ${err}")
endif()
file(READ ${OUT}/reek.json stats)
foreach(stage cut_surface secondary primary ssao mean_filter total)
  string(JSON ms GET "${stats}" stages_ms ${stage})
  if(NOT ms GREATER 0)
    message(FATAL_ERROR "stages_ms.${stage} = ${ms}")
  endif()
endforeach()
if(NOT EXISTS ${OUT}/reek_ids.png)
  message(FATAL_ERROR "--cell-ids wrote no image")
endif()
foreach(key gl_query_ms gl_query_valid gl_renderer lp_num_threads size cells primary_cells primary_exposure
            context_kept border_line_width baseline_ms git_revision configuration faces_drawn bricks_culled
            cells_culled frame_ms_unfenced baseline_faces_drawn readback_bytes cut_device)
  string(JSON value ERROR_VARIABLE missing GET "${stats}" ${key})
  if(missing)
    message(FATAL_ERROR "stats.json has no ${key}")
  endif()
endforeach()
# Memory by phase: resident bytes after load, set-up and frames never exceed the peak, which is non-zero.
string(JSON peak GET "${stats}" memory_bytes peak_resident)
if(NOT peak GREATER 0)
  message(FATAL_ERROR "memory_bytes.peak_resident ${peak}, expected > 0")
endif()
foreach(phase resident_after_load resident_after_setup resident_after_frames)
  string(JSON resident GET "${stats}" memory_bytes ${phase})
  if(NOT resident GREATER 0 OR resident GREATER peak)
    message(FATAL_ERROR "memory_bytes.${phase} ${resident}, expected in (0, peak ${peak}]")
  endif()
endforeach()
string(JSON readback GET "${stats}" readback_bytes)
if(NOT readback EQUAL 0)  # the default strategy (frustum) runs on the GPU
  message(FATAL_ERROR "readback_bytes ${readback}, expected 0")
endif()
string(JSON primaries GET "${stats}" primary_cells)
if(NOT primaries EQUAL 358)  # 1% of 35,838 active cells, rounded
  message(FATAL_ERROR "primary_cells ${primaries}, expected 358")
endif()

function(expect_failure name code pattern)
  execute_process(COMMAND ${CUTAWAY} render ${ARGN} --out ${OUT}/${name}.png RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL ${code} OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${name}: exit ${rc} (expected ${code}), message '${err}'")
  endif()
endfunction()

expect_failure(unknown_property 2 "--property SATURATION: not in the model \\(static: PORO" ${REEK} --property SATURATION)
expect_failure(huge_image 2 "--size: expected a finite number in \\[16, 32768\\] pixels, found .100000." ${REEK} --size 100000 100)
expect_failure(bad_border 2 "--border: expected one of raycast\\|threshold, found 'wide'" ${REEK} --border wide)
expect_failure(bad_kernel 2 "--mean-filter-kernel: expected one of full\\|sampled\\|distance-scaled, found 'box'" ${REEK} --mean-filter-kernel box)
expect_failure(bad_aperture 2 "--aperture: expected .*\\[0, 180\\] degrees" ${REEK} --aperture 181 30)
expect_failure(bad_draw 2 "--draw: expected one of visible\\|all-faces, found 'some'" ${REEK} --draw some)
expect_failure(bad_ssao_resolution 2 "--ssao-resolution: expected one of half\\|full, found 'quarter'" ${REEK} --ssao-resolution quarter)
# Choices are checked by the parser from the settings' name tables, before any file is read: a
# missing model file is not reached.
expect_failure(bad_strategy 2 "--strategy: expected one of auto\\|frustum\\|.*, found 'nope'" ${OUT}/missing.grdecl --strategy nope)
expect_failure(no_device 4 "OpenGL: EGL platform 'device': no hardware EGL device" ${REEK} --egl-platform device)
file(WRITE ${OUT}/nan.grdecl "SPECGRID\n 1 1 1 1 F /\nCOORD\n 0 0 0 0 0 1  1 0 0 1 0 1  0 1 0 0 1 1  1 1 0 1 1 1 /\nZCORN\n 4*0 4*1 /\nPORO\n nan /\n")
expect_failure(nan_property 2 "property PORO: NaN in active cell \\(i,j,k\\) = \\(0,0,0\\)" ${OUT}/nan.grdecl)

# An empty primary set still renders the context, and says so.
execute_process(COMMAND ${CUTAWAY} render ${REEK} --range 5 6 --size 160 120 --repeat 1 --no-metrics --out ${OUT}/empty.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err MATCHES "no cell of PORO lies in the primary range" OR NOT EXISTS ${OUT}/empty.png)
  message(FATAL_ERROR "empty selection: exit ${rc}, message '${err}'")
endif()
