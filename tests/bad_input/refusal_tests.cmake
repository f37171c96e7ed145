# bb_add_refusal_tests(DIR PREFIX LABEL OUT): one test PREFIX.<stem> per DIR/*.toml, each a case that
# bladebench must refuse as bad input (expect_bad_input.cmake). The first line of a file is
# "# expect: <part of the error message>"; a line "# args: <options>" adds options to the run and
# "# command: calibrate" runs `bladebench calibrate` instead of `bladebench run`; "# plots: drawn"
# runs it with its plots (they are skipped otherwise).
function(bb_add_refusal_tests dir prefix label out)
  file(GLOB cases CONFIGURE_DEPENDS ${dir}/*.toml)
  foreach(case_file IN LISTS cases)
    get_filename_component(stem ${case_file} NAME_WE)
    # Editing the expectation must re-run the configure step.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${case_file})
    # Read apart: a line with an unbalanced '[' would join list elements.
    file(STRINGS ${case_file} first_line LIMIT_COUNT 1)
    if(NOT first_line MATCHES "^# expect: (.+)$")
      message(FATAL_ERROR "${case_file}: the first line must be '# expect: <part of the error message>'")
    endif()
    string(STRIP "${CMAKE_MATCH_1}" expect)
    file(STRINGS ${case_file} directives REGEX "^# (args|command|plots): ")
    set(run_args "")
    set(command run)
    set(plots OFF)
    foreach(line IN LISTS directives)
      if(line MATCHES "^# args: (.+)$")
        string(STRIP "${CMAKE_MATCH_1}" run_args)
      elseif(line MATCHES "^# command: (run|calibrate)$")
        set(command ${CMAKE_MATCH_1})
      elseif(line MATCHES "^# plots: drawn$")
        set(plots ON)
      endif()
    endforeach()
    add_test(NAME ${prefix}.${stem}
             COMMAND ${CMAKE_COMMAND} -DBIN=$<TARGET_FILE:bladebench> -DCASE=${case_file} "-DEXPECT=${expect}"
                     "-DARGS=${run_args}" -DSUBCOMMAND=${command} -DPLOTS=${plots} -DOUT=${out}/${stem}
                     -P ${PROJECT_SOURCE_DIR}/tests/bad_input/expect_bad_input.cmake)
    set_tests_properties(${prefix}.${stem} PROPERTIES LABELS ${label} TIMEOUT 120)
  endforeach()
endfunction()
