# Runs bladebench with --out naming places a report cannot go and fails unless each is refused:
#   cmake -DBIN=<bladebench> -DCASE=<valid case.toml> -DWORK=<dir> -P expect_unusable_out.cmake
# Each command must exit with code 2 and print an "error: " line naming the path, write nothing
# (no summary.json, no hidden .<name>.tmp-* folder) and leave what was there untouched. Last, a
# valid run over an earlier report must replace it whole.
foreach(var BIN CASE WORK)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "expect_unusable_out.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}" "${WORK}-cases")
file(COPY "${CASE}" DESTINATION "${WORK}-cases")  # what validate would run, were --out not refused
set(CASES "${WORK}-cases")
file(MAKE_DIRECTORY "${WORK}/not_a_report")
file(WRITE "${WORK}/a_file" "precious\n")
file(WRITE "${WORK}/not_a_report/thesis.tex" "precious\n")

set(problems "")
include(${CMAKE_CURRENT_LIST_DIR}/expect_refusal.cmake)

expect_refusal("report folder ${WORK}/a_file: exists and is not a folder"
               run "${CASE}" --no-plots --out "${WORK}/a_file")
expect_refusal("report folder ${WORK}/a_file/case: ${WORK}/a_file exists and is not a folder"
               run "${CASE}" --no-plots --out "${WORK}/a_file/case")
expect_refusal("report folder ${WORK}/not_a_report: an existing folder that holds no bladebench report"
               run "${CASE}" --no-plots --out "${WORK}/not_a_report")
expect_refusal("report folder ${WORK}/.: names no folder of its own"
               run "${CASE}" --no-plots --out "${WORK}/.")
expect_refusal("error: --out ${WORK}/a_file: ${WORK}/a_file exists and is not a folder"
               validate "${CASES}" --no-plots --out "${WORK}/a_file")
expect_refusal("error: --out ${WORK}/a_file/reports: ${WORK}/a_file exists and is not a folder"
               run "${CASE}" "${CASE}" --no-plots --out "${WORK}/a_file/reports")

file(READ "${WORK}/a_file" text)
if(NOT text STREQUAL "precious\n")
  string(APPEND problems "\n  - ${WORK}/a_file was changed")
endif()
file(GLOB left RELATIVE "${WORK}" "${WORK}/*" "${WORK}/.*" "${WORK}/not_a_report/*")
list(SORT left)
if(NOT "${left}" STREQUAL "a_file;not_a_report;not_a_report/thesis.tex")
  string(APPEND problems "\n  - the refused runs left or removed files in ${WORK}: ${left}")
endif()

# A valid run over an earlier report replaces it whole, through a temporary folder that is gone after.
file(MAKE_DIRECTORY "${WORK}/report")
file(WRITE "${WORK}/report/summary.json" "{}\n")
file(WRITE "${WORK}/report/stale.csv" "from an earlier run\n")
execute_process(COMMAND "${BIN}" run "${CASE}" --no-plots --out "${WORK}/report" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT "${rc}" STREQUAL "0")
  string(APPEND problems "\n  - the valid run into ${WORK}/report exited with ${rc}\n${err}")
endif()
if(EXISTS "${WORK}/report/stale.csv" OR NOT EXISTS "${WORK}/report/summary.json")
  string(APPEND problems "\n  - ${WORK}/report was not replaced whole by the new report")
endif()
file(GLOB temporaries "${WORK}/.report.*")
if(temporaries)
  string(APPEND problems "\n  - temporary folders left: ${temporaries}")
endif()

if(problems)
  message(FATAL_ERROR "unusable --out was not refused properly:${problems}")
endif()
message(STATUS "every unusable --out refused with exit 2; a report replaced whole")
