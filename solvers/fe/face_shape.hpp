// Shape functions of an element face in its natural coordinates (xi, eta) in [-1, 1]^2: the bilinear
// 4-node quadrilateral (hex8, hex8i) and the 8-node serendipity one (hex20), nodes as in
// mesh/element_topology.hpp (corners counterclockwise seen from outside, then mid-edge nodes).
#pragma once
#include <Eigen/Dense>

namespace bb::fe {

// Natural coordinates of a face's nodes: corners counterclockwise, then mid-edge nodes.
inline constexpr double kFaceNodes[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};

template <int N>
inline void face_shape(double xi, double eta, Eigen::Matrix<double, N, 1>& n, Eigen::Matrix<double, 2, N>& dn) {
  for (int a = 0; a < N; ++a) {
    const double xa = kFaceNodes[a][0], ya = kFaceNodes[a][1];
    if (N == 4) {
      n[a] = 0.25 * (1 + xa * xi) * (1 + ya * eta);
      dn(0, a) = 0.25 * xa * (1 + ya * eta);
      dn(1, a) = 0.25 * (1 + xa * xi) * ya;
    } else if (a < 4) {  // serendipity corner: (1/4)(1 + xi xa)(1 + eta ya)(xi xa + eta ya - 1)
      n[a] = 0.25 * (1 + xa * xi) * (1 + ya * eta) * (xa * xi + ya * eta - 1);
      dn(0, a) = 0.25 * xa * (1 + ya * eta) * (2 * xa * xi + ya * eta);
      dn(1, a) = 0.25 * ya * (1 + xa * xi) * (xa * xi + 2 * ya * eta);
    } else if (xa == 0) {  // mid-edge node on eta = ya: (1/2)(1 - xi^2)(1 + eta ya)
      n[a] = 0.5 * (1 - xi * xi) * (1 + ya * eta);
      dn(0, a) = -xi * (1 + ya * eta);
      dn(1, a) = 0.5 * (1 - xi * xi) * ya;
    } else {  // mid-edge node on xi = xa
      n[a] = 0.5 * (1 + xa * xi) * (1 - eta * eta);
      dn(0, a) = 0.5 * xa * (1 - eta * eta);
      dn(1, a) = -(1 + xa * xi) * eta;
    }
  }
}

}  // namespace bb::fe
