# `cutaway inspect` as a user runs it: JSON on stdout for the Reek grid, a CSV with one row per
# active cell, a preset generated in memory, and a clear message with a non-zero exit for a missing
# file, a malformed one and an unknown preset.
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${CUTAWAY} inspect ${DATA}/grdecl/reek/reek_sim_grid.grdecl
                        ${DATA}/grdecl/reek/reek_sim_poro.grdecl --json --cells-csv ${OUT}/reek_cells.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "inspect failed (${rc}): ${err}")
endif()
string(JSON active GET "${out}" active_cells)
string(JSON faults GET "${out}" faces fault)
string(JSON poro GET "${out}" properties 0)
if(NOT active EQUAL 35838 OR faults LESS 1000 OR NOT poro STREQUAL "PORO")
  message(FATAL_ERROR "unexpected report: active ${active}, fault faces ${faults}, property ${poro}")
endif()
file(STRINGS ${OUT}/reek_cells.csv rows)
list(LENGTH rows n)
list(GET rows 0 head)
if(NOT n EQUAL 35839 OR NOT head STREQUAL "i,j,k,volume,cx,cy,cz")
  message(FATAL_ERROR "cells CSV: ${n} lines, header '${head}'")
endif()

execute_process(COMMAND ${CUTAWAY} inspect ${OUT}/does-not-exist.grdecl RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "does-not-exist.grdecl.*no such file")
  message(FATAL_ERROR "missing file: exit ${rc}, message '${err}'")
endif()

file(WRITE ${OUT}/truncated.grdecl "SPECGRID\n 1 1 1 /\nCOORD\n 0 0 0 0 0 1 /\n")
execute_process(COMMAND ${CUTAWAY} inspect ${OUT}/truncated.grdecl RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "truncated.grdecl:4: keyword COORD: expected 24 values, found 6")
  message(FATAL_ERROR "truncated file: exit ${rc}, message '${err}'")
endif()

# A preset is generated in memory, as `render preset:NAME` does: zaphirus is 30 x 50 x 5.
execute_process(COMMAND ${CUTAWAY} inspect preset:zaphirus --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "inspect preset:zaphirus failed (${rc}): ${err}")
endif()
string(JSON cells GET "${out}" cells)
string(JSON active GET "${out}" active_cells)
string(JSON shell GET "${out}" faces shell)
if(NOT cells EQUAL 7500 OR active LESS 1 OR active GREATER 7500 OR shell LESS 1)
  message(FATAL_ERROR "preset report: cells ${cells}, active ${active}, shell faces ${shell}")
endif()
execute_process(COMMAND ${CUTAWAY} inspect preset:nope RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "preset:nope: expected preset:NAME with NAME one of zaphirus, petra")
  message(FATAL_ERROR "unknown preset: exit ${rc}, message '${err}'")
endif()

# Each property's range and percentiles, so a user can choose --range: ordered, p2..p98 inside min..max.
execute_process(COMMAND ${CUTAWAY} inspect ${DATA}/grdecl/reek/reek_sim_grid.grdecl ${DATA}/grdecl/reek/reek_sim_poro.grdecl --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(previous -1e30)
foreach(key min p2 p25 p50 p75 p98 max)
  string(JSON value GET "${out}" property_ranges PORO ${key})
  if(value LESS previous)
    message(FATAL_ERROR "PORO ${key} ${value} below the previous statistic ${previous}")
  endif()
  set(previous ${value})
endforeach()
