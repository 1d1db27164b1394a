# bench_distributed under mpirun: exit 0, one JSON report (rank 0's) with the benchmark, its rank
# count and a frame time; a rank left waiting in a collective would instead hang until the timeout.
# -DMPIEXEC=... -DBENCH=... -DRANKS=N
execute_process(COMMAND ${MPIEXEC} --oversubscribe -np ${RANKS} ${BENCH} --presets=zaphirus --size=160x120 --frames=2
                        --warmup=0 --benchmark_format=json
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "expected exit code 0, found ${code}\nstderr: ${err}\nstdout: ${out}")
endif()
string(REGEX MATCHALL "\"name\": \"BM_distributed_frame/zaphirus[/\"]" runs "${out}")
list(LENGTH runs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one report of BM_distributed_frame/zaphirus (rank 0's), found ${count}:\n${out}")
endif()
if(NOT out MATCHES "\"ranks\": ${RANKS}(\\.0+e\\+00)?," OR NOT out MATCHES "\"real_time\": [0-9]")
  message(FATAL_ERROR "expected \"ranks\": ${RANKS} and a real_time in the report:\n${out}")
endif()
