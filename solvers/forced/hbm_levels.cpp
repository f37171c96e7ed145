#include "forced/hbm_levels.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <functional>
#include <mutex>
#include <string>

#include "common/errors.hpp"
#include "common/parallel_indices.hpp"
#include "common/progress_clock.hpp"
#include "distributed/byte_record.hpp"
#include "distributed/distributed.hpp"
#include "forced/hbm_level_bytes.hpp"

namespace bb {
namespace {

HbmLevel sweep_one(const PreparedHbm& prepared, const HbmSpec& spec, size_t i, const HbmProgress& progress,
                   LevelRelay& relay) {
  const LevelRelay::Guard published(relay, i);
  const LevelLink link{relay, i};
  const double f = spec.force_levels[i];
  return spec.harmonic_tolerance > 0.0 ? sweep_hbm_level_adaptive(prepared, spec, f, progress, &link)
                                       : sweep_hbm_level(prepared, spec, f, spec.harmonics, progress, true, &link);
}

// Levels are handed out in list order, so a level waits only for one that has started.
std::vector<HbmLevel> sweep_on_threads(const PreparedHbm& prepared, const HbmSpec& spec, const HbmProgress& progress) {
  const size_t n = spec.force_levels.size();
  std::vector<HbmLevel> levels(n);
  ProgressClock clock(static_cast<int>(n));
  std::mutex report;  // the progress line and the clock, from every worker
  int done = 0;
  const HbmProgress timed = with_clock_locked(progress, clock, report);
  LevelRelay relay(n);
  for_each_index(n, worker_count(n, spec.threads), [&](size_t i) {
    levels[i] = sweep_one(prepared, spec, i, timed, relay);
    const std::lock_guard<std::mutex> lock(report);
    clock.finished(++done);
  });
  return levels;
}

// What a rank sends of one level: the level, or the error it ended with and its kind.
enum class Ended : int { swept = 0, bad_input = 1, solver_failed = 2, other = 3 };

std::string record(Ended how, const std::string& what) {
  distributed::ByteWriter w;
  w.put(static_cast<int>(how)).put(what);
  return w.bytes();
}

std::string swept_or_error(const std::function<HbmLevel()>& sweep) {
  try {
    return record(Ended::swept, to_bytes(sweep()));
  } catch (const InputError& e) {
    return record(Ended::bad_input, e.what());
  } catch (const SolverError& e) {
    return record(Ended::solver_failed, e.what());
  } catch (const std::exception& e) {
    return record(Ended::other, e.what());
  }
}

[[noreturn]] void rethrow(Ended how, const std::string& what) {
  if (how == Ended::bad_input) throw InputError(what);
  if (how == Ended::solver_failed) throw SolverError(what);
  throw std::runtime_error(what);
}

// Eigensolves inside a level belong to that level's rank alone while the ranks share out levels.
class SolvesOnThisRank {
 public:
  SolvesOnThisRank() : before_(distributed::shared_solves()) { distributed::set_shared_solves(false); }
  SolvesOnThisRank(const SolvesOnThisRank&) = delete;
  SolvesOnThisRank& operator=(const SolvesOnThisRank&) = delete;
  ~SolvesOnThisRank() { distributed::set_shared_solves(before_); }

 private:
  bool before_;
};

// Level i on rank i % ranks, each rank's in order on its one thread (MPI is started funneled); then
// every rank receives every level.
std::vector<HbmLevel> sweep_over_ranks(const PreparedHbm& prepared, const HbmSpec& spec, const HbmProgress& progress) {
  const size_t n = spec.force_levels.size();
  const int ranks = distributed::size();
  if (distributed::is_root() && static_cast<size_t>(ranks) > n)
    std::fprintf(stderr, "warning: %d MPI ranks for %zu force levels: %zu ranks sweep none\n", ranks, n,
                 static_cast<size_t>(ranks) - n);
  if (n > 1) distributed::count_shared_work();
  std::vector<std::string> mine;
  {
    const SolvesOnThisRank scope;
    LevelRelay relay(n, LevelRelay::Scope::ranks);
    for (size_t i : distributed::share_of_rank(n, distributed::rank()))
      mine.push_back(swept_or_error([&] { return sweep_one(prepared, spec, i, progress, relay); }));
    relay.finish();
  }
  distributed::ByteWriter w;
  w.put(mine);
  const std::vector<std::string> all = distributed::gather_from_all(w.bytes());
  std::vector<HbmLevel> levels(n);
  std::vector<std::pair<Ended, std::string>> ended(n, {Ended::swept, ""});
  for (int r = 0; r < ranks; ++r) {
    distributed::ByteReader in(all[static_cast<size_t>(r)]);
    std::vector<std::string> records;
    in.get(records);
    const std::vector<size_t> theirs = distributed::share_of_rank(n, r);
    if (records.size() != theirs.size())
      throw SolverError(fmt::format("rank {} sent {} of its {} levels", r, records.size(), theirs.size()));
    for (size_t k = 0; k < theirs.size(); ++k) {
      distributed::ByteReader rec(records[k]);
      int how = 0;
      std::string what;
      rec.get(how);
      rec.get(what);
      ended[theirs[k]] = {static_cast<Ended>(how), what};
      if (static_cast<Ended>(how) == Ended::swept) levels[theirs[k]] = level_from_bytes(what);
    }
  }
  for (const auto& [how, what] : ended)
    if (how != Ended::swept) rethrow(how, what);
  return levels;
}

}  // namespace

std::vector<HbmLevel> sweep_levels(const PreparedHbm& prepared, const HbmSpec& spec, const HbmProgress& progress) {
  // Ranks share out levels only where they share the case (a run), not where each runs its own.
  if (distributed::size() > 1 && distributed::shared_solves()) return sweep_over_ranks(prepared, spec, progress);
  return sweep_on_threads(prepared, spec, progress);
}

}  // namespace bb
