#include "timeint/static_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "linalg/damped_newton.hpp"

namespace bb::timeint {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

StaticState static_initial_state(const friction::FrictionModel& input, const StaticOptions& options) {
  friction::FrictionModel m = input;
  friction::validate_model(m, "static initial state");
  if (options.max_iterations < 1 || options.max_backtracks < 0 || !(options.tolerance > 0.0))
    throw std::invalid_argument("static initial state: max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");
  const Index n = m.mass.rows();
  const bool stuck = options.friction == StaticFriction::stuck_at_offset;
  double scale = m.static_load.norm();
  for (const friction::ContactElement& c : m.contacts) scale += (1.0 + c.point.mu) * c.point.n0;
  const double tolerance = options.tolerance * (scale + 1.0);

  const auto balance = [&](const VectorXd& q) {
    NewtonPoint p;
    p.residual = m.stiffness * q - m.static_load;
    p.jacobian = m.stiffness;
    for (const friction::ContactElement& c : m.contacts) {
      const double v = c.normal.dot(q);
      const double normal = std::max(c.point.n0 + c.point.kn * v, 0.0);
      p.residual += c.normal.transpose() * normal;
      // Semismooth choice at N0 + kn v == 0: closed, so a contact that just touches is stiff.
      if (c.point.n0 + c.point.kn * v >= 0.0) p.jacobian += c.point.kn * c.normal.transpose() * c.normal;
      if (stuck) {
        p.residual += c.tangential.transpose() * (c.point.kt * (c.tangential.dot(q) - c.tangential_offset));
        p.jacobian += c.point.kt * c.tangential.transpose() * c.tangential;
      }
    }
    return p;
  };
  const DampedNewtonResult r = damped_newton(balance, VectorXd::Zero(n),
                                             {.tolerance = tolerance,
                                              .max_iterations = options.max_iterations,
                                              .max_backtracks = options.max_backtracks,
                                              .step_solve = NewtonStepSolve::full_pivot_lu});

  StaticState s;
  // The iteration that failed (singular tangent, line search) is counted.
  s.iterations = r.iterations + (r.converged || r.status == NewtonStatus::iteration_limit ? 0 : 1);
  s.residual = r.residual;
  s.converged = r.converged;
  if (r.status == NewtonStatus::singular_jacobian)
    s.failure = fmt::format(
        "static initial state: singular tangent at iteration {} (|R| = {:.3e} N): the model is not held in some "
        "direction{}",
        s.iterations, r.residual, stuck ? "" : " with friction neglected; try StaticFriction::stuck_at_offset");
  else if (!s.converged)
    s.failure = fmt::format(
        "static initial state did not converge: |R| = {:.3e} N after {} iterations (tolerance "
        "{:.3e} N)",
        r.residual, s.iterations, tolerance);
  s.q = s.converged ? r.x : VectorXd::Zero(n);
  for (const friction::ContactElement& c : m.contacts) {
    const double w = stuck ? 0.0 : c.tangential.dot(s.q) - c.tangential_offset;
    s.sliders.push_back(w);
    s.contacts.push_back(contact_step(c, w, s.q));
  }
  return s;
}

}  // namespace bb::timeint
