#include "contact/static_contact.hpp"

#include <fmt/format.h>

#include "assembly/assemble.hpp"
#include "common/errors.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {

StaticContactSolution solve_static_contact(const Eigen::SparseMatrix<double>& stiffness, const DofMap& dofs,
                                           const std::vector<ContactPoint>& points, const ContactPenalty& penalty,
                                           const Eigen::VectorXd& initial_gap, const Eigen::VectorXd& external,
                                           std::vector<char> closed, const StaticContactOptions& options,
                                           int load_step, int load_steps) {
  const int n = dofs.n_global();
  const auto n_points = static_cast<Eigen::Index>(points.size());
  if (static_cast<Eigen::Index>(closed.size()) != n_points || initial_gap.size() != n_points)
    throw std::invalid_argument("solve_static_contact: one status and one initial gap per point");
  if (external.size() != 0 && external.size() != n)
    throw std::invalid_argument("solve_static_contact: one external force per DOF");
  const double gap_scale = n_points > 0 ? initial_gap.cwiseAbs().maxCoeff() : 0.0;
  const std::string step = fmt::format("static contact, load step {} of {}", load_step, load_steps);
  StaticContactSolution s;
  SpdFactorization factor(FillOrdering::metis);
  for (s.iterations = 1; s.iterations <= options.max_iterations; ++s.iterations) {
    const Partitioned k = partition(stiffness + contact_stiffness(points, closed, penalty, n), dofs);
    Eigen::VectorXd f_all = initial_gap_force(points, closed, penalty, initial_gap, n);
    if (external.size() != 0) f_all += external;
    Eigen::VectorXd f(dofs.n_free);
    for (int i = 0; i < dofs.n_free; ++i) f[i] = f_all[dofs.free_dofs[static_cast<size_t>(i)]];
    if (!dofs.constrained_dofs.empty()) f -= k.fc * dofs.prescribed;
    const FactorStatus status = factor.factorize(k.ff);
    if (!status.ok)
      throw SolverError(fmt::format("{}: K + K_contact cannot be factored ({}); a body held by contact alone needs "
                                    "every closed point sticking or a constraint",
                                    step, status.message));
    const Eigen::VectorXd u_free = factor.solve(f);
    s.displacement = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < dofs.n_free; ++i) s.displacement[dofs.free_dofs[static_cast<size_t>(i)]] = u_free[i];
    for (size_t c = 0; c < dofs.constrained_dofs.size(); ++c)
      s.displacement[dofs.constrained_dofs[c]] = dofs.prescribed[static_cast<Eigen::Index>(c)];
    if (!s.displacement.allFinite()) throw SolverError(fmt::format("{}: the solution is not finite", step));
    s.gap.resize(n_points);
    const double tol = options.gap_tolerance * std::max(gap_scale, s.displacement.cwiseAbs().maxCoeff());
    int changes = 0;
    for (Eigen::Index k_point = 0; k_point < n_points; ++k_point) {
      const ContactPoint& p = points[static_cast<size_t>(k_point)];
      s.gap[k_point] = initial_gap[k_point] + p.normal.dot(relative_displacement(p, s.displacement));
      char& c = closed[static_cast<size_t>(k_point)];
      const char now = c ? s.gap[k_point] <= tol : s.gap[k_point] < -tol;
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
  s.pressure = Eigen::VectorXd::Zero(n_points);
  s.shear = Eigen::VectorXd::Zero(n_points);
  for (Eigen::Index k_point = 0; k_point < n_points; ++k_point) {
    if (!s.closed[static_cast<size_t>(k_point)]) continue;
    const ContactPoint& p = points[static_cast<size_t>(k_point)];
    s.pressure[k_point] = penalty.normal[k_point] * std::max(-s.gap[k_point], 0.0);
    const Eigen::Vector3d du = relative_displacement(p, s.displacement);
    s.shear[k_point] = penalty.tangential[k_point] * (du - p.normal.dot(du) * p.normal).norm();
  }
  return s;
}

}  // namespace bb
