// Linear static analysis: K u = f with prescribed displacements eliminated.
#pragma once
#include <Eigen/Dense>

#include "analysis/static_spec.hpp"
#include "assembly/stress_recovery.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

struct StaticSolution {
  Eigen::MatrixXd displacements;  // n_nodes x dim [m]
  Eigen::MatrixXd reactions;      // n_nodes x dim [N], nonzero only on constrained DOFs
  Eigen::VectorXd loads;          // applied nodal forces, global DOF order [N]
  int n_free_dofs = 0;
  double pivot_ratio = 0.0;        // CHOLMOD rcond estimate of the free-free stiffness
  double relative_residual = 0.0;  // ||K u - f|| / ||f|| on the free DOFs
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;  // factorization + solve
};

// Throws InputError when the model is singular (names the DOF of the zero pivot).
StaticSolution solve_static(const Model& model);

// A static analysis's run: the solution and its stresses.
struct StaticOutcome {
  StaticSolution solution;
  StressField stresses;
};

// Solves, recovers the stresses and fills `tables` with nodal_displacements, nodal_stresses,
// nodal_strains and (spec.integration_point_stresses) integration_point_stresses.
StaticOutcome run_static(const Model& model, const StaticSpec& spec, ResultTables& tables);

ResultTable nodal_displacement_table(const Mesh& mesh, const Eigen::MatrixXd& displacements);

}  // namespace bb
