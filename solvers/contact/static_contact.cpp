#include "contact/static_contact.hpp"

#include <fmt/format.h>

#include <cmath>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {
namespace {

// The total potential energy at u for a fixed status (elastic, external and contact energies), given
// ku = K u.
double potential(const Eigen::VectorXd& ku, const Eigen::VectorXd& external, const std::vector<ContactPoint>& points,
                 const std::vector<char>& closed, const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap,
                 const Eigen::VectorXd& u) {
  return 0.5 * u.dot(ku) - (external.size() ? external.dot(u) : 0.0) +
         contact_energy(points, closed, penalty, initial_gap, u);
}

StaticContactSolution solve_step(const Eigen::SparseMatrix<double>& stiffness, const DofMap& dofs,
                                 const std::vector<ContactPoint>& points, const ContactPenalty& penalty,
                                 const Eigen::VectorXd& initial_gap, const Eigen::VectorXd& external,
                                 std::vector<char> closed, const StaticContactOptions& options,
                                 const std::string& step, const Eigen::VectorXd& start) {
  const int n = dofs.n_global();
  const auto n_points = static_cast<Eigen::Index>(points.size());
  const double gap_scale = n_points > 0 ? initial_gap.cwiseAbs().maxCoeff() : 0.0;
  StaticContactSolution s;
  s.displacement = start.size() == n ? start : Eigen::VectorXd::Zero(n);
  for (size_t c = 0; c < dofs.constrained_dofs.size(); ++c)
    s.displacement[dofs.constrained_dofs[c]] = dofs.prescribed[static_cast<Eigen::Index>(c)];
  SpdFactorization factor(FillOrdering::metis);
  // Outer: the status. Inner: Newton on the smooth convex energy of that status, with a backtracking
  // line search (one step when the normal law is linear, the energy then quadratic).
  for (s.iterations = 1; s.iterations <= options.max_iterations; ++s.iterations) {
    double force_scale = 0.0;
    for (int newton = 0;; ++newton) {
      const Eigen::VectorXd ku = stiffness * s.displacement;
      Eigen::VectorXd r_all = ku - contact_force(points, closed, penalty, initial_gap, s.displacement);
      if (external.size() != 0) r_all -= external;
      const Eigen::VectorXd r = free_part(dofs, r_all);
      if (newton == 0) {
        // The linear law's force of the initial gaps: the exponential one at u = 0 would be astronomic.
        force_scale = free_part(dofs, initial_gap_force(points, closed, penalty, initial_gap, n)).norm();
        if (external.size() != 0) force_scale = std::max(force_scale, free_part(dofs, external).norm());
        force_scale = std::max(force_scale, free_part(dofs, ku).norm());
      }
      if (r.norm() <= options.residual_tolerance * std::max(force_scale, 1e-300)) break;
      if (newton >= options.max_newton_iterations)
        throw SolverError(fmt::format("{}: Newton did not converge in {} iterations for the contact status of "
                                      "iteration {} (|R| = {:.3g} N, {:.3g} of the forces)",
                                      step, options.max_newton_iterations, s.iterations, r.norm(),
                                      r.norm() / std::max(force_scale, 1e-300)));
      ContactPenalty tangent = penalty;
      for (Eigen::Index k = 0; k < n_points; ++k) {
        const double g = point_motion(points[static_cast<size_t>(k)], initial_gap[k], s.displacement).gap;
        tangent.normal[k] = normal_tangent(penalty.normal[k], penalty.roughness, g);
      }
      const Partitioned k = partition(stiffness + contact_stiffness(points, closed, tangent, n), dofs);
      const FactorStatus status = factor.factorize(k.ff);
      if (!status.ok)
        throw SolverError(fmt::format("{}: K + K_contact cannot be factored ({}); a body held by contact alone "
                                      "needs every closed point sticking or a constraint",
                                      step, status.message));
      const Eigen::VectorXd du = -factor.solve(r);
      const Eigen::VectorXd du_all = to_global(dofs, du, false);
      const double e0 = potential(ku, external, points, closed, penalty, initial_gap, s.displacement);
      const double slope = r.dot(du);
      double alpha = 1.0;
      for (int halving = 0;; ++halving) {
        const Eigen::VectorXd trial = s.displacement + alpha * du_all;
        const double e = potential(stiffness * trial, external, points, closed, penalty, initial_gap, trial);
        if (std::isfinite(e) && e <= e0 + 1e-4 * alpha * slope + 1e-14 * std::abs(e0)) {
          s.displacement = trial;
          break;
        }
        if (halving == 40)
          throw SolverError(fmt::format("{}: the line search found no descent (|R| = {:.3g} N)", step, r.norm()));
        alpha *= 0.5;
      }
      ++s.newton_iterations;
    }
    if (!s.displacement.allFinite()) throw SolverError(fmt::format("{}: the solution is not finite", step));
    s.gap.resize(n_points);
    const double tol = options.gap_tolerance * std::max(gap_scale, s.displacement.cwiseAbs().maxCoeff());
    int changes = 0;
    for (Eigen::Index k = 0; k < n_points; ++k) {
      s.gap[k] = point_motion(points[static_cast<size_t>(k)], initial_gap[k], s.displacement).gap;
      char& c = closed[static_cast<size_t>(k)];
      const char now = c ? s.gap[k] <= tol : s.gap[k] < -tol;
      changes += now != c;
      c = now;
    }
    s.status_changes += changes;
    if (changes == 0) break;
  }
  if (s.iterations > options.max_iterations)
    throw SolverError(fmt::format("{}: the contact status did not settle in {} iterations ({} status changes in all)",
                                  step, options.max_iterations, s.status_changes));
  s.closed = std::move(closed);
  return s;
}

}  // namespace

