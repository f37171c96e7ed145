# run under mpirun shares a harmonic-balance case's force levels out over the ranks (level i on
# rank i % ranks, each level starting from the previous level's first solution, received from the
# rank that swept it): on 2 ranks every result table is the one-process run's, cell for cell but
# the wall times; 4 ranks for 3 levels run with a warning for the idle rank and the same tables as
# those 3 levels in one process. Arguments: BIN, CASE, WORK, MPIEXEC, MPIFLAGS, PYTHON.
file(REMOVE_RECURSE ${WORK})
function(run_case name)  # ARGN: the launcher, if any, then extra arguments of run
  execute_process(COMMAND ${ARGN} --out ${WORK}/${name}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${name} exited ${code}:\n${out}\n${err}")
  endif()
  set(err "${err}" PARENT_SCOPE)
endfunction()
function(same_tables a b)
  execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_tables.py ${WORK}/${a} ${WORK}/${b}
                  RESULT_VARIABLE differ OUTPUT_VARIABLE out ERROR_VARIABLE why)
  if(differ)
    message(FATAL_ERROR "${b} against ${a}: ${why}")
  endif()
  message(STATUS "${b} against ${a}: ${out}")
endfunction()

set(RUN ${BIN} run ${CASE} --no-cache --no-plots)
run_case(serial ${RUN})
run_case(ranks2 ${MPIEXEC} ${MPIFLAGS} -np 2 ${RUN})
if(err MATCHES "shares no work")
  message(FATAL_ERROR "2 ranks said they shared no work although the case has force levels:\n${err}")
endif()
same_tables(serial ranks2)

set(THREE --set "analysis.force_levels=[300.0, 150.0, 60.0]" --unset analysis.nonlinear_modes --unset check --unset study)
run_case(serial3 ${RUN} ${THREE})
run_case(ranks4 ${MPIEXEC} ${MPIFLAGS} -np 4 ${RUN} ${THREE})
if(NOT err MATCHES "4 MPI ranks for 3 force levels: 1 ranks sweep none")
  message(FATAL_ERROR "4 ranks for 3 force levels gave no warning for the idle rank:\n${err}")
endif()
same_tables(serial3 ranks4)
