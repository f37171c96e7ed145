// The sector's motions of one nodal diameter k as real coordinates. In a travelling wave
// u_j = Re(U e^{i k j 2 pi / N}) the right face moves as U_right = e^{i k 2 pi / N} R U_left, so
// the sector's interior and left face carry the motion. For k = 0 and k = N/2 the phase factor is
// +-1 and the problem is real of the sector's size. For 0 < k < N/2 the complex amplitude is either
// kept complex (complex_cyclic_projection: a Hermitian problem of the sector's size, what the modal
// solve uses) or written as its cosine and sine parts (CyclicProjection with split: a real problem
// of twice the size, each eigenvalue twice, the standing cosine and sine waves).
#pragma once
#include <Eigen/Sparse>

#include <complex>
#include <vector>

#include "cyclic/cyclic_boundary.hpp"

namespace bb {

struct CyclicProjection {
  int nodal_diameter = 0;
  bool split = false;  // cosine and sine parts (0 < k < N/2)
  int n_free = 0;      // the sector's free DOFs
  // Sector free DOFs (twice over, cosine then sine, when split) from the reduced coordinates.
  Eigen::SparseMatrix<double> T;

  Eigen::Index reduced_size() const { return T.cols(); }
};

// The reduced index of each free equation: -1 on the right face (it follows the left face), the
// others numbered in order.
std::vector<int> reduced_indices(int n_free, const CyclicDofs& cyclic);

// Calls couple(r, l, c) for each right-face equation r and left-face equation l it follows with
// the rotation's coefficient c != 0 (u_r = sum c u_l, times the phase factor).
template <class Couple>
void for_each_face_coupling(const CyclicDofs& cyclic, const Couple& couple) {
  const auto dim = static_cast<size_t>(cyclic.dim);
  for (size_t pair = 0; pair < cyclic.right.size() / dim; ++pair)
    for (size_t a = 0; a < dim; ++a) {
      const int r = cyclic.right[pair * dim + a];
      if (r < 0) continue;
      for (size_t b = 0; b < dim; ++b) {
        const double c = cyclic.rotation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
        const int l = cyclic.left[pair * dim + b];
        if (c != 0.0 && l >= 0) couple(r, l, c);
      }
    }
}

// Throws InputError for k outside 0..N/2.
CyclicProjection cyclic_projection(int n_free, const CyclicDofs& cyclic, int nodal_diameter);

// T^T A T, with A repeated on the cosine and sine parts when split: for K and M of the sector the
// stiffness and mass of nodal diameter k.
Eigen::SparseMatrix<double> project(const Eigen::SparseMatrix<double>& a, const CyclicProjection& p);

// The right face following the left one with the phase factor e^{i phase} (2 pi k / N for nodal
// diameter k): sector free DOFs (rows) from the complex reduced coordinates (the sector without
// its right face).
Eigen::SparseMatrix<std::complex<double>> complex_cyclic_projection(int n_free, const CyclicDofs& cyclic, double phase);

// T^H A T: for K and M of the sector the Hermitian stiffness and mass of that phase.
Eigen::SparseMatrix<std::complex<double>> project(const Eigen::SparseMatrix<double>& a,
                                                  const Eigen::SparseMatrix<std::complex<double>>& T);

}  // namespace bb
