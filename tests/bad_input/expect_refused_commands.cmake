# Command-line inputs that must be refused with exit 2 and an "error" naming them, and writes that must
# not replace what the command did not create (issue 70, points 1, 4 and 6):
#   cmake -DBIN=<bladebench> -DCASE=<valid case.toml> -DWORK=<dir> -P expect_refused_commands.cmake
# CASE must pass quickly (its report is the report tree that compare and html are given).
foreach(var BIN CASE WORK)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "expect_refused_commands.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(problems "")

include(${CMAKE_CURRENT_LIST_DIR}/expect_refusal.cmake)

# 4. A bound or a noise that is not a finite number of the reader's range (nan passed CLI11's
# PositiveNumber and switched the bound off).
foreach(option --max-work --max-memory)
  foreach(value nan inf -1 1e308)
    expect_refusal("${option}" run "${CASE}" --no-plots --out "${WORK}/bounds" ${option} ${value})
  endforeach()
  expect_refusal("must be finite" validate "${WORK}" --no-plots --out "${WORK}/bounds" ${option} nan)
  expect_refusal("must be finite" calibrate "${CASE}" --no-plots --out "${WORK}/bounds" ${option} nan)
endforeach()
foreach(option --noise --phase-noise-deg --frequency-noise --force-noise)
  foreach(value nan 1e308 -0.1)
    expect_refusal("${option}" synthesize "${CASE}" --table frequencies --kind peaks
                   --column frequency=frequency_hz:Hz --out "${WORK}/rig.csv" ${option} ${value})
  endforeach()
endforeach()
expect_refusal("--max-change" compare "${WORK}" "${WORK}" --max-change nan)
if(EXISTS "${WORK}/bounds" OR EXISTS "${WORK}/rig.csv")
  string(APPEND problems "\n  - a refused command wrote its output")
endif()

# A report tree for compare and html.
execute_process(COMMAND "${BIN}" run "${CASE}" --no-plots --out "${WORK}/reports/case" RESULT_VARIABLE rc
                ERROR_VARIABLE err)
if(NOT "${rc}" STREQUAL "0")
  message(FATAL_ERROR "the valid run of ${CASE} exited with ${rc}:\n${err}")
endif()
file(READ "${WORK}/reports/case/summary.json" summary_before)

# 1. compare --out inside a report tree (it replaced its own input) or on a FIFO; synthesize --out on
# its case file or a FIFO; html over a report.html that is a FIFO; run --out over a folder holding the case.
expect_refusal("lies inside the report tree" compare "${WORK}/reports" "${WORK}/reports"
               --out "${WORK}/reports/case/summary.json")
expect_refusal("lies inside the report tree" compare "${WORK}/reports/case" "${WORK}/reports"
               --out "${WORK}/reports/case/changes.md")
execute_process(COMMAND mkfifo "${WORK}/fifo" RESULT_VARIABLE rc)
if(NOT "${rc}" STREQUAL "0")
  message(FATAL_ERROR "mkfifo ${WORK}/fifo failed")
endif()
expect_refusal("${WORK}/fifo: exists and is not a regular file" compare "${WORK}/reports" "${WORK}/reports"
               --out "${WORK}/fifo")
expect_refusal("${WORK}/fifo: exists and is not a regular file" synthesize "${CASE}" --table frequencies
               --kind peaks --column frequency=frequency_hz:Hz --out "${WORK}/fifo")
file(COPY "${CASE}" DESTINATION "${WORK}/own")
get_filename_component(case_name "${CASE}" NAME)
file(READ "${WORK}/own/${case_name}" case_before)
expect_refusal("an input of this command" synthesize "${WORK}/own/${case_name}" --table frequencies
               --kind peaks --column frequency=frequency_hz:Hz --out "${WORK}/own/${case_name}")
file(WRITE "${WORK}/own/summary.json" "{}\n")  # a report folder that also holds the case
expect_refusal("an input of this command" run "${WORK}/own/${case_name}" --no-plots --out "${WORK}/own")
expect_refusal("an input of this command" calibrate "${WORK}/own/${case_name}" --no-plots --out "${WORK}/own")
file(READ "${WORK}/own/${case_name}" case_after)
if(NOT case_after STREQUAL case_before OR NOT EXISTS "${WORK}/own/summary.json")
  string(APPEND problems "\n  - a refused write changed ${WORK}/own")
endif()
file(RENAME "${WORK}/fifo" "${WORK}/reports/case/report.html")
expect_refusal("report.html: exists and is not a regular file" html "${WORK}/reports")
execute_process(COMMAND test -p "${WORK}/reports/case/report.html" RESULT_VARIABLE not_fifo)
file(READ "${WORK}/reports/case/summary.json" summary_after)
if(NOT "${not_fifo}" STREQUAL "0" OR NOT summary_after STREQUAL summary_before)
  string(APPEND problems "\n  - a refused write replaced the FIFO or changed ${WORK}/reports/case/summary.json")
endif()
file(REMOVE "${WORK}/reports/case/report.html")

# 6. A symbolic-link loop where a command looks for a file: named with exit 2, not a filesystem error.
file(MAKE_DIRECTORY "${WORK}/loops")
file(CREATE_LINK "loop_b.toml" "${WORK}/loops/loop_a.toml" SYMBOLIC)
file(CREATE_LINK "loop_a.toml" "${WORK}/loops/loop_b.toml" SYMBOLIC)
expect_refusal(".toml: cannot open (Too many levels of symbolic links)" validate "${WORK}/loops" --no-plots
               --out "${WORK}/loops_out")
file(CREATE_LINK "report.md" "${WORK}/reports/case/report.md.loop" SYMBOLIC)
file(REMOVE "${WORK}/reports/case/report.md")
file(CREATE_LINK "report.md.loop" "${WORK}/reports/case/report.md" SYMBOLIC)
expect_refusal("report.md: cannot open (Too many levels of symbolic links)" html "${WORK}/reports")
file(REMOVE "${WORK}/reports/case/summary.json")
file(CREATE_LINK "summary.json" "${WORK}/reports/case/summary.json" SYMBOLIC)
expect_refusal("summary.json: cannot open (Too many levels of symbolic links)" compare "${WORK}/reports"
               "${WORK}/reports")

if(problems)
  message(FATAL_ERROR "command-line inputs not refused properly:${problems}")
endif()
message(STATUS "every refused command exited 2 naming its input; nothing it did not create was replaced")
