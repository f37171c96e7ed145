# One case solved by the default eigensolver, then by SLEPc on 1 rank (no mpirun) and under mpirun on
# 2 and 3 ranks: every run passes its own checks, every checked value agrees with the default
# eigensolver's within 1e-9 in the eigenvalue (compare_frequencies.py), and the reports state the same
# completeness count. Arguments: BIN, CASE, WORK, MPIEXEC, MPIFLAGS (a ;-list), PYTHON, SERIAL_TOL.
file(REMOVE_RECURSE ${WORK})
get_filename_component(name ${CASE} NAME_WE)

function(run_case out)
  execute_process(COMMAND ${ARGN} ${BIN} run ${CASE} --out ${WORK}/${out}/${name} --no-plots --no-cache ${EXTRA}
                  RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr TIMEOUT 600)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${out}: exited ${code}, expected 0\n${stdout}\n${stderr}")
  endif()
  file(READ ${WORK}/${out}/${name}/report.md report)
  # The report's completeness row (not the case's description, which may quote one).
  string(REGEX MATCH "\\| completeness[^|]*\\| [0-9]+ modes below [0-9.]+ Hz, all found" row "${report}")
  string(REGEX MATCH "[0-9]+ modes below [0-9.]+ Hz" count "${row}")
  if(count STREQUAL "")
    message(FATAL_ERROR "${out}: the report states no completeness count")
  endif()
  set(count "${count}" PARENT_SCOPE)
endfunction()

set(EXTRA "")
run_case(spectra)
set(serial_count "${count}")
set(EXTRA --set "analysis.eigensolver=\"slepc\"")
run_case(slepc_1)
set(counts "slepc_1: ${count}")
foreach(ranks 2 3)
  run_case(slepc_${ranks} ${MPIEXEC} ${MPIFLAGS} -np ${ranks})
  string(APPEND counts "\nslepc_${ranks}: ${count}")
endforeach()
# Each run's count of modes below its cut, and the number of modes, as the default's.
string(REGEX MATCH "^[0-9]+" expected "${serial_count}")
foreach(line slepc_1 slepc_2 slepc_3)
  string(REGEX MATCH "${line}: [0-9]+" found "${counts}")
  if(NOT found STREQUAL "${line}: ${expected}")
    message(FATAL_ERROR "completeness counts differ from the default's (${serial_count}):\n${counts}")
  endif()
endforeach()

# Against the default eigensolver at SERIAL_TOL (1e-9 unless the case's test states its measured
# miss); between rank counts at 1e-9.
if(NOT SERIAL_TOL)
  set(SERIAL_TOL 1e-9)
endif()
foreach(pair "spectra;slepc_1;${SERIAL_TOL}" "spectra;slepc_2;${SERIAL_TOL}" "spectra;slepc_3;${SERIAL_TOL}"
             "slepc_1;slepc_2;1e-9" "slepc_1;slepc_3;1e-9")
  list(GET pair 0 old)
  list(GET pair 1 new)
  list(GET pair 2 tol)
  execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_frequencies.py
                          ${WORK}/${old}/${name}/frequencies.csv ${WORK}/${new}/${name}/frequencies.csv ${tol}
                  RESULT_VARIABLE code OUTPUT_VARIABLE said ERROR_VARIABLE why)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${new} differs from ${old}: ${why}")
  endif()
  string(APPEND counts "\n${old} -> ${new}: ${said}")
endforeach()
message(STATUS "default: ${serial_count}\n${counts}")
