# `mpirun -np N cutaway render` never overwrites its model or one output with another (issue 47):
# rank 0 compares the files before any rank reads the model, and every rank leaves on its verdict
# (exit 2, one message); a run whose stats cannot be written leaves no image. Each case checks
# the model's SHA-256 and that OUT holds nothing but the model afterwards.
# -DMPIEXEC=... -DCUTAWAY=... -DOUT=dir -DRANKS=N
include(${CMAKE_CURRENT_LIST_DIR}/refusal_checks.cmake)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(model ${OUT}/model.grdecl)
execute_process(COMMAND ${CUTAWAY} generate --dims 6 6 4 --seed 1 --quiet --out ${model} RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "generating the model failed: ${code}")
endif()
file(SHA256 ${model} model_hash)

# case name; expected stderr regex; the arguments after `render model.grdecl` (run in OUT).
function(expect_refused name expect)
  execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${RANKS} ${CUTAWAY} render model.grdecl --size 160 90 --repeat 1
                          --warmup 0 --no-metrics ${ARGN}
                  WORKING_DIRECTORY ${OUT} RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
  check_mpi_refusal(${name} "${code}" "${err}" "${out}" "${expect}")
  file(SHA256 ${model} hash)
  if(NOT hash STREQUAL model_hash)
    message(FATAL_ERROR "${name}: the model was overwritten")
  endif()
  file(GLOB left LIST_DIRECTORIES true ${OUT}/* ${OUT}/.*)
  list(REMOVE_ITEM left ${model})
  if(left)
    message(FATAL_ERROR "${name}: a refused run left ${left}")
  endif()
endfunction()

expect_refused(out_is_model "--out: expected a file other than the model's" --out model.grdecl)
expect_refused(stats_is_model "--stats: expected a file other than the model's" --out frame.png --stats ./model.grdecl)
expect_refused(cell_ids_is_model "--cell-ids: expected a file other than the model's" --out frame.png
               --cell-ids ${OUT}/model.grdecl)
expect_refused(cell_ids_is_out "--cell-ids: expected a file other than --out's" --out frame.png --cell-ids ./frame.png)
expect_refused(stats_full "/dev/full: expected the output written whole" --out frame.png --stats /dev/full)
