// Modes of a cyclically symmetric structure from one sector, nodal diameter by nodal diameter,
// each with its own completeness (Sturm) count, and the count that ties them to the whole
// structure: the whole has, below any frequency, the sum over k of the sector's count for k,
// twice for 0 < k < N/2.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <vector>

#include "cyclic/cyclic_projection.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {

struct NodalDiameterModes {
  int nodal_diameter = 0;
  bool pairs = false;              // 0 < k < N/2: each frequency belongs to a cosine and a sine wave
  Eigen::VectorXd frequencies_hz;  // ascending, each family once
  // Sector free DOFs of each family's wave (columns): cosine part, and sine part (zero unless pairs).
  Eigen::MatrixXd cosine, sine;
  int reduced_size = 0;  // real unknowns of the problem solved (a travelling wave: twice its complex ones)
  int iterations = 0;
  int lanczos_runs = 0;
  int sturm_count = -1;  // families below sturm_frequency_hz (each pair once)
  double sturm_frequency_hz = 0.0;
  double max_residual = 0.0;
  double seconds = 0.0;
};

// The lowest `families` of nodal diameter k (more when a repeated frequency straddles the last).
// `options.n_modes` is ignored. Throws InputError when the reduced problem is smaller than asked,
// SolverError as lowest_modes does.
NodalDiameterModes nodal_diameter_modes(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, const CyclicDofs& cyclic,
                                        int nodal_diameter, int families, const ModalOptions& options);

// The families every one of `diameters` has (at least the number asked; a straddling pair adds one
// to some): the width of a nodal-diameter map.
Eigen::Index common_families(const std::vector<NodalDiameterModes>& diameters);

// Eigenvalues of nodal diameter k below (2 pi f)^2, each pair once; -1 when the count failed.
int nodal_diameter_count(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                         const CyclicDofs& cyclic, int nodal_diameter, double frequency_hz);

}  // namespace bb
