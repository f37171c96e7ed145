#include "cyclic/cyclic_projection.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/errors.hpp"

namespace bb {

std::vector<int> reduced_indices(int n_free, const CyclicDofs& cyclic) {
  std::vector<int> reduced(static_cast<size_t>(n_free), 0);
  for (int r : cyclic.right)
    if (r >= 0) reduced[static_cast<size_t>(r)] = -1;
  int m = 0;
  for (int& r : reduced) r = r < 0 ? -1 : m++;
  return reduced;
}

CyclicProjection cyclic_projection(int n_free, const CyclicDofs& cyclic, int nodal_diameter) {
  const int N = cyclic.sectors;
  if (nodal_diameter < 0 || 2 * nodal_diameter > N)
    throw InputError(fmt::format("nodal diameter {} lies outside 0..{} (N = {} sectors)", nodal_diameter, N / 2, N));
  CyclicProjection p;
  p.nodal_diameter = nodal_diameter;
  p.split = nodal_diameter != 0 && 2 * nodal_diameter != N;
  p.n_free = n_free;
  const std::vector<int> reduced = reduced_indices(n_free, cyclic);
  int m = 0;
  for (int r : reduced) m += r >= 0 ? 1 : 0;
  const double phase = 2 * std::numbers::pi * nodal_diameter / N;
  const double c = std::cos(phase), s = p.split ? std::sin(phase) : 0.0;
  const int n = n_free, blocks = p.split ? 2 : 1;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<size_t>(blocks * (n + 2 * cyclic.dim * static_cast<int>(cyclic.right.size()))));
  for (int i = 0; i < n; ++i)
    if (const int j = reduced[static_cast<size_t>(i)]; j >= 0)
      for (int b = 0; b < blocks; ++b) t.emplace_back(b * n + i, b * m + j, 1.0);
  // cosine part: c A_l - s B_l; sine part: s A_l + c B_l (both turned by the rotation).
  for_each_face_coupling(cyclic, [&](int r, int l, double rot) {
    const int j = reduced[static_cast<size_t>(l)];
    t.emplace_back(r, j, c * rot);
    if (p.split) {
      t.emplace_back(r, m + j, -s * rot);
      t.emplace_back(n + r, j, s * rot);
      t.emplace_back(n + r, m + j, c * rot);
    }
  });
  p.T.resize(blocks * n, blocks * m);
  p.T.setFromTriplets(t.begin(), t.end());
  return p;
}

Eigen::SparseMatrix<double> project(const Eigen::SparseMatrix<double>& a, const CyclicProjection& p) {
  if (!p.split) {
    Eigen::SparseMatrix<double> r = p.T.transpose() * a * p.T;
    return r;
  }
  const Eigen::Index n = a.rows();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<size_t>(2 * a.nonZeros()));
  for (Eigen::Index k = 0; k < a.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) {
      t.emplace_back(it.row(), it.col(), it.value());
      t.emplace_back(n + it.row(), n + it.col(), it.value());
    }
  Eigen::SparseMatrix<double> twice(2 * n, 2 * n);
  twice.setFromTriplets(t.begin(), t.end());
  Eigen::SparseMatrix<double> r = p.T.transpose() * twice * p.T;
  return r;
}

}  // namespace bb
