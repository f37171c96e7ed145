# `compare-models` on the decoupled joint: exit 0 (every fit converged), and the model named in
# FIRST ranked first in ranking.csv (it predicts the held-out curves best). Arguments: BIN, OUT,
# FIRST, CASES (a ;-list), optional FLAGS (a ;-list of compare-models options, e.g. --leave-one-out).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${BIN} compare-models ${CASES} ${FLAGS} --no-plots --out ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}:\n${out}${err}")
endif()
file(STRINGS ${OUT}/ranking.csv rows)
list(GET rows 1 first)
if(NOT first MATCHES "^1,\"${FIRST}\",")
  message(FATAL_ERROR "expected ${FIRST} ranked first, ranking.csv:\n${rows}\n${err}")
endif()
message(STATUS "${err}")
