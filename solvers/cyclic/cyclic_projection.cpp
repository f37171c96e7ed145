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

namespace {

// T^H diag(A, .., A) T (`blocks` copies of A) entry by entry: each free equation is one reduced
// coordinate, or a few on the right face, so there is about one term per entry of A and block,
// where two sparse products would sort the result twice.
template <class Scalar>
Eigen::SparseMatrix<Scalar> congruence(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<Scalar>& T,
                                       int blocks) {
  const Eigen::SparseMatrix<Scalar, Eigen::RowMajor> follows = T;
  using Row = typename Eigen::SparseMatrix<Scalar, Eigen::RowMajor>::InnerIterator;
  const Eigen::Index n = a.rows();
  std::vector<Eigen::Triplet<Scalar>> t;
  t.reserve(static_cast<size_t>(blocks * a.nonZeros()));
  for (Eigen::Index k = 0; k < a.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it)
      for (int b = 0; b < blocks; ++b)
        for (Row r(follows, b * n + it.row()); r; ++r)
          for (Row c(follows, b * n + it.col()); c; ++c)
            t.emplace_back(static_cast<int>(r.col()), static_cast<int>(c.col()),
                           Eigen::numext::conj(r.value()) * it.value() * c.value());
  Eigen::SparseMatrix<Scalar> out(T.cols(), T.cols());
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace

Eigen::SparseMatrix<double> project(const Eigen::SparseMatrix<double>& a, const CyclicProjection& p) {
  return congruence(a, p.T, p.split ? 2 : 1);
}

Eigen::SparseMatrix<std::complex<double>> project(const Eigen::SparseMatrix<double>& a,
                                                  const Eigen::SparseMatrix<std::complex<double>>& T) {
  return congruence(a, T, 1);
}

Eigen::SparseMatrix<std::complex<double>> complex_cyclic_projection(int n_free, const CyclicDofs& cyclic,
                                                                    double phase) {
  const std::vector<int> reduced = reduced_indices(n_free, cyclic);
  int m = 0;
  for (int r : reduced) m += r >= 0 ? 1 : 0;
  const std::complex<double> shift = std::polar(1.0, phase);
  std::vector<Eigen::Triplet<std::complex<double>>> t;
  for (int i = 0; i < n_free; ++i)
    if (const int j = reduced[static_cast<size_t>(i)]; j >= 0) t.emplace_back(i, j, 1.0);
  for_each_face_coupling(
      cyclic, [&](int r, int l, double rot) { t.emplace_back(r, reduced[static_cast<size_t>(l)], shift * rot); });
  Eigen::SparseMatrix<std::complex<double>> T(n_free, m);
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

}  // namespace bb
