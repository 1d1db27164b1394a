# `mpirun -np N cutaway render` refusing what it cannot do: exit 2, one message from rank 0, no output.
# -DMPIEXEC=... -DCUTAWAY=... -DOUT=dir -DRANKS=N -DEXPECT=regex -DARGS="a;b;c"
include(${CMAKE_CURRENT_LIST_DIR}/refusal_checks.cmake)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${RANKS} ${CUTAWAY} render ${ARGS} --size 160 90 --out ${OUT}/frame.png
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
check_mpi_refusal(render "${code}" "${err}" "${out}" "${EXPECT}")
if(EXISTS ${OUT}/frame.png)
  message(FATAL_ERROR "a refused run left ${OUT}/frame.png")
endif()
