# Sequential MUMPS (Debian: libmumps-seq-dev): the multifrontal LDL^T whose inertia gives the
# modal solver's Sturm counts (linalg/inertia.cpp). Double precision only. MUMPS::MUMPS links it
# (the module solvers/linalg/mumps_module does, nothing else); MUMPS::headers gives its header.
find_path(MUMPS_INCLUDE_DIR NAMES dmumps_c.h PATH_SUFFIXES mumps_seq)
find_library(MUMPS_DMUMPS_LIBRARY NAMES dmumps_seq)
find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common_seq)
find_library(MUMPS_MPISEQ_LIBRARY NAMES mpiseq_seq)
find_library(MUMPS_PORD_LIBRARY NAMES pord_seq)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_INCLUDE_DIR MUMPS_DMUMPS_LIBRARY
                                  MUMPS_COMMON_LIBRARY MUMPS_MPISEQ_LIBRARY MUMPS_PORD_LIBRARY)
if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS UNKNOWN IMPORTED)
  set_target_properties(MUMPS::MUMPS PROPERTIES
    IMPORTED_LOCATION "${MUMPS_DMUMPS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${MUMPS_COMMON_LIBRARY};${MUMPS_MPISEQ_LIBRARY};${MUMPS_PORD_LIBRARY}")
endif()
if(MUMPS_FOUND AND NOT TARGET MUMPS::headers)
  add_library(MUMPS::headers INTERFACE IMPORTED)
  set_target_properties(MUMPS::headers PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}")
endif()
