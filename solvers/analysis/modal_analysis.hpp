// Modal analysis: lowest natural frequencies and mass-normalized shapes of the constrained model.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "linalg/modal_solver.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

struct ModalResult {
  Eigen::VectorXd frequencies_hz;
  std::vector<Eigen::MatrixXd> shapes;  // per mode: n_nodes x dim, mass-normalized
  int n_free_dofs = 0;
  int iterations = 0;
  double max_residual = 0.0;
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;
};

ModalResult solve_modal(const Model& model, const ModalOptions& options);

ResultTable frequency_table(const Eigen::VectorXd& frequencies_hz);

}  // namespace bb
