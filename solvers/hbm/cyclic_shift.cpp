#include "hbm/cyclic_shift.hpp"

#include <cmath>

namespace bb::hbm {


Eigen::VectorXd shift_coefficients(const Eigen::VectorXd& c, double phase) {
  Eigen::VectorXd s = c;
  for (Eigen::Index h = 1; 2 * h < c.size(); ++h) {
    const double cs = std::cos(static_cast<double>(h) * phase), sn = std::sin(static_cast<double>(h) * phase),
                 a = c[2 * h - 1], b = c[2 * h];
    s[2 * h - 1] = a * cs + b * sn;
    s[2 * h] = b * cs - a * sn;
  }
  return s;
}

Eigen::MatrixXd cyclic_gap_operator(const Eigen::RowVectorXd& own, const Eigen::RowVectorXd& next, double phase,
                                    int harmonics) {
  const Eigen::Index nc = own.size(), m = 2 * harmonics + 1;
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(m, nc * m);
  for (Eigen::Index i = 0; i < nc; ++i) {
    for (Eigen::Index j = 0; j < m; ++j) g(j, j * nc + i) += own[i];
    const double w = next[i];
    if (w == 0.0) continue;
    g(0, i) += w;
    for (Eigen::Index h = 1; h <= harmonics; ++h) {
      const Eigen::Index a = 2 * h - 1, b = 2 * h;
      const double cs = std::cos(static_cast<double>(h) * phase) * w, sn = std::sin(static_cast<double>(h) * phase) * w;
      g(a, a * nc + i) += cs;
      g(a, b * nc + i) += sn;
      g(b, a * nc + i) -= sn;
      g(b, b * nc + i) += cs;
    }
  }
  return g;
}

}  // namespace bb::hbm
