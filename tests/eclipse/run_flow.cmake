# Runs OPM Flow on a copy of a shared deck (a CTest fixture: the simulator's own EGRID, INIT and
# UNRST for the tests that read them). Arguments (-D):
#   FLOW      the flow program
#   DECK_DIR  folder with DECK and the files it INCLUDEs (every *.DATA there is copied)
#   DECK      the deck's file name, e.g. SPE1CASE2.DATA
#   OUT       the case folder, emptied first; flow writes CASE.EGRID, CASE.INIT, CASE.UNRST there
#   RPTRST    optional: the deck's RPTRST record replaced by this one (e.g. 'BASIC=2' for every report step)
#   RPTRST_WAS  the record text RPTRST replaces (required with RPTRST)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(GLOB decks ${DECK_DIR}/*.DATA)
foreach(source ${decks})
  get_filename_component(name ${source} NAME)
  file(READ ${source} text)
  if(name STREQUAL DECK AND DEFINED RPTRST)
    string(FIND "${text}" "${RPTRST_WAS}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${source}: expected the record ${RPTRST_WAS} to replace, found none")
    endif()
    string(REPLACE "${RPTRST_WAS}" "${RPTRST}" text "${text}")
  endif()
  file(WRITE ${OUT}/${name} "${text}")
endforeach()
execute_process(COMMAND ${FLOW} ${DECK} --output-dir=${OUT}
                WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc OUTPUT_FILE ${OUT}/flow.log ERROR_FILE ${OUT}/flow.err)
string(REGEX REPLACE "\\.DATA$" "" case ${DECK})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "flow ${DECK} failed (${rc}); see ${OUT}/flow.log and ${OUT}/flow.err")
endif()
foreach(extension EGRID UNRST)
  if(NOT EXISTS ${OUT}/${case}.${extension})
    message(FATAL_ERROR "flow ${DECK} wrote no ${case}.${extension} in ${OUT}")
  endif()
endforeach()
