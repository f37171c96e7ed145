# Installs the build tree into a fresh prefix, then configures, builds and runs the consumer
# project against it: fails unless find_package(bladebench) and the installed headers and library
# work from outside the source tree. Arguments: BUILD (the build tree), WORK (a scratch folder),
# CONSUMER (tests/install/consumer, or examples/), GENERATOR; RUN_CTEST=ON runs the project's own
# tests (the consumer's program and case files, or the examples) instead of its `consumer` program.
file(REMOVE_RECURSE "${WORK}")
foreach(step
        "install;--install;${BUILD};--prefix;${WORK}/prefix"
        "configure;-S;${CONSUMER};-B;${WORK}/build;-G;${GENERATOR};-DCMAKE_PREFIX_PATH=${WORK}/prefix;-DCMAKE_BUILD_TYPE=Release"
        "build;--build;${WORK}/build")
  list(POP_FRONT step name)
  execute_process(COMMAND ${CMAKE_COMMAND} ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed (${rc}):\n${out}\n${err}")
  endif()
endforeach()
if(NOT EXISTS "${WORK}/prefix/include/bladebench/hbm/harmonic_balance.hpp")
  message(FATAL_ERROR "headers not installed under include/bladebench")
endif()
if(RUN_CTEST)
  set(run ${CMAKE_CTEST_COMMAND} --test-dir ${WORK}/build --output-on-failure)
else()
  set(run ${WORK}/build/consumer)
endif()
execute_process(COMMAND ${run} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed (${rc}):\n${out}\n${err}")
endif()
