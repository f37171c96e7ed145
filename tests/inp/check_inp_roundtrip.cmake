# A case's mesh written as a CalculiX deck (export-calculix) and read back as [mesh] kind = "inp"
# gives the case's natural frequencies to 1e-10: the deck's nodes, elements, *BOUNDARY sets and
# material carry the whole model. Arguments: BIN, SOURCE, WORK, CASE (e.g. thesis/table06_glued_modal),
# MODES.
file(REMOVE_RECURSE ${WORK})
get_filename_component(name ${CASE} NAME)

function(bladebench)
  execute_process(COMMAND ${BIN} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  set(rc ${code} PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

bladebench(run ${SOURCE}/cases/${CASE}.toml --out ${WORK}/original --no-plots --no-cache)
if(NOT EXISTS ${WORK}/original/frequencies.csv)
  message(FATAL_ERROR "the original case ${CASE} wrote no frequencies.csv (exit ${rc}):\n${err}")
endif()
file(MAKE_DIRECTORY ${WORK}/deck)
bladebench(export-calculix ${SOURCE}/cases/${CASE}.toml --out ${WORK}/deck/model.inp --modes ${MODES})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "export-calculix ${CASE} exited ${rc}:\n${err}")
endif()

# No [material] and no [[bc]]: the deck's *MATERIAL and *BOUNDARY are the model's.
file(WRITE ${WORK}/deck/roundtrip.toml "[case]
name = \"${name}_inp\"
title = \"${CASE} read back from its CalculiX deck\"

[mesh]
kind = \"inp\"
file = \"model.inp\"

[analysis]
type = \"modal\"
modes = ${MODES}

[[check]]
name = \"frequencies of the deck read back = the case's\"
result = \"frequencies\"
reference = \"../original/frequencies.csv\"
key = \"mode\"
compare = { frequency_hz = \"frequency_hz\" }
rel_tol = 1e-10
abs_tol = 1e-9  # rigid-body modes: 0 Hz in both
source = \"bladebench run of ${CASE}\"
")
bladebench(run ${WORK}/deck/roundtrip.toml --out ${WORK}/roundtrip --no-plots --no-cache)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the deck read back missed the case's frequencies (exit ${rc}):\n${err}")
endif()
file(READ ${WORK}/roundtrip/report.md report)
if(NOT report MATCHES "deck model.inp")
  message(FATAL_ERROR "the report does not name the deck as the mesh's source")
endif()
