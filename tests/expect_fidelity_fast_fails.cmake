# `run --fidelity fast` must end with exit 1 (a check failed), neither passing nor crashing: the
# check it fails is the point of the test. Arguments: BIN, CASE, OUT.
execute_process(COMMAND ${BIN} run ${CASE} --fidelity fast --no-plots --out ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "expected exit 1 (a check fails), got ${rc}:\n${out}${err}")
endif()
