# eigensolver = "slepc" in a build without the plugin: exit 2, the key named and how to get it.
execute_process(COMMAND ${BIN} run ${CASE} --set "analysis.eigensolver=\"slepc\"" --out ${WORK} --no-plots --no-cache
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT 60)
if(NOT code EQUAL 2 OR NOT err MATCHES "eigensolver" OR NOT err MATCHES "libslepc-real-dev")
  message(FATAL_ERROR "exit ${code}, expected 2 naming analysis.eigensolver and libslepc-real-dev:\n${out}\n${err}")
endif()