StaticContactSolution solve_static_contact(const Eigen::SparseMatrix<double>& stiffness, const DofMap& dofs,
                                           const std::vector<ContactPoint>& points, const ContactPenalty& penalty,
                                           const Eigen::VectorXd& initial_gap, const Eigen::VectorXd& external,
                                           std::vector<char> closed, const StaticContactOptions& options,
                                           const std::string& context, const Eigen::VectorXd& start) {
  const int n = dofs.n_global();
  const auto n_points = static_cast<Eigen::Index>(points.size());
  if (static_cast<Eigen::Index>(closed.size()) != n_points || initial_gap.size() != n_points)
    throw std::invalid_argument("solve_static_contact: one status and one initial gap per point");
  if (external.size() != 0 && external.size() != n)
    throw std::invalid_argument("solve_static_contact: one external force per DOF");
  // Load steps: with a stiffening law and no start, the gaps and forces grow from about one
  // roughness of overlap by factors of sqrt(10), each step starting from the last one scaled, so that
  // Newton never starts tens of roughnesses deep on the exponential.
  std::vector<double> factors = {1.0};
  const double overlap = n_points > 0 ? (-initial_gap).maxCoeff() : 0.0;
  if (penalty.roughness > 0 && start.size() == 0 && overlap > 3 * penalty.roughness) {
    factors.clear();
    for (double f = penalty.roughness / overlap; f < 1.0; f *= std::sqrt(10.0)) factors.push_back(f);
    factors.push_back(1.0);
  }
  StaticContactSolution s;
  s.displacement = start;
  int iterations = 0, newton = 0, changes = 0;
  for (size_t k = 0; k < factors.size(); ++k) {
    const std::string step = fmt::format("{}, load step {} of {}", context, k + 1, factors.size());
    Eigen::VectorXd from = s.displacement;
    if (k > 0) from *= factors[k] / factors[k - 1];
    const Eigen::VectorXd scaled_external = external.size() ? Eigen::VectorXd(factors[k] * external) : external;
    s = solve_step(stiffness, dofs, points, penalty, factors[k] * initial_gap, scaled_external, closed, options, step,
                   from);
    closed = s.closed;
    iterations += s.iterations;
    newton += s.newton_iterations;
    changes += s.status_changes;
  }
  s.iterations = iterations;
  s.newton_iterations = newton;
  s.status_changes = changes;
  s.pressure = Eigen::VectorXd::Zero(n_points);
  s.shear = Eigen::VectorXd::Zero(n_points);
  s.normal_stiffness = Eigen::VectorXd::Zero(n_points);
  for (Eigen::Index k = 0; k < n_points; ++k) {
    if (!s.closed[static_cast<size_t>(k)]) continue;
    s.pressure[k] = std::max(normal_pressure(penalty.normal[k], penalty.roughness, s.gap[k]), 0.0);
    s.normal_stiffness[k] = normal_tangent(penalty.normal[k], penalty.roughness, s.gap[k]);
    s.shear[k] = penalty.tangential[k] *
                 point_motion(points[static_cast<size_t>(k)], initial_gap[k], s.displacement).slip.norm();
  }
  return s;
}

}  // namespace bb
