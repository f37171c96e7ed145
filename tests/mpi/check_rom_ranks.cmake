# A Craig-Bampton reduction with its fixed-interface modes by SLEPc and its constraint modes by
# PETSc's MUMPS Cholesky, through the command line on 1 and 2 ranks: the reduced model's frequencies
# are the default eigensolver's within 1e-9, with a number of modes and with every mode below a cut. Arguments: BIN, CASE, WORK, MPIEXEC, MPIFLAGS, PYTHON.
file(REMOVE_RECURSE ${WORK})
file(READ ${CASE} text)
string(REPLACE "[[analysis.rom]]" "[[analysis.rom]]\neigensolver = \"slepc\"" sliced "${text}")
file(WRITE ${WORK}/cantilever_rom.toml "${sliced}")
foreach(entry default slepc_1 slepc_2)
  if(entry STREQUAL "default")
    set(file ${CASE})
    set(launcher "")
  else()
    set(file ${WORK}/cantilever_rom.toml)
    set(launcher "")
    if(entry STREQUAL "slepc_2")
      set(launcher ${MPIEXEC} ${MPIFLAGS} -np 2)
    endif()
  endif()
  execute_process(COMMAND ${launcher} ${BIN} run ${file} --out ${WORK}/${entry} --no-plots --no-cache
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${entry}: exited ${code}, expected 0 (a case without checks):\n${out}\n${err}")
  endif()
endforeach()
foreach(entry slepc_1 slepc_2)
  execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_frequencies.py
                          ${WORK}/default/rom_frequencies_rom.csv ${WORK}/${entry}/rom_frequencies_rom.csv 1e-9
                  RESULT_VARIABLE code OUTPUT_VARIABLE said ERROR_VARIABLE why)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${entry}: the reduced model differs from the default eigensolver's: ${why}")
  endif()
  message(STATUS "${entry}: ${said}")
endforeach()

# Every fixed-interface mode below 3 kHz instead of 6 modes: on SLEPc the count is the slicing's own
# (no sequential MUMPS count of K_ss); the same reduced model as the default's count-then-solve.
string(REPLACE "modes = 6" "modes_below_hz = 3000.0" band_default "${text}")
string(REPLACE "modes = 6" "modes_below_hz = 3000.0" band_sliced "${sliced}")
file(WRITE ${WORK}/band_default.toml "${band_default}")
file(WRITE ${WORK}/band_sliced.toml "${band_sliced}")
foreach(entry default slepc_1 slepc_2)
  set(file ${WORK}/band_sliced.toml)
  set(launcher "")
  if(entry STREQUAL "default")
    set(file ${WORK}/band_default.toml)
  elseif(entry STREQUAL "slepc_2")
    set(launcher ${MPIEXEC} ${MPIFLAGS} -np 2)
  endif()
  execute_process(COMMAND ${launcher} ${BIN} run ${file} --out ${WORK}/band_${entry} --no-plots --no-cache
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "band, ${entry}: exited ${code}, expected 0:\n${out}\n${err}")
  endif()
endforeach()
foreach(entry slepc_1 slepc_2)
  execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_frequencies.py
                          ${WORK}/band_default/rom_frequencies_rom.csv ${WORK}/band_${entry}/rom_frequencies_rom.csv 1e-9
                  RESULT_VARIABLE code OUTPUT_VARIABLE said ERROR_VARIABLE why)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "band, ${entry}: the reduced model differs from the default eigensolver's: ${why}")
  endif()
  message(STATUS "band, ${entry}: ${said}")
endforeach()

# The same reduction with slaves the masters do not hold (no clamp, one master node: the beam turns
# about it; the full model's residual flexibility, which needs no rigid-body mode, off): bad input on every path, exit 2 naming K_ss, on 2 ranks too (MUMPS's pivot counts are
# global, so every rank refuses alike and none waits).
string(REPLACE "[[bc]]\nset = \"clamp\"\ndofs = [\"x\", \"y\"]\n" "" free "${sliced}")
string(REPLACE "masters = [\"tip\", \"mid\"]" "masters = [\"tip\"]" free "${free}")
string(REPLACE "[analysis]\n" "[analysis]\nresidual_flexibility = false\n" free "${free}")
file(WRITE ${WORK}/free_rom.toml "${free}")
foreach(entry slepc_1 slepc_2)
  set(launcher "")
  if(entry STREQUAL "slepc_2")
    set(launcher ${MPIEXEC} ${MPIFLAGS} -np 2)
  endif()
  execute_process(COMMAND ${launcher} ${BIN} run ${WORK}/free_rom.toml --out ${WORK}/free_${entry} --no-plots --no-cache
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT code EQUAL 2 OR NOT "${out}${err}" MATCHES "K_ss cannot be factored")
    message(FATAL_ERROR "${entry}, unheld slaves: exited ${code}, expected 2 naming K_ss:\n${out}\n${err}")
  endif()
  message(STATUS "${entry}, unheld slaves: exit 2")
endforeach()
