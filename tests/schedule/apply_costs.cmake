# Read by ctest after every test of the tree is declared (CMakeLists.txt here): each listed test's
# COST. A name not in the run is ignored by ctest; check_costs.cmake catches a renamed one.
include(${CMAKE_CURRENT_LIST_DIR}/test_costs.cmake)
list(LENGTH BB_TEST_COSTS bb_cost_count)
math(EXPR bb_cost_last "${bb_cost_count} - 1")
foreach(i RANGE 0 ${bb_cost_last} 2)
  math(EXPR j "${i} + 1")
  list(GET BB_TEST_COSTS ${i} bb_test)
  list(GET BB_TEST_COSTS ${j} bb_seconds)
  set_tests_properties(${bb_test} PROPERTIES COST ${bb_seconds})
endforeach()
