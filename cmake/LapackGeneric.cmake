# LAPACK for the dense LU of the Newton steps (solvers/linalg/dense_lu.cpp), found as Debian's
# generic liblapack.so.3, which follows the alternatives (the OpenBLAS that run.sh installs), not
# ATLAS, which FindLAPACK prefers otherwise (see CeresWithOpenBlas.cmake).
if(NOT DEFINED BLA_VENDOR)
  set(BLA_VENDOR Generic)
  set(_bb_lapack_vendor_set TRUE)
endif()
find_package(LAPACK REQUIRED)
if(_bb_lapack_vendor_set)
  unset(BLA_VENDOR)
  unset(_bb_lapack_vendor_set)
endif()
