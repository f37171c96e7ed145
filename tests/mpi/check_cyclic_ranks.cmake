# A cyclic_modal case (complex Hermitian nodal diameters) by the default eigensolver, then by SLEPc
# through the real form on 1 rank and under mpirun on 2: every run passes its own checks, and the
# families, Campbell rows and Sturm counts agree with the default's (compare_cyclic.py, 1e-9 in the
# eigenvalue). Arguments: BIN, CASE, WORK, MPIEXEC, MPIFLAGS (a ;-list), PYTHON.
file(REMOVE_RECURSE ${WORK})
foreach(run spectra slepc_1 slepc_2)
  set(launch "")
  set(extra "")
  if(NOT run STREQUAL "spectra")
    set(extra --set "analysis.eigensolver=\"slepc\"")
  endif()
  if(run STREQUAL "slepc_2")
    set(launch ${MPIEXEC} ${MPIFLAGS} -np 2)
  endif()
  execute_process(COMMAND ${launch} ${BIN} run ${CASE} --out ${WORK}/${run} --no-plots --no-cache ${extra}
                  RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr TIMEOUT 600)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${run}: exited ${code}, expected 0\n${stdout}\n${stderr}")
  endif()
endforeach()
foreach(run slepc_1 slepc_2)
  execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_cyclic.py ${WORK}/spectra ${WORK}/${run} 1e-9
                  RESULT_VARIABLE code OUTPUT_VARIABLE said ERROR_VARIABLE why)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${run} differs from the default eigensolver: ${why}")
  endif()
  message(STATUS "spectra -> ${run}: ${said}")
endforeach()
