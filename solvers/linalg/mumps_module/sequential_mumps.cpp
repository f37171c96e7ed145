// libbladebench_mumps_seq.so: the sequential MUMPS (and its MPI stand-in), linked here and loaded by
// linalg/inertia.cpp into a symbol scope of its own, so that the MPI build of MUMPS under the
// PETSc/SLEPc plugin never resolves to it, nor it to that one.
#include <dmumps_c.h>

extern "C" void* bladebench_dmumps_c() { return reinterpret_cast<void*>(&dmumps_c); }
