# bladebench_add_case(NAME CASE [LABELS label...] [EXPECT_EXIT 0-3] [TIMEOUT seconds] [OUT folder]
#                     [ARGS arg...])
#
# A ctest test that runs `bladebench run CASE` (the installed program) and passes when it exits
# with EXPECT_EXIT (default 0: every check within its tolerance). bladebench's exit codes: 0 all
# checks pass, 1 a check failed, 2 bad input, 3 solver failure; any other code fails the test too.
# The report goes to OUT (default <build>/bladebench-reports/NAME), the model cache to
# <build>/bladebench-model-cache. ARGS are passed on (e.g. --set analysis.harmonics=3). Labels:
# `bladebench` and LABELS.
set(_BLADEBENCH_RUN_CASE_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/bladebenchRunCase.cmake")

function(bladebench_add_case name case_file)
  cmake_parse_arguments(PARSE_ARGV 2 BB "" "EXPECT_EXIT;TIMEOUT;OUT" "LABELS;ARGS")
  if(BB_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "bladebench_add_case(${name}): unknown arguments ${BB_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET bladebench::bladebench)
    message(FATAL_ERROR "bladebench_add_case(${name}): find_package(bladebench) first")
  endif()
  get_filename_component(case_path "${case_file}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT EXISTS "${case_path}")
    message(FATAL_ERROR "bladebench_add_case(${name}): no case file ${case_path}")
  endif()
  if(NOT DEFINED BB_EXPECT_EXIT)
    set(BB_EXPECT_EXIT 0)
  endif()
  if(NOT BB_EXPECT_EXIT MATCHES "^[0-3]$")
    message(FATAL_ERROR "bladebench_add_case(${name}): EXPECT_EXIT must be 0, 1, 2 or 3, found '${BB_EXPECT_EXIT}'")
  endif()
  if(NOT BB_OUT)
    set(BB_OUT "${CMAKE_BINARY_DIR}/bladebench-reports/${name}")
  endif()
  # A list cannot pass through add_test's command line: the arguments travel joined by a control
  # character that no case path or setting contains.
  string(ASCII 31 separator)
  string(JOIN "${separator}" args ${BB_ARGS})
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} "-DBLADEBENCH=$<TARGET_FILE:bladebench::bladebench>" "-DCASE=${case_path}"
                   "-DOUT=${BB_OUT}" "-DEXPECT=${BB_EXPECT_EXIT}" "-DARGS=${args}" -P "${_BLADEBENCH_RUN_CASE_SCRIPT}")
  set_tests_properties(${name} PROPERTIES LABELS "bladebench;${BB_LABELS}"
                                          ENVIRONMENT "BLADEBENCH_CACHE_DIR=${CMAKE_BINARY_DIR}/bladebench-model-cache")
  if(BB_TIMEOUT)
    set_tests_properties(${name} PROPERTIES TIMEOUT ${BB_TIMEOUT})
  endif()
endfunction()
