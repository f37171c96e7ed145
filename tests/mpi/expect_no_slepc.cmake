# eigensolver = "slepc" in a build without the plugin: exit 2, the key named and how to get it.
# Arguments: BIN, CASE, WORK, MPIEXEC (may be empty or NOTFOUND).
execute_process(COMMAND ${BIN} run ${CASE} --set "analysis.eigensolver=\"slepc\"" --out ${WORK} --no-plots --no-cache
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT 60)
if(NOT code EQUAL 2 OR NOT err MATCHES "eigensolver" OR NOT err MATCHES "libslepc-real-dev")
  message(FATAL_ERROR "exit ${code}, expected 2 naming analysis.eigensolver and libslepc-real-dev:\n${out}\n${err}")
endif()

# Under mpirun such a build runs the command on rank 0 alone (a warning); the other ranks stop at once.
if(MPIEXEC AND EXISTS "${MPIEXEC}")
  execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe -np 2 ${BIN} run ${CASE} --out ${WORK}/ranks
                          --no-plots --no-cache
                  RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT 120)
  string(REGEX MATCHALL "pass \\(" runs "${out}${err}")
  list(LENGTH runs count)
  if(NOT code EQUAL 0 OR NOT err MATCHES "rank 0 runs alone" OR NOT count EQUAL 1)
    message(FATAL_ERROR "mpirun -np 2 without the plugin exited ${code} with ${count} runs, expected 0, one run and "
                        "a warning:\n${out}\n${err}")
  endif()
endif()
