# `cutaway` on OPM Flow's output as a user runs it (the eclipse_flow fixture wrote CASES/spe1 and
# CASES/spe9): a report step rendered from CASE.EGRID, the report steps and wells of
# `inspect --json` (by case name, without extension), the CSV's property columns, and one-line
# refusals with exit 2 for a step out of range and a restart of another grid.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(spe1 ${CASES}/spe1/SPE1CASE2)
set(spe9 ${CASES}/spe9/SPE9)

execute_process(COMMAND ${CUTAWAY} render ${spe1}.EGRID --property SWAT --time-step 5 --range 0.5 1 --size 320 240
                        --out ${OUT}/spe1_swat_5.png --stats ${OUT}/spe1_swat_5.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/spe1_swat_5.png)
  message(FATAL_ERROR "render SPE1 SWAT step 5 failed (${rc}): ${err}")
endif()
file(READ ${OUT}/spe1_swat_5.json stats)
string(JSON label GET "${stats}" property name)
if(NOT label STREQUAL "SWAT step 5")
  message(FATAL_ERROR "render SPE1: property '${label}', expected 'SWAT step 5'")
endif()
# The frame says which step it shows, with the case's date, as animate's frames do.
string(JSON caption GET "${stats}" property caption)
if(NOT caption MATCHES "^SWAT  [0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]  \\(step 5 of 0-[0-9]+\\)$")
  message(FATAL_ERROR "render SPE1: caption '${caption}', expected 'SWAT  YYYY-MM-DD  (step 5 of 0-N)'")
endif()
execute_process(COMMAND ${CUTAWAY} render ${spe1}.EGRID --property SWAT --time-step 5 --range 0.5 1 --size 320 240
                        --no-caption --out ${OUT}/spe1_plain.png --stats ${OUT}/spe1_plain.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
file(READ ${OUT}/spe1_plain.json stats)
string(JSON caption GET "${stats}" property caption)
if(NOT rc EQUAL 0 OR NOT caption STREQUAL "")
  message(FATAL_ERROR "render SPE1 --no-caption (${rc}): caption '${caption}', expected none; ${err}")
endif()

# --step is the older name of --time-step.
execute_process(COMMAND ${CUTAWAY} render ${spe9} --property SWAT --step 80 --range 0.5 1 --size 320 240
                        --out ${OUT}/spe9_swat_80.png --stats ${OUT}/spe9_swat_80.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
file(READ ${OUT}/spe9_swat_80.json stats)
string(JSON primaries GET "${stats}" primary_cells)
if(NOT rc EQUAL 0 OR primaries LESS 1)
  message(FATAL_ERROR "render SPE9 SWAT step 80 (${rc}): ${primaries} primary cells; ${err}")
endif()

execute_process(COMMAND ${CUTAWAY} inspect ${spe9} --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "inspect SPE9 failed (${rc}): ${err}")
endif()
string(JSON wells LENGTH "${out}" wells)
string(JSON steps LENGTH "${out}" report_steps)
string(JSON last_report GET "${out}" report_steps 89 report)
string(JSON last_date GET "${out}" report_steps 89 date)
string(JSON swat_steps GET "${out}" dynamic_properties SWAT)
string(JSON soil_steps GET "${out}" dynamic_properties SOIL)
string(JSON unit_system GET "${out}" unit_system)
# SPE9.DATA: 26 wells (INJE1 and PRODU2..PRODU26), TSTEP 90*10 days from 1 JAN 2015.
if(NOT wells EQUAL 26 OR NOT steps EQUAL 90 OR NOT last_report EQUAL 90 OR NOT last_date STREQUAL "2017-06-19"
   OR NOT swat_steps EQUAL 90 OR NOT soil_steps EQUAL 90 OR NOT unit_system STREQUAL "FIELD")
  message(FATAL_ERROR "inspect SPE9: ${wells} wells, ${steps} steps, last report ${last_report} on ${last_date}, "
                      "SWAT ${swat_steps} steps, SOIL ${soil_steps}, units ${unit_system}")
endif()

execute_process(COMMAND ${CUTAWAY} inspect ${spe1}.EGRID --cells-csv ${OUT}/spe1_cells.csv --property PORO
                        --property SWAT --property SOIL --time-step 5
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
file(STRINGS ${OUT}/spe1_cells.csv rows)
list(LENGTH rows n)
list(GET rows 0 head)
list(GET rows 1 first)
string(REPLACE "," ";" first "${first}")
list(GET first 7 poro)
if(NOT rc EQUAL 0 OR NOT n EQUAL 301 OR NOT head STREQUAL "i,j,k,volume,cx,cy,cz,PORO,SWAT,SOIL" OR NOT poro STREQUAL "0.3")
  message(FATAL_ERROR "cells CSV (${rc}): ${n} lines, header '${head}', first PORO '${poro}'; ${err}")
endif()

execute_process(COMMAND ${CUTAWAY} render ${spe1}.EGRID --property SWAT --time-step 120 --out ${OUT}/beyond.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "^cutaway: --time-step 120: expected a report step 0..119 of .*SPE1CASE2.UNRST \\(120 steps\\)\n$"
   OR EXISTS ${OUT}/beyond.png)
  message(FATAL_ERROR "step out of range: exit ${rc}, message '${err}'")
endif()

# SPE9's restart beside SPE1's grid: a restart of another grid.
file(MAKE_DIRECTORY ${OUT}/mixed)
file(COPY_FILE ${spe1}.EGRID ${OUT}/mixed/MIXED.EGRID)
file(COPY_FILE ${spe9}.UNRST ${OUT}/mixed/MIXED.UNRST)
execute_process(COMMAND ${CUTAWAY} inspect ${OUT}/mixed/MIXED --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "MIXED.UNRST: array INTEHEAD at report 1: expected a restart of the EGRID's grid"
   OR NOT out STREQUAL "")
  message(FATAL_ERROR "restart of another grid: exit ${rc}, message '${err}', output '${out}'")
endif()

# animate reads a case's restart one report step at a time: SPE9's SWAT over steps 10-12, two frames
# per step (5 frames), each frame's primaries within the range and every primary pixel exposed.
execute_process(COMMAND ${CUTAWAY} animate ${spe9}.EGRID --property SWAT --range 0.5 1 --size 160 120 --steps 10 12
                        --frames-per-step 2 --mean-filter 0 --out ${OUT}/spe9.mp4 --stats ${OUT}/spe9_animate.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/spe9.mp4)
  message(FATAL_ERROR "animate SPE9: exit ${rc}, message '${err}'")
endif()
file(READ ${OUT}/spe9_animate.json stats)
string(JSON frames LENGTH "${stats}" frames)
string(JSON steps GET "${stats}" property report_steps)
string(JSON exposure GET "${stats}" primary_exposure_min)
string(JSON primaries GET "${stats}" frames 0 primary_cells)
# 90 report steps in the file; about 2,700 cells of SPE9 hold SWAT above 0.5 (its water zone)
if(NOT frames EQUAL 5 OR NOT steps EQUAL 90 OR NOT exposure EQUAL 1 OR primaries LESS 2000)
  message(FATAL_ERROR "animate SPE9: ${frames} frames, ${steps} report steps, exposure ${exposure}, ${primaries} primaries")
endif()
