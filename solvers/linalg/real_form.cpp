#include "linalg/real_form.hpp"

#include <vector>

namespace bb {

Eigen::SparseMatrix<double> real_form(const Eigen::SparseMatrix<std::complex<double>>& a) {
  const Eigen::Index n = a.rows();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<size_t>(4 * a.nonZeros()));
  for (Eigen::Index k = 0; k < a.outerSize(); ++k)
    for (Eigen::SparseMatrix<std::complex<double>>::InnerIterator it(a, k); it; ++it) {
      const Eigen::Index i = it.row(), j = it.col();
      const double re = it.value().real(), im = it.value().imag();
      t.emplace_back(i, j, re);
      t.emplace_back(n + i, n + j, re);
      if (im != 0.0) {
        t.emplace_back(i, n + j, -im);
        t.emplace_back(n + i, j, im);
      }
    }
  Eigen::SparseMatrix<double> d(2 * n, 2 * n);
  d.setFromTriplets(t.begin(), t.end());
  return d;
}

}  // namespace bb
