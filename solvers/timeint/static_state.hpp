// Static initial condition of a time integration (thesis eq 3.49): K q + g(q) = f_static for the
// friction system of hbm/friction_system.hpp, with the contact sliders it leaves behind. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "friction/friction_system.hpp"
#include "timeint/contact_step.hpp"

namespace bb::timeint {

enum class StaticFriction {
  // Friction neglected in the static state, as damper::solve_damper_static does: only the normal
  // springs N = max(N0 + kn v, 0) act, the contacts settle with no tangential load and every slider
  // starts at its u (closed with zero tangential force). K must hold the model tangentially.
  free_slip,
  // Every contact stuck at its tangential offset: T = kt (a_t q - offset), so a model held only by
  // friction is statically determinate; sliders start at 0 (the offset).
  stuck_at_offset,
};

struct StaticOptions {
  StaticFriction friction = StaticFriction::free_slip;
  int max_iterations = 50;
  double tolerance = 1e-10;  // ||K q + g - f_static|| <= tolerance * (||f_static|| + sum (1 + mu) N0 + 1 N)
  int max_backtracks = 30;
};

struct StaticState {
  Eigen::VectorXd q;            // [m]; zero on failure
  std::vector<double> sliders;  // per contact, for NewmarkIntegrator::initial_state
  std::vector<ContactSample> contacts;
  int iterations = 0;
  double residual = 0.0;
  bool converged = false;
  std::string failure;
};

// Newton (semismooth on the max of the normal law, linalg/damped_newton.hpp with a rank-revealing
// step) with backtracking on K q + g(q) = f_static, the full model (static problems are solved
// once). Never throws on non-convergence; throws std::invalid_argument on invalid models.
[[nodiscard]] StaticState static_initial_state(const friction::FrictionModel& model, const StaticOptions& options = {});

}  // namespace bb::timeint
