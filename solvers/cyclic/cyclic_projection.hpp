// The sector's motions of one nodal diameter k as real coordinates. In a travelling wave
// u_j = Re(U e^{i k j 2 pi / N}) the right face moves as U_right = e^{i k 2 pi / N} R U_left, so
// the sector's interior and left face carry the motion. For 0 < k < N/2 the complex amplitude is
// written as its cosine and sine parts (a real problem of twice the size, each eigenvalue twice:
// the standing cosine and sine waves); for k = 0 and k = N/2 the phase factor is +-1 and the
// problem is real of the sector's size.
#pragma once
#include <Eigen/Sparse>

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

// Throws InputError for k outside 0..N/2.
CyclicProjection cyclic_projection(int n_free, const CyclicDofs& cyclic, int nodal_diameter);

// T^T A T, with A repeated on the cosine and sine parts when split: for K and M of the sector the
// stiffness and mass of nodal diameter k.
Eigen::SparseMatrix<double> project(const Eigen::SparseMatrix<double>& a, const CyclicProjection& p);

}  // namespace bb
