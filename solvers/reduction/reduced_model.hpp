// A reduced model: small dense M and K over named DOFs (master node directions, then modal
// coordinates), and optionally the matrix that expands a reduced solution back to the mesh.
// Built by Craig-Bampton here, or exported by Ansys / NX and read from files.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

namespace bb {

// One reduced DOF: a nodal translation ("T2.x") or a modal coordinate ("mode 3").
struct ReducedDof {
  std::string label;   // node label, e.g. "T2"; empty for a modal coordinate
  int direction = -1;  // 0 = x, 1 = y, 2 = z; -1 for a modal coordinate
  int mode = 0;        // 1-based fixed-interface mode number; 0 for a nodal DOF

  std::string name() const;                                         // "T2.x" or "mode 3"
  static std::optional<ReducedDof> parse(const std::string& name);  // inverse of name()
  bool operator==(const ReducedDof&) const = default;
};

struct ReducedModel {
  Eigen::MatrixXd stiffness;  // symmetric positive semi-definite
  Eigen::MatrixXd mass;       // symmetric positive definite
  std::vector<ReducedDof> dofs;
  // Free DOFs of the full model x reduced DOFs: u_full = recovery * q. Empty when imported.
  Eigen::MatrixXd recovery;
  // Fixed-interface (slaves-clamped) natural frequencies of the kept modes [Hz]; empty when unknown.
  Eigen::VectorXd fixed_interface_frequencies_hz;

  int size() const { return static_cast<int>(dofs.size()); }
  // Index of nodal DOF label.direction, or std::nullopt.
  std::optional<int> index_of(const std::string& label, int direction) const;
};

// Throws InputError, the message starting with `source`, when sizes disagree, a matrix is not
// symmetric (relative 1e-8 of its largest entry), has a non-finite entry, M is not positive
// definite or K is indefinite (an eigenvalue below -1e-8 of the largest), or a DOF name repeats.
void validate_reduced_model(const ReducedModel& model, const std::string& source);

// Why `c` cannot be the damping matrix of a forced response ("" when it can): not symmetric
// (relative 1e-8 of its largest entry), or not positive semi-definite (negative damping feeds
// energy in: no steady response balances it).
std::string damping_matrix_problem(const Eigen::MatrixXd& c);

}  // namespace bb
