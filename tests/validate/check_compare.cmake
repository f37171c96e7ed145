# `bladebench compare` through the command line: two validate runs of the same cases are unchanged
# (exit 0); a tightened tolerance flips verdicts (exit 1, named on the page); a folder of case
# files is not a report tree (exit 2, the path named). Arguments: BIN, SOURCE, WORK.
file(REMOVE_RECURSE ${WORK})
file(READ ${SOURCE}/cases/verification/cantilever_modal_q4.toml text)
string(REPLACE "../../references/" "${SOURCE}/references/" text "${text}")
file(WRITE ${WORK}/before/cantilever.toml "${text}")
string(REPLACE "rel_tol = 0.01" "rel_tol = 1e-3" tight "${text}")
file(WRITE ${WORK}/after/cantilever.toml "${tight}")

function(bladebench)
  execute_process(COMMAND ${BIN} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  set(rc ${code} PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

foreach(run old same)
  bladebench(validate ${WORK}/before --out ${WORK}/${run} --no-plots --no-cache)
endforeach()
bladebench(validate ${WORK}/after --out ${WORK}/new --no-plots --no-cache)

bladebench(compare ${WORK}/old ${WORK}/same --out ${WORK}/same.md)
if(NOT rc EQUAL 0 OR NOT err MATCHES "compare: unchanged: 1 cases")
  message(FATAL_ERROR "compare of two runs of the same case exited ${rc}, expected 0 (unchanged):\n${err}")
endif()
if(NOT EXISTS ${WORK}/same.html)
  message(FATAL_ERROR "compare --out same.md wrote no same.html")
endif()

bladebench(compare ${WORK}/old ${WORK}/new --out ${WORK}/new.md)
file(READ ${WORK}/new.md page)
if(NOT rc EQUAL 1 OR NOT page MATCHES "\\*\\*pass -> fail\\*\\*" OR NOT page MATCHES "frequency_hz mode 4")
  message(FATAL_ERROR "compare after a tightened tolerance exited ${rc}, expected 1 naming the flips:\n${err}\n${page}")
endif()

bladebench(compare ${WORK}/before ${WORK}/new)
if(NOT rc EQUAL 2 OR NOT err MATCHES "before: not a report tree")
  message(FATAL_ERROR "compare on a folder of case files exited ${rc}, expected 2 naming it:\n${err}")
endif()
bladebench(compare ${WORK}/old ${WORK}/no_such_folder)
if(NOT rc EQUAL 2 OR NOT err MATCHES "no_such_folder: not a folder")
  message(FATAL_ERROR "compare on a missing folder exited ${rc}, expected 2 naming it:\n${err}")
endif()
