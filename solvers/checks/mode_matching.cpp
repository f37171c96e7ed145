#include "checks/mode_matching.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include "common/errors.hpp"

namespace bb {
namespace {

// Pairs (node of `mesh`, node of `reference`) at the same place within `tol` [m], found through a
// grid of cells of size 2 tol (each point is looked for in its cell's 3^dim neighbourhood).
std::vector<std::pair<int, int>> common_nodes(const Mesh& mesh, const Mesh& reference, double tol) {
  const double cell = 2 * tol;
  auto key = [&](const Eigen::RowVectorXd& x) {
    std::array<long, 3> k{0, 0, 0};
    for (Eigen::Index d = 0; d < x.size(); ++d) k[static_cast<size_t>(d)] = std::lround(std::floor(x[d] / cell));
    return k;
  };
  std::map<std::array<long, 3>, std::vector<int>> grid;
  for (int n = 0; n < mesh.n_nodes(); ++n) grid[key(mesh.coords.row(n))].push_back(n);
  std::vector<std::pair<int, int>> pairs;
  const int dz = mesh.dim == 3 ? 1 : 0;
  for (int r = 0; r < reference.n_nodes(); ++r) {
    const Eigen::RowVectorXd x = reference.coords.row(r);
    const std::array<long, 3> k = key(x);
    int found = -1;
    for (long i = -1; i <= 1 && found < 0; ++i)
      for (long j = -1; j <= 1 && found < 0; ++j)
        for (long l = -dz; l <= dz && found < 0; ++l) {
          const auto it = grid.find({k[0] + i, k[1] + j, k[2] + l});
          if (it == grid.end()) continue;
          for (int n : it->second)
            if ((mesh.coords.row(n) - x).norm() <= tol) {
              found = n;
              break;
            }
        }
    if (found >= 0) pairs.emplace_back(found, r);
  }
  return pairs;
}

// Consecutive modes of one repeated eigenvalue: [first, last] index ranges. The rigid-body modes
// (below 1e-4 of the highest frequency, the modal solver's threshold on eigenvalues) are one.
std::vector<std::pair<int, int>> clusters(const Eigen::VectorXd& f) {
  std::vector<std::pair<int, int>> out;
  const double rigid = 1e-4 * (f.size() > 0 ? f.maxCoeff() : 0.0);
  for (int i = 0; i < static_cast<int>(f.size()); ++i) {
    const bool joins = !out.empty() && ((f[i] <= rigid && f[out.back().second] <= rigid) ||
                                        std::abs(f[i] - f[out.back().second]) <=
                                            kRepeatedFrequency * std::max(f[i], f[out.back().second]));
    if (joins)
      out.back().second = i;
    else
      out.emplace_back(i, i);
  }
  return out;
}

}  // namespace

ModeMatch match_modes_by_shape(const Mesh& mesh, const ModalResult& modes, const Mesh& reference_mesh,
                               const ModalResult& reference_modes) {
  if (mesh.dim != reference_mesh.dim)
    throw InputError(
        fmt::format("mode matching by shape: a {}D mesh against a {}D reference mesh", mesh.dim, reference_mesh.dim));
  const double size = (reference_mesh.coords.colwise().maxCoeff() - reference_mesh.coords.colwise().minCoeff()).norm();
  const auto pairs = common_nodes(mesh, reference_mesh, 1e-6 * size);
  const int n_ref = static_cast<int>(reference_modes.shapes.size());
  if (static_cast<int>(pairs.size()) < std::max(3, n_ref))
    throw InputError(
        fmt::format("mode matching by shape: the two meshes share {} nodes (within 1e-6 of the model size); the MAC "
                    "needs at least {} to tell {} reference modes apart",
                    pairs.size(), std::max(3, n_ref), n_ref));
  const int dim = mesh.dim;
  const Eigen::Index rows = static_cast<Eigen::Index>(pairs.size()) * dim;
  auto sample = [&](const std::vector<Eigen::MatrixXd>& shapes, bool reference) {
    Eigen::MatrixXd v(rows, static_cast<Eigen::Index>(shapes.size()));
    for (size_t k = 0; k < shapes.size(); ++k)
      for (size_t p = 0; p < pairs.size(); ++p)
        v.block(static_cast<Eigen::Index>(p) * dim, static_cast<Eigen::Index>(k), dim, 1) =
            shapes[k].row(reference ? pairs[p].second : pairs[p].first).transpose();
    return v;
  };
  const Eigen::MatrixXd a = sample(modes.shapes, false), b = sample(reference_modes.shapes, true);
  ModeMatch m;
  m.common_nodes = static_cast<int>(pairs.size());
  const Eigen::VectorXd na = a.colwise().squaredNorm().transpose(), nb = b.colwise().squaredNorm().transpose();
  const Eigen::MatrixXd dots = a.transpose() * b;
  m.mac = dots.array().square() / (na * nb.transpose()).array().max(1e-300);
  // Subspace MAC of every reference mode with every computed cluster.
  const auto groups = clusters(modes.frequencies_hz);
  Eigen::MatrixXd sub(static_cast<Eigen::Index>(groups.size()), n_ref);
  for (size_t g = 0; g < groups.size(); ++g) {
    const auto [first, last] = groups[g];
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a.middleCols(first, last - first + 1));
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(rows, last - first + 1);
    for (int j = 0; j < n_ref; ++j)
      sub(static_cast<Eigen::Index>(g), j) = (q.transpose() * b.col(j)).squaredNorm() / std::max(nb[j], 1e-300);
  }
  // Greedy assignment, best pairing first; a cluster takes as many reference modes as it has modes.
  std::vector<std::tuple<double, int, int>> candidates;  // (subspace MAC, cluster, reference mode)
  for (Eigen::Index g = 0; g < sub.rows(); ++g)
    for (int j = 0; j < n_ref; ++j) candidates.emplace_back(sub(g, j), static_cast<int>(g), j);
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& x, const auto& y) { return std::get<0>(x) > std::get<0>(y); });
  std::vector<std::vector<int>> taken(groups.size());
  m.computed_of_reference.assign(static_cast<size_t>(n_ref), -1);
  m.match_mac.assign(static_cast<size_t>(n_ref), 0.0);
  std::vector<int> cluster_of(static_cast<size_t>(n_ref), -1);
  for (const auto& [mac, g, j] : candidates) {
    const auto ug = static_cast<size_t>(g);
    const int capacity = groups[ug].second - groups[ug].first + 1;
    if (cluster_of[static_cast<size_t>(j)] >= 0 || static_cast<int>(taken[ug].size()) >= capacity) continue;
    cluster_of[static_cast<size_t>(j)] = g;
    taken[ug].push_back(j);
    m.match_mac[static_cast<size_t>(j)] = mac;
  }
  // Inside a cluster, reference modes in their order take the cluster's modes in frequency order.
  for (size_t g = 0; g < groups.size(); ++g) {
    std::sort(taken[g].begin(), taken[g].end());
    for (size_t i = 0; i < taken[g].size(); ++i)
      m.computed_of_reference[static_cast<size_t>(taken[g][i])] = groups[g].first + static_cast<int>(i);
  }
  return m;
}

ResultTable mode_match_table(const std::string& name, const ModeMatch& match, const ModalResult& modes,
                             const ModalResult& reference_modes) {
  ResultTable t;
  t.name = name;
  t.columns = {"mode", "reference_frequency_hz", "matched_mode", "frequency_hz", "mac"};
  const Eigen::Index n = match.mac.rows(), m = match.mac.cols();
  for (Eigen::Index k = 0; k < n; ++k) t.columns.push_back(fmt::format("mac_{}", k + 1));
  t.values.resize(m, static_cast<Eigen::Index>(t.columns.size()));
  for (Eigen::Index j = 0; j < m; ++j) {
    const int k = match.computed_of_reference[static_cast<size_t>(j)];
    t.values(j, 0) = static_cast<double>(j + 1);
    t.values(j, 1) = reference_modes.frequencies_hz[j];
    t.values(j, 2) = k >= 0 ? k + 1 : 0;
    t.values(j, 3) = k >= 0 ? modes.frequencies_hz[k] : 0.0;
    t.values(j, 4) = match.match_mac[static_cast<size_t>(j)];
    t.values.row(j).tail(n) = match.mac.col(j).transpose();
  }
  return t;
}

}  // namespace bb
