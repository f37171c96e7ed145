// Static equilibrium of a linear elastic model with penalty contact (contact/surface_contact.hpp):
// the contact status is iterated to a fixed point (closed where the gap is negative, open where it is
// positive). With the linear law the problem is piecewise linear, one factorization of K + K_c per
// status, so this is the semismooth Newton method and ends in finitely many steps when it converges
// (Wriggers, Computational Contact Mechanics, 2nd ed., sec. 6.3.1 and 8.1); with a rough (stiffening)
// law each status is solved by Newton with a line search on its convex potential energy.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <string>
#include <vector>

#include "assembly/dof_map.hpp"
#include "contact/surface_contact.hpp"

namespace bb {

struct StaticContactOptions {
  int max_iterations = 50;
  // A closed point opens when its gap exceeds this fraction of the largest initial gap or
  // displacement (and an open one closes below minus it): rounding cannot flip a point that just
  // touches.
  double gap_tolerance = 1e-9;
  // Newton on each status (one step for the linear law): |R| below this fraction of the forces.
  double residual_tolerance = 1e-10;
  int max_newton_iterations = 100;
};

struct StaticContactSolution {
  Eigen::VectorXd displacement;  // every DOF (node * 3 + direction) [m]
  std::vector<char> closed;      // per contact point
  Eigen::VectorXd gap;           // per point [m], < 0 penetration
  Eigen::VectorXd pressure;      // per point [Pa], kn max(-g, 0) on closed points
  Eigen::VectorXd shear;         // per point [Pa], |kt slip| on closed points
  Eigen::VectorXd normal_stiffness;  // per point: the law's tangent dp/d(-g) on closed points [Pa/m]
  int iterations = 0;                // of the status
  int newton_iterations = 0;         // over all statuses
  int status_changes = 0;  // over all iterations
};

// `stiffness` on every DOF (the assembled K), `external` the applied forces on every DOF (empty:
// none); `closed` is the starting status and `start` the starting displacement (e.g. the previous
// load step's; empty: zero). Messages start with `context` and name the load step (a stiffening law
// started from zero is loaded in steps). Throws SolverError naming the load step when the status does not settle, or when
// K + K_c is singular (a body held only by frictionless contact).
StaticContactSolution solve_static_contact(const Eigen::SparseMatrix<double>& stiffness, const DofMap& dofs,
                                           const std::vector<ContactPoint>& points, const ContactPenalty& penalty,
                                           const Eigen::VectorXd& initial_gap, const Eigen::VectorXd& external,
                                           std::vector<char> closed, const StaticContactOptions& options = {},
                                           const std::string& context = "static contact",
                                           const Eigen::VectorXd& start = {});

}  // namespace bb
