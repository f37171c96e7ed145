# Runs one case for bladebench_add_case (bladebenchAddCase.cmake): BLADEBENCH, CASE, OUT, EXPECT,
# ARGS (joined by the unit separator). Fails unless the program exits with EXPECT.
string(ASCII 31 separator)
string(REPLACE "${separator}" ";" args "${ARGS}")
execute_process(COMMAND "${BLADEBENCH}" run "${CASE}" --no-plots --out "${OUT}" ${args} RESULT_VARIABLE rc)
if(NOT "${rc}" STREQUAL "${EXPECT}")
  set(meaning "0 all checks pass, 1 a check failed, 2 bad input, 3 solver failure")
  message(FATAL_ERROR "bladebench run ${CASE} exited with ${rc}, expected ${EXPECT} (${meaning}); report: ${OUT}/report.md")
endif()
