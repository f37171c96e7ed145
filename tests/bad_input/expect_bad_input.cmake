# Runs one malformed case and fails unless bladebench rejects it as bad input:
#   cmake -DBIN=<bladebench> -DCASE=<case.toml> -DEXPECT=<substring> -DOUT=<dir> [-DARGS=<options>]
#         [-DSUBCOMMAND=run|calibrate] [-DPLOTS=ON] -P expect_bad_input.cmake
# Runs without plots unless PLOTS is on (a refusal that only a drawn plot can reveal).
# Passes only if
#   - the exit code is exactly 2 (bad input; not 0/1, not 3 = solver failure, not a crash),
#   - stderr has an "  error: " line and contains EXPECT. The case's own folder is stripped
#     from stderr before matching, so EXPECT can say "data/ref.csv" rather than an absolute path,
#   - OUT/summary.json exists and records "status": "bad_input".
foreach(var BIN CASE EXPECT OUT)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "expect_bad_input.cmake: -D${var}=... is required")
  endif()
endforeach()

# A stale summary.json from an earlier run must not count.
file(REMOVE_RECURSE "${OUT}")

separate_arguments(extra_args UNIX_COMMAND "${ARGS}")
set(plot_args --no-plots)
if(PLOTS)
  set(plot_args "")
endif()
if(NOT SUBCOMMAND)
  set(SUBCOMMAND run)
endif()
execute_process(
  COMMAND "${BIN}" ${SUBCOMMAND} "${CASE}" ${plot_args} --out "${OUT}" ${extra_args}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 60)

get_filename_component(case_dir "${CASE}" DIRECTORY)
string(REPLACE "${case_dir}/" "" err_rel "${err}")

set(problems "")
if(NOT "${rc}" STREQUAL "2")
  string(APPEND problems "\n  - exit code ${rc}, expected 2 (bad input)")
endif()
# run prints its verdict line, then "  error: ..."; calibrate prints "error: ..." alone.
if(SUBCOMMAND STREQUAL "calibrate")
  set(error_prefix "error: ")
else()
  set(error_prefix "  error: ")
endif()
string(FIND "${err}" "${error_prefix}" pos)
if(pos LESS 0)
  string(APPEND problems "\n  - stderr has no '${error_prefix}' line")
endif()
string(FIND "${err_rel}" "${EXPECT}" pos)
if(pos LESS 0)
  string(APPEND problems "\n  - stderr does not contain the expected text:\n      ${EXPECT}")
endif()

set(summary "${OUT}/summary.json")
if(SUBCOMMAND STREQUAL "calibrate")
  # calibrate writes its report only after a fit: a refused case leaves no folder at all.
  if(EXISTS "${OUT}")
    string(APPEND problems "\n  - ${OUT} was written for a refused calibration")
  endif()
elseif(NOT EXISTS "${summary}")
  string(APPEND problems "\n  - ${summary} was not written")
else()
  file(READ "${summary}" summary_text)
  if(NOT summary_text MATCHES "\"status\"[ \t\r\n]*:[ \t\r\n]*\"bad_input\"")
    string(REGEX MATCH "\"status\"[ \t\r\n]*:[ \t\r\n]*\"[^\"]*\"" status "${summary_text}")
    string(APPEND problems "\n  - ${summary} does not record \"status\": \"bad_input\" (found: ${status})")
  endif()
endif()

if(problems)
  message(FATAL_ERROR "bad-input case ${CASE} was not rejected properly:${problems}\n"
                      "--- stdout ---\n${out}--- stderr ---\n${err}")
endif()
message(STATUS "rejected as expected (exit 2): ${EXPECT}")
