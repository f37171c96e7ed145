# expect_refusal(<expected text> <bladebench arguments>...): runs ${BIN} with the arguments and appends
# to `problems` in the caller unless it exits 2 with stderr containing the text. Included by the
# scripts that check refusals of the command line (expect_unusable_out.cmake, expect_refused_commands.cmake).
function(expect_refusal expect)
  execute_process(COMMAND "${BIN}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(NOT "${rc}" STREQUAL "2")
    string(APPEND problems "\n  - bladebench ${ARGN}: exit code ${rc}, expected 2\n${err}")
  endif()
  string(FIND "${err}" "${expect}" pos)
  if(pos LESS 0)
    string(APPEND problems "\n  - bladebench ${ARGN}: stderr does not contain\n      ${expect}\n    it is:\n${err}")
  endif()
  set(problems "${problems}" PARENT_SCOPE)
endfunction()
