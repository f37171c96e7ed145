# Debian's Ceres brings ATLAS (a dependency of libceres-dev) twice: its target lists libf77blas and
# libatlas, and its SuiteSparse search asks FindBLAS, which prefers ATLAS. Linked first, ATLAS's
# kernels then served MUMPS's factorizations instead of the OpenBLAS that run.sh installs as
# libblas.so.3 (sec32_root_contact: 70 s -> 58 s). The generic libblas.so.3 follows Debian's
# alternatives; libceres.so carries its own dependencies.
if(NOT DEFINED BLA_VENDOR)
  set(BLA_VENDOR Generic)
  set(_bb_vendor_set TRUE)
endif()
find_package(Ceres 2.1 REQUIRED)
if(_bb_vendor_set)
  unset(BLA_VENDOR)
  unset(_bb_vendor_set)
endif()
get_target_property(_bb_ceres_link Ceres::ceres INTERFACE_LINK_LIBRARIES)
list(FILTER _bb_ceres_link EXCLUDE REGEX "libf77blas|libatlas")
set_target_properties(Ceres::ceres PROPERTIES INTERFACE_LINK_LIBRARIES "${_bb_ceres_link}")
unset(_bb_ceres_link)
