# `cutaway generate-seismic` then `cutaway volume` on its output and on f3.sgy with the caster
# CASTER; checks the PNG and the stats JSON; then the refusals (exit 2, file named).
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${CUTAWAY} generate-seismic --dims 20 24 40 --seed 3 --format int16 --out ${OUT}/cube.sgy
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "generate-seismic failed (${rc}): ${err}")
endif()

foreach(cube ${OUT}/cube.sgy ${DATA}/segy/f3.sgy)
  file(REMOVE ${OUT}/image.png ${OUT}/stats.json)
  execute_process(COMMAND ${CUTAWAY} volume ${cube} --tf layer --caster ${CASTER} --size 96 80 --camera 30 20 0
                          --repeat 2 --out ${OUT}/image.png --stats ${OUT}/stats.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/image.png)
    message(FATAL_ERROR "volume ${cube} failed (${rc}): ${err}")
  endif()
  file(READ ${OUT}/stats.json stats)
  string(JSON samples GET "${stats}" samples)
  string(JSON rays GET "${stats}" rays)
  string(JSON ray_cast_ms GET "${stats}" stages_ms ray_cast)
  string(JSON tf GET "${stats}" configuration transfer_function name)
  string(JSON width GET "${stats}" configuration size 0)
  string(JSON threads GET "${stats}" lp_num_threads)
  string(JSON renderer GET "${stats}" gl_renderer)
  if(samples LESS 1 OR rays LESS 100 OR NOT tf STREQUAL "layer" OR NOT width EQUAL 96 OR threads STREQUAL ""
     OR renderer STREQUAL "" OR ray_cast_ms STREQUAL "")
    message(FATAL_ERROR "unexpected stats for ${cube}: ${stats}")
  endif()
endforeach()

execute_process(COMMAND ${CUTAWAY} volume ${DATA}/segy/broken.sgy --caster ${CASTER} --out ${OUT}/broken.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "broken.sgy: truncated")
  message(FATAL_ERROR "broken.sgy: exit ${rc}, message '${err}'")
endif()
execute_process(COMMAND ${CUTAWAY} volume ${DATA}/segy/1x1.sgy --caster ${CASTER} --out ${OUT}/prestack.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "1x1.sgy: pre-stack")
  message(FATAL_ERROR "1x1.sgy: exit ${rc}, message '${err}'")
endif()
