# A Craig-Bampton reduction with its fixed-interface modes by SLEPc and its constraint modes by
# PETSc's MUMPS Cholesky, through the command line on 1 and 2 ranks: the reduced model's frequencies
# are the default eigensolver's within 1e-9, with a number of modes and with every mode below a cut;
# slaves that the masters do not hold are bad input. Arguments: BIN, CASE, WORK, MPIEXEC, MPIFLAGS,
# PYTHON.
file(REMOVE_RECURSE ${WORK})
file(READ ${CASE} text)
string(REPLACE "[[analysis.rom]]" "[[analysis.rom]]\neigensolver = \"slepc\"" sliced "${text}")

# Runs case text `content` as `name` for `entry` (default, slepc_1 or slepc_2: 2 ranks under mpirun);
# its exit code, output and error in run_code and run_said.
function(run_entry name entry content)
  file(WRITE ${WORK}/${name}_${entry}.toml "${content}")
  set(launcher "")
  if(entry STREQUAL "slepc_2")
    set(launcher ${MPIEXEC} ${MPIFLAGS} -np 2)
  endif()
  execute_process(COMMAND ${launcher} ${BIN} run ${WORK}/${name}_${entry}.toml --out ${WORK}/${name}_${entry}
                          --no-plots --no-cache
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  set(run_code ${code} PARENT_SCOPE)
  set(run_said "${out}\n${err}" PARENT_SCOPE)
endfunction()

# `default_text` by the default eigensolver, `sliced_text` on 1 and 2 ranks: each exits 0 (a case
# without checks) and its reduced model's frequencies are the default's within 1e-9.
function(compare_reductions name default_text sliced_text)
  foreach(entry default slepc_1 slepc_2)
    if(entry STREQUAL "default")
      run_entry(${name} ${entry} "${default_text}")
    else()
      run_entry(${name} ${entry} "${sliced_text}")
    endif()
    if(NOT run_code EQUAL 0)
      message(FATAL_ERROR "${name}, ${entry}: exited ${run_code}, expected 0:\n${run_said}")
    endif()
  endforeach()
  foreach(entry slepc_1 slepc_2)
    execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_frequencies.py
                            ${WORK}/${name}_default/rom_frequencies_rom.csv
                            ${WORK}/${name}_${entry}/rom_frequencies_rom.csv 1e-9
                    RESULT_VARIABLE code OUTPUT_VARIABLE said ERROR_VARIABLE why)
    if(NOT code EQUAL 0)
      message(FATAL_ERROR "${name}, ${entry}: the reduced model differs from the default eigensolver's: ${why}")
    endif()
    message(STATUS "${name}, ${entry}: ${said}")
  endforeach()
endfunction()

compare_reductions(modes "${text}" "${sliced}")

# Every fixed-interface mode below 3 kHz instead of 6 modes: on SLEPc the count is the slicing's own
# (no sequential MUMPS count of K_ss); the same reduced model as the default's count-then-solve.
string(REPLACE "modes = 6" "modes_below_hz = 3000.0" band_default "${text}")
string(REPLACE "modes = 6" "modes_below_hz = 3000.0" band_sliced "${sliced}")
compare_reductions(band "${band_default}" "${band_sliced}")

# Slaves the masters do not hold (no clamp, one master node: the beam turns about it; the full
# model's residual flexibility, which needs no rigid-body mode, off): bad input, exit 2 naming K_ss,
# on 2 ranks too (MUMPS's pivot counts are global, so every rank refuses alike and none waits).
string(REPLACE "[[bc]]\nset = \"clamp\"\ndofs = [\"x\", \"y\"]\n" "" free "${sliced}")
string(REPLACE "masters = [\"tip\", \"mid\"]" "masters = [\"tip\"]" free "${free}")
string(REPLACE "[analysis]\n" "[analysis]\nresidual_flexibility = false\n" free "${free}")
foreach(entry slepc_1 slepc_2)
  run_entry(free ${entry} "${free}")
  if(NOT run_code EQUAL 2 OR NOT "${run_said}" MATCHES "K_ss cannot be factored")
    message(FATAL_ERROR "unheld slaves, ${entry}: exited ${run_code}, expected 2 naming K_ss:\n${run_said}")
  endif()
  message(STATUS "unheld slaves, ${entry}: exit 2")
endforeach()
