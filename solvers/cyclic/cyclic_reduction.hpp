// Craig-Bampton reduction of one sector for one inter-sector phase sigma (nodal diameter k:
// sigma = 2 pi k / N). In a travelling wave the right face moves as U_right = e^{i sigma} R U_left,
// so the sector's interior and left face carry the complex amplitude and K, M become Hermitian:
// K_sigma = T^H K T. Masters (points of the sector, not on the right face) are kept physical; the
// fixed-interface modes below a cut frequency are added. Keeping every mode below the cut, for
// every phase, spans the same space as the whole structure's fixed-interface modes below that cut:
// a whole-structure reduction with the same cut is the same model (cases/beyond/
// bladed_disk_vs_whole_forced.toml relies on it).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>
#include <vector>

#include "cyclic/cyclic_boundary.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {

struct SectorReduction {
  double phase = 0.0;                   // sigma [rad]
  Eigen::MatrixXcd stiffness, mass;     // Hermitian; the masters in the given order, then the modes
  Eigen::VectorXd mode_frequencies_hz;  // of the fixed-interface modes kept, ascending
  int masters = 0;
};

// `masters`: free equations of the sector. Keeps every fixed-interface mode below
// `cut_frequency_hz` (their count from the Sturm sequence of the doubled real problem), or
// exactly `modes` when `cut_frequency_hz` <= 0. Throws InputError for a master on the right face
// or a repeated one, SolverError when the eigensolver fails or a mode is lost.
SectorReduction cyclic_craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass, const CyclicDofs& cyclic, double phase,
                                     const std::vector<int>& masters, double cut_frequency_hz, int modes,
                                     const ModalOptions& options);

}  // namespace bb
