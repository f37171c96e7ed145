# validate under mpirun shares the cases out over the ranks: the index lists every case once with the
# verdicts of a run in one process (bladebench compare, exit 0), a rank without a case is a warning,
# and a solve that fails on one rank of a run stops every rank with exit 3 and its message, no hang.
# Arguments: BIN, SOURCE, WORK, MPIEXEC, MPIFLAGS (a ;-list).
file(REMOVE_RECURSE ${WORK})
foreach(c cantilever_modal_q4 nafems_fv52_pair_cut)
  file(READ ${SOURCE}/cases/verification/${c}.toml text)
  string(REPLACE "../../references/" "${SOURCE}/references/" text "${text}")
  file(WRITE ${WORK}/cases/${c}.toml "${text}")
endforeach()

execute_process(COMMAND ${BIN} validate ${WORK}/cases --out ${WORK}/serial --no-plots --no-cache
                RESULT_VARIABLE code ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "validate in one process exited ${code}:\n${err}")
endif()
execute_process(COMMAND ${MPIEXEC} ${MPIFLAGS} -np 3 ${BIN} validate ${WORK}/cases --out ${WORK}/ranks --no-plots --no-cache
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 0 OR NOT err MATCHES "3 ranks for 2 cases" OR NOT err MATCHES "2 cases: 2 passed")
  message(FATAL_ERROR "validate on 3 ranks exited ${code}, expected 0 with a warning for the idle rank:\n${out}\n${err}")
endif()
execute_process(COMMAND ${BIN} compare ${WORK}/serial ${WORK}/ranks RESULT_VARIABLE code OUTPUT_VARIABLE page)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "validate on 3 ranks differs from validate in one process:\n${page}")
endif()
file(READ ${WORK}/ranks/index.md index)
foreach(c cantilever_modal_q4 nafems_fv52_pair_cut)
  if(NOT index MATCHES "${c}")
    message(FATAL_ERROR "index.md of the ranked run lacks ${c}:\n${index}")
  endif()
endforeach()

# A solve that fails on one rank while the other waits in it (BLADEBENCH_FAULT_RANK=1): every rank
# stops with exit 3 and the failing rank's message, no hang.
execute_process(COMMAND ${CMAKE_COMMAND} -E env BLADEBENCH_FAULT_RANK=1
                        ${MPIEXEC} ${MPIFLAGS} -np 2 ${BIN} run ${WORK}/cases/nafems_fv52_pair_cut.toml
                        --set "analysis.eigensolver=\"slepc\"" --out ${WORK}/failing --no-plots --no-cache
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 3 OR NOT "${out}${err}" MATCHES "MPI rank 1 of 2: SLEPc[^\n]*fault injected")
  message(FATAL_ERROR "a solve failing on rank 1 of 2 exited ${code}, expected 3 with that rank's message:\n${out}\n${err}")
endif()

# More ranks than work: a case with nothing to share runs on every rank, exit 0, with a warning.
execute_process(COMMAND ${MPIEXEC} ${MPIFLAGS} -np 2 ${BIN} run ${WORK}/cases/cantilever_modal_q4.toml
                        --out ${WORK}/unshared --no-plots --no-cache
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 0 OR NOT err MATCHES "shares no work over them")
  message(FATAL_ERROR "a case without shared work on 2 ranks exited ${code}, expected 0 with a warning:\n${out}\n${err}")
endif()
