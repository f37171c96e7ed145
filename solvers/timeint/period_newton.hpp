// Newton's method on a period map P: x(0) -> x(2 pi), shared by the two shooting methods (the exact
// flow of timeint/shooting.hpp and the Newmark map of timeint/newmark_shooting.hpp). The state is
// x = (motion [m], sliders [m]): the first `motion` entries set the scale of the tolerance, the
// contacts' sliders sit at [slider_offset, slider_offset + contacts).
//
// A contact stuck over the whole period leaves its slider free (any position repeats): its residual
// row is replaced by "slider unchanged", and its multiplier (exactly 1) is left out of the Floquet
// verdict.
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace bb::timeint {

// One period of a map from x.
struct PeriodEval {
  Eigen::VectorXd end;            // x(2 pi)
  Eigen::MatrixXd monodromy;      // d x(2 pi) / d x(0), when asked
  std::vector<char> free_slider;  // per contact: stuck over the whole period
  // Other neutral directions held: equation `row` of the period replaced by gradient . dx = 0 (a
  // rigidly stuck contact's u, which any value repeats, held where Newton has it).
  struct Held {
    Eigen::Index row;
    Eigen::RowVectorXd gradient;
  };
  std::vector<Held> held;
  int transitions = 0;  // contact transitions over the period
  std::string failure;  // empty when the period was integrated
};

using PeriodMap = std::function<PeriodEval(const Eigen::VectorXd& x, bool jacobian)>;

struct PeriodLayout {
  Eigen::Index motion = 0;         // leading entries that scale the tolerance
  Eigen::Index slider_offset = 0;  // first slider entry
};

struct PeriodNewtonResult {
  Eigen::VectorXd x;  // the periodic state (the last iterate on failure)
  PeriodEval period;  // the period from x, with its monodromy
  double residual = 0.0;
  int iterations = 0;
  int periods = 0;  // periods integrated
  bool converged = false;
  std::string failure;  // with |R| and the iteration count
};

// Converged when max |R| <= tolerance * max |x_motion|, or when a Newton correction of the motion is
// that small (the rounding floor, where |R| stops falling). Each step is backtracked on max |R|.
[[nodiscard]] PeriodNewtonResult newton_on_period(const PeriodMap& map, Eigen::VectorXd x, const PeriodLayout& layout,
                                                  double tolerance, int max_iterations, double omega_rad_s);

// The multipliers of the monodromy without the free sliders and held directions, by decreasing modulus.
[[nodiscard]] Eigen::VectorXcd floquet_multipliers(const PeriodEval& p, const PeriodLayout& layout);

}  // namespace bb::timeint
