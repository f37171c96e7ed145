// Work beyond one process: MPI start-up under mpirun and what a run needs to know of its ranks
// (the PETSc/SLEPc plugin itself: distributed/plugin.hpp, for the solves that call it).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace bb::distributed {

// Whether this build has the plugin (CMake found PETSc and SLEPc).
bool built_with_slepc();

// Whether this process was started by mpirun / mpiexec (Open MPI, MPICH or PMIx environment).
bool launched_by_mpi();

// At program start: under mpirun, load the plugin and start MPI so that the ranks are known before
// any output is written. False for a process that must not run the command: under mpirun in a build
// without the plugin, every rank but 0 (rank 0 runs alone, with a warning).
bool start_if_launched();
// MPI finalized, if this process started it.
void finish();

int rank();  // 0 without MPI
int size();  // 1 without MPI
inline bool is_root() { return rank() == 0; }

// Independent runs 0..count-1 shared out over the ranks: rank r takes r, r + size(), ... (every one
// without MPI), and run i belongs to rank i % size().
std::vector<std::size_t> share_of_rank(std::size_t count, int rank);
inline int owner_of(std::size_t run) { return static_cast<int>(run % static_cast<std::size_t>(size())); }

// Whether eigensolves span every rank (one case run by all ranks) or stay on each rank (the ranks
// share out independent runs). Default: every rank.
void set_shared_solves(bool shared);
bool shared_solves();

// Work shared by the ranks of one case so far (an eigensolve over every rank, force levels shared
// out); a run under mpirun with none computed the same on each rank.
void count_shared_work();
int shared_work_count();

// Element-wise maximum over the ranks; unchanged without MPI.
void max_over_ranks(std::vector<int>& values);
// Every rank's `mine`, in rank order, on every rank; {mine} without MPI.
std::vector<std::string> gather_from_all(const std::string& mine);
// Point to point, for runs that hand a result on to the next (a force level's first solution to the
// rank of the next level). `bytes` go to rank `to` without waiting for their receipt; receive_from
// waits for the next message from `from` with `tag`; complete_sends waits until every message this
// rank sent has been received. MPI calls only from the thread that started MPI.
void send_to(int to, int tag, const std::string& bytes);
std::string receive_from(int from, int tag);
void complete_sends();

// Every rank stops with this exit code (mpirun reports it); returns only without MPI.
void abort_all(int exit_code);

}  // namespace bb::distributed
