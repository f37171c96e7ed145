// The BLAS and OpenMP runtimes set up for several single-threaded factorizations at once: the
// project runs its parallel work as independent jobs (force levels, starts, nodal diameters), each
// on one core, never a library's own threads inside a job.
#pragma once

namespace bb {

// Once per process (later calls do nothing): OpenBLAS to one thread per call and CHOLMOD's OpenMP
// regions inactive. Debian's CHOLMOD opens them with a compiled-in team of 4 around loops too small
// to gain from them (sec32_root_contact: a third of its time, mostly in the kernel). Both runtimes
// are looked up, not linked: they are there only if the BLAS or CHOLMOD was built with them.
void use_one_thread_per_factorization();

// Whether two threads may call the BLAS at once. False for OpenBLAS built without threads
// (Debian's libopenblas0-serial has no locks: concurrent factorizations return wrong numbers);
// true for its pthread and OpenMP builds and for any other BLAS.
bool blas_allows_concurrent_calls();

}  // namespace bb
