// The balances one force level of an hbm analysis is solved with, and its grid sweep: shared by
// the sweep of a level (hbm_sweep.cpp) and the grid with an H per frequency (hbm_grid_sweep.cpp).
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "forced/hbm_level.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/harmonic_truncation.hpp"
#include "hbm/sensitivity.hpp"

namespace bb {

// The balance of one level; samples = 0 leaves the choice to hbm::HarmonicBalance.
hbm::HarmonicBalance level_system(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics, int samples);

// The same with ten times spec.max_iterations per Newton start: the last resort of a first point
// or a grid frequency, where Newton from a far start approaches the solution only linearly
// (Levenberg-Marquardt steps across the contacts' kinks).
hbm::HarmonicBalance patient_level_system(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                                          int samples);

// The balances of one level, one per H, built on first use (the point scope solves its
// frequencies at different H).
class LevelSystems {
 public:
  LevelSystems(const PreparedHbm& p, const HbmSpec& spec, double force, int samples)
      : p_(p), spec_(spec), force_(force), samples_(samples) {}
  const hbm::HarmonicBalance& at(int harmonics) const;
  // The truncation probe of at(harmonics), built once (it holds a balance of up to 3 H).
  const hbm::TruncationProbe& probe(int harmonics) const;
  double force() const { return force_; }
  int samples() const { return samples_; }  // as asked for (0: automatic per H)

 private:
  const PreparedHbm& p_;
  const HbmSpec& spec_;
  double force_;
  int samples_;
  mutable std::map<int, std::unique_ptr<hbm::HarmonicBalance>> systems_;
  mutable std::map<int, std::unique_ptr<hbm::TruncationProbe>> probes_;
};

// |value - reference| / reference; 0 when both are 0, 1 when only the reference is.
double relative_change(double value, double reference);

// x (contact-DOF harmonics, layout of hbm/condensed_balance.hpp) with `harmonics` harmonics: the
// higher ones cut, or added as zero.
Eigen::VectorXd with_harmonics(const Eigen::VectorXd& x, Eigen::Index contact_dofs, int harmonics);

// The solution at omega approached from a converged solution x at w0 in `steps` equal frequency
// steps, each from the one before, stopping at the first that fails (returned): the way past a
// kink between two frequencies. Every solve's iterations are added to `iterations`.
hbm::HbmSolution approach_in_steps(const hbm::HarmonicBalance& system, double w0, Eigen::VectorXd x, double omega,
                                   int steps, int& iterations, ChordFactorization* chord = nullptr);

// The solution at omega from the last arc of a continuation that ended at or just past it (at
// least two points): the arc's two ends interpolated there, then Newton.
hbm::HbmSolution solve_on_last_arc(const hbm::HarmonicBalance& system,
                                   const std::vector<hbm::ContinuationPoint>& points, double omega);

// The point of a non-empty path nearest to omega in frequency (the first of equals): the start
// of a solve there.
const hbm::ContinuationPoint& nearest_point(const hbm::ContinuationResult& path, double omega);

// The H of path point i: the level's, or with the point scope the point's own.
inline int point_h(const HbmLevel& level, size_t i) {
  return level.point_harmonics.empty() ? level.harmonics : level.point_harmonics[i];
}

// The first frequency's solution of a level: direct Newton from `initial` (or the linear limits),
// then (H > 1) the H = 1 solution lifted to H, homotopies in the force, longer Newton solves and
// (H > 3) the solution at H - 2 lifted by two (hbm_first_solution.cpp). With initial_force, `initial` is a solution at
// that force (the previous level's), the start of the first homotopy.
hbm::HbmSolution first_solution(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics, int samples,
                                double omega, const std::optional<Eigen::VectorXd>& initial,
                                std::optional<double> initial_force = std::nullopt);

// The first frequency's solution on the branch that comes up from below: traced by pseudo-arclength
// from 5 % below omega, where the contacts stick and the static state is the seated one. A start
// whose stuck sliders sit elsewhere can lie on a branch that ends at a kink further up (Table XI,
// H = 5, 60 N swept from 172.2 Hz); the sweep is tried again from this one.
hbm::HbmSolution first_solution_from_below(const hbm::HarmonicBalance& system, double omega);

// The first frequency's solution at H harmonics (first_solution from the level's start).
using FirstSolution = std::function<hbm::HbmSolution(int harmonics)>;
// Progress of a sweep: (omega, point, iterations).
using SweepReport = std::function<void(double, int, int)>;

// The grid sweep of one level: every frequency from the cubic extrapolation of the last four
// converged points, a failed one approached in smaller steps, then bridged by arclength through a
// fold. A fixed-H sweep that does not reach its end is swept once more from
// first_solution_from_below, and kept when that one does. Fills level.path and level.failed_hz, and with the point
// scope level.point_harmonics and point_change. level.harmonics is the H of a fixed-H sweep, and the start of a
// point-scope one (which sets it to the largest H used).
void sweep_grid(const PreparedHbm& p, const HbmSpec& spec, const LevelSystems& systems, const FirstSolution& first,
                HbmLevel& level, const SweepReport& report);

// The grid frequencies [first, last] (indices into the band's fixed_grid) of a sweep around peaks.
struct GridWindow {
  int first = 0, last = 0;
};

// A level swept on windows of the band only, each from the nearest point of `around` (the same
// level at a lower H): the peaks of a higher H without sweeping the band again.
struct PeakWindows {
  const HbmLevel& around;
  std::vector<GridWindow> windows;  // ascending, disjoint
};

// The grid sweep of each window in turn (sweep_grid on its frequencies), their paths one after
// another in level.path; level.path.converged when every window's is.
void sweep_grid_windows(const PreparedHbm& p, const HbmSpec& spec, const LevelSystems& systems,
                        const PeakWindows& windows, HbmLevel& level, const SweepReport& report);

// sweep_hbm_level on windows of the band (sweep_grid_windows); a failed sweep is not retried with
// more AFT samples, and no first point is relayed to the next level.
HbmLevel sweep_hbm_level_windows(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                                 const HbmProgress& progress, const PeakWindows& windows);

// The first point's start when the model has a damper: the stuck limit's vibration with the
// contact DOFs at the damper's static pre-solve (seated by CF); nullopt without a damper.
std::optional<Eigen::VectorXd> damper_seated_start(const PreparedHbm& p, const hbm::HarmonicBalance& system,
                                                   double omega);

// d(model)/d(log p) for each of spec.sensitivities on the level's model m.
std::vector<hbm::ModelDerivative> log_derivatives(const PreparedHbm& p, const HbmSpec& spec,
                                                  const friction::FrictionModel& m);

// p d|z|/dp [m] and p d arg z/dp [deg] of each response's first harmonic z at the converged point
// (x, omega) of `system`: rows the derivatives, columns the responses; NaN where not defined.
struct ResponseDlog {
  Eigen::MatrixXd amplitude, phase_deg;
};
ResponseDlog response_dlog(const PreparedHbm& p, const hbm::HarmonicBalance& system, const Eigen::VectorXd& x,
                           double omega, const std::vector<hbm::ModelDerivative>& derivatives);

// Every peak of the level trusted and its solve converged (and there is at least one).
bool peaks_trusted(const HbmLevel& level);

}  // namespace bb
