#include "distributed/distributed.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "common/errors.hpp"
#include "common/run_time_module.hpp"
#include "distributed/plugin.hpp"

namespace bb::distributed {
namespace {

struct State {
  std::once_flag once;
  const bb_plugin* plugin = nullptr;
  std::string failure;  // why the plugin could not start
  bool started = false;
  bool shared = true;
  int shared_work = 0;
};

State& state() {
  static State s;
  return s;
}

std::vector<std::string> plugin_candidates() {
  std::vector<std::string> c;
  if (const char* p = std::getenv("BLADEBENCH_SLEPC_PLUGIN"); p && *p) c.emplace_back(p);
#ifdef BB_SLEPC_PLUGIN_BUILD
  c.emplace_back(BB_SLEPC_PLUGIN_BUILD);
#endif
#ifdef BB_SLEPC_PLUGIN_INSTALL
  c.emplace_back(BB_SLEPC_PLUGIN_INSTALL);
#endif
  return c;
}

// The plugin in a symbol scope of its own (common/run_time_module.hpp): its PETSc links the MPI build
// of MUMPS, the Sturm counts the sequential one (linalg/inertia.cpp).
void load(State& s) {
  const bb_plugin* p = nullptr;
  try {
    using Entry = const bb_plugin* (*)();
    p = reinterpret_cast<Entry>(
        run_time_module_entry(plugin_candidates(), "bladebench_plugin", "the PETSc/SLEPc plugin"))();
  } catch (const SolverError& e) {
    s.failure = e.what();
    return;
  }
  if (!p || p->abi_version != BB_PLUGIN_ABI_VERSION) {
    s.failure = fmt::format("the PETSc/SLEPc plugin found is not this build's (interface version {}, expected {})",
                            p ? p->abi_version : -1, BB_PLUGIN_ABI_VERSION);
    return;
  }
  char message[512] = {0};
  if (p->initialize(message, sizeof message) != 0) {
    s.failure = fmt::format("MPI / PETSc / SLEPc did not start: {}", message);
    return;
  }
  s.plugin = p;
  s.started = true;
  std::atexit([] { finish(); });  // a program that never calls finish() still ends MPI cleanly
}

}  // namespace

bool built_with_slepc() {
#ifdef BB_SLEPC_PLUGIN_BUILD
  return true;
#else
  return false;
#endif
}

const bb_plugin& plugin(const std::string& what_needs_it) {
  if (!built_with_slepc())
    throw InputError(fmt::format(
        "{}: this bladebench was built without PETSc/SLEPc. Install Debian's libslepc-real-dev and "
        "libpetsc-real-dev (./run.sh does), then configure again (cmake --preset release) to build the plugin",
        what_needs_it));
  State& s = state();
  std::call_once(s.once, [&] { load(s); });
  if (!s.plugin) throw SolverError(fmt::format("{}: {}", what_needs_it, s.failure));
  return *s.plugin;
}

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

bool start_if_launched() {
  if (!launched_by_mpi()) return true;
  if (!built_with_slepc()) {
    // The launcher's environment still tells the rank; the others leave so that rank 0 alone writes.
    int launched_rank = 0;
    for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
      if (const char* r = std::getenv(v); r && *r) {
        launched_rank = std::atoi(r);
        break;
      }
    if (launched_rank != 0) return false;
    std::fprintf(stderr,
                 "warning: started by mpirun, but this bladebench was built without PETSc/SLEPc: rank 0 runs "
                 "alone, the other ranks stop\n");
    return true;
  }
  plugin("mpirun");
  return true;
}

void finish() {
  State& s = state();
  if (s.started) s.plugin->finalize();
  s.started = false;
}

int rank() { return state().started ? state().plugin->rank() : 0; }
int size() { return state().started ? state().plugin->size() : 1; }

std::vector<std::size_t> share_of_rank(std::size_t count, int rank) {
  std::vector<std::size_t> runs;
  for (auto i = static_cast<std::size_t>(rank); i < count; i += static_cast<std::size_t>(size())) runs.push_back(i);
  return runs;
}

void set_shared_solves(bool shared) { state().shared = shared; }
bool shared_solves() { return state().shared; }

void count_shared_work() { ++state().shared_work; }
int shared_work_count() { return state().shared_work; }

void max_over_ranks(std::vector<int>& values) {
  if (size() > 1 && state().plugin->allreduce_max(values.data(), static_cast<int>(values.size())) != 0)
    throw SolverError("MPI_Allreduce over the ranks failed");
}

std::vector<std::string> gather_from_all(const std::string& mine) {
  const int ranks = size();
  if (ranks == 1) return {mine};
  const bb_plugin& p = *state().plugin;
  std::vector<int64_t> sizes(static_cast<size_t>(ranks));
  if (p.allgather_sizes(static_cast<int64_t>(mine.size()), sizes.data()) != 0)
    throw SolverError("MPI_Allgather of the ranks' result sizes failed");
  int64_t total = 0;
  for (int64_t n : sizes) total += n;
  std::string all(static_cast<size_t>(total), '\0');
  if (p.allgather_bytes(mine.data(), static_cast<int64_t>(mine.size()), sizes.data(), all.data()) != 0)
    throw SolverError("MPI_Allgatherv of the ranks' results failed (or they exceed 2 GB)");
  std::vector<std::string> out;
  size_t at = 0;
  for (int64_t n : sizes) {
    out.push_back(all.substr(at, static_cast<size_t>(n)));
    at += static_cast<size_t>(n);
  }
  return out;
}

void send_to(int to, int tag, const std::string& bytes) {
  if (size() > 1 && state().plugin->send_bytes(to, tag, bytes.data(), static_cast<int64_t>(bytes.size())) != 0)
    throw SolverError(fmt::format("MPI_Isend to rank {} failed", to));
}

std::string receive_from(int from, int tag) {
  if (size() == 1) throw SolverError("a message from another rank was awaited without MPI");
  const bb_plugin& p = *state().plugin;
  int64_t n = 0;
  if (p.probe_bytes(from, tag, &n) != 0) throw SolverError(fmt::format("MPI_Probe for rank {} failed", from));
  std::string bytes(static_cast<size_t>(n), '\0');
  if (p.receive_bytes(from, tag, bytes.data(), n) != 0)
    throw SolverError(fmt::format("MPI_Recv from rank {} failed", from));
  return bytes;
}

void complete_sends() {
  if (size() > 1 && state().plugin->complete_sends() != 0) throw SolverError("MPI_Wait for a sent message failed");
}

void abort_all(int exit_code) {
  if (size() > 1) state().plugin->abort_all(exit_code);
}

}  // namespace bb::distributed
