# calibrate under mpirun shares its starts out over the ranks: on 2 ranks, and on 4 for 3 starts (a
# warning for the idle rank), the identification, every start's result and the convergence history
# are the run's in one process, file for file. Arguments: BIN, CASE, WORK, MPIEXEC, MPIFLAGS.
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${BIN} calibrate ${CASE} --out ${WORK}/serial --no-plots
                RESULT_VARIABLE code ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "calibrate in one process exited ${code}:\n${err}")
endif()
foreach(ranks 2 4)
  execute_process(COMMAND ${MPIEXEC} ${MPIFLAGS} -np ${ranks} ${BIN} calibrate ${CASE} --out ${WORK}/ranks${ranks} --no-plots
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "calibrate on ${ranks} ranks exited ${code}:\n${out}\n${err}")
  endif()
  foreach(f identification.csv starts.csv convergence.csv)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/serial/${f} ${WORK}/ranks${ranks}/${f}
                    RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "calibrate on ${ranks} ranks: ${f} differs from the run in one process")
    endif()
  endforeach()
endforeach()
if(NOT err MATCHES "4 MPI ranks for 3 starts: 1 ranks ran none")
  message(FATAL_ERROR "calibrate on 4 ranks for 3 starts gave no warning for the idle rank:\n${err}")
endif()
