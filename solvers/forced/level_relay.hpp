// The first solution of each force level handed to the next level of the list: levels are close
// in force, so a neighbour's solution is a near start where the static one is far (Table XI at
// H = 7, 220 N: 1 819 Newton iterations from the static start).
#pragma once
#include <Eigen/Dense>

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>
#include <vector>

namespace bb {

// A converged first point: the contact-DOF harmonics, their H and the level's force [N].
struct LevelStart {
  Eigen::VectorXd x;
  int harmonics = 0;
  double force = 0.0;
};

// Levels are handed to workers in list order (common/parallel_indices.hpp), so a level waits only
// for one that has started; every level must publish once (LevelRelay::Guard makes sure), or its
// successor would wait for ever.
// Over MPI ranks (level i on rank i % ranks, each rank's levels in order on the thread that started
// MPI), a start whose successor belongs to another rank is sent there, and one whose predecessor
// does is received from it.
class LevelRelay {
 public:
  enum class Scope { threads, ranks };
  explicit LevelRelay(std::size_t levels, Scope scope = Scope::threads)
      : scope_(scope), published_(levels, false), starts_(levels) {}

  // The first solution of level - 1, once it has one or has ended without; none for level 0.
  std::optional<LevelStart> from_neighbour(std::size_t level);
  // The first call for a level counts, later ones are ignored.
  void publish(std::size_t level, std::optional<LevelStart> start);
  // Over ranks, once this rank's levels have ended: receives what was sent to a level of this rank
  // that never asked (it stopped before its first point), so that no message outlives the relay;
  // then waits until this rank's own messages have been received.
  void finish();

  // Publishes "no solution" for a level that ends (or throws) without having published.
  class Guard {
   public:
    Guard(LevelRelay& relay, std::size_t level) : relay_(relay), level_(level) {}
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;
    ~Guard();

   private:
    LevelRelay& relay_;
    std::size_t level_;
  };

 private:
  bool remote(std::size_t level) const;  // over ranks: level belongs to another rank
  Scope scope_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<bool> published_;
  std::vector<std::optional<LevelStart>> starts_;
};

// A level's place in the relay; a sweep without one starts from the static solution alone.
struct LevelLink {
  LevelRelay& relay;
  std::size_t level;
};

}  // namespace bb
