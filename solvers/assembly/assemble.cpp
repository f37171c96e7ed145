#include "assembly/assemble.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "common/errors.hpp"

namespace bb {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

template <int N>
void scatter(const Eigen::Matrix<double, 2 * N, 2 * N>& ke, const int* nodes, Triplets& out) {
  for (int a = 0; a < N; ++a)
    for (int da = 0; da < 2; ++da)
      for (int c = 0; c < N; ++c)
        for (int dc = 0; dc < 2; ++dc) {
          const double v = ke(2 * a + da, 2 * c + dc);
          if (v != 0.0) out.emplace_back(2 * nodes[a] + da, 2 * nodes[c] + dc, v);
        }
}

template <int N>
Eigen::Matrix<double, N, 2> element_coords(const Mesh& mesh, const int* nodes) {
  Eigen::Matrix<double, N, 2> xy;
  for (int a = 0; a < N; ++a) xy.row(a) = mesh.coords.row(nodes[a]).head<2>();
  return xy;
}

template <int N, typename StiffFn, typename MassFn>
void assemble_block(const Mesh& mesh, const ElementBlock& block, const fe::PlaneSection& section,
                    const AssemblyOptions& options, StiffFn stiff, MassFn mass, Triplets& k,
                    Triplets& m) {
  for (Eigen::Index e = 0; e < block.conn.rows(); ++e) {
    const int* nodes = block.conn.row(e).data();
    const auto xy = element_coords<N>(mesh, nodes);
    try {
      if (options.stiffness) scatter<N>(stiff(xy, section), nodes, k);
      if (options.mass) scatter<N>(mass(xy, section), nodes, m);
    } catch (const std::domain_error& err) {
      throw InputError(fmt::format("element {} ({}): {}", block.ids[e], element_name(block.type), err.what()));
    }
  }
}

}  // namespace

GlobalMatrices assemble(const Mesh& mesh, const fe::PlaneSection& section, const AssemblyOptions& options) {
  if (mesh.dim != 2) throw InputError("plane-stress assembly needs a 2D mesh");
  Triplets k, m;
  size_t entries = 0;
  for (const auto& b : mesh.blocks) entries += b.ids.size() * static_cast<size_t>(4 * nodes_per_element(b.type) * nodes_per_element(b.type));
  if (options.stiffness) k.reserve(entries);
  if (options.mass) m.reserve(entries / 2);  // mass has no x-y coupling
  for (const auto& b : mesh.blocks) {
    switch (b.type) {
      case ElementType::q4:
        assemble_block<4>(mesh, b, section, options, fe::q4_stiffness, fe::q4_consistent_mass, k, m);
        break;
      case ElementType::cst:
        assemble_block<3>(mesh, b, section, options, fe::cst_stiffness, fe::cst_consistent_mass, k, m);
        break;
    }
  }
  const int n = mesh.n_nodes() * mesh.dim;
  GlobalMatrices g;
  if (options.stiffness) {
    g.stiffness.resize(n, n);
    g.stiffness.setFromTriplets(k.begin(), k.end());
  }
  if (options.mass) {
    g.mass.resize(n, n);
    g.mass.setFromTriplets(m.begin(), m.end());
  }
  return g;
}

Partitioned partition(const SparseMatrix& a, const DofMap& dofs) {
  std::vector<int> constrained_index(dofs.n_global(), -1);
  for (size_t i = 0; i < dofs.constrained_dofs.size(); ++i) constrained_index[dofs.constrained_dofs[i]] = static_cast<int>(i);
  Triplets ff, fc;
  ff.reserve(static_cast<size_t>(a.nonZeros()));
  for (int col = 0; col < a.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(a, col); it; ++it) {
      const int row_eq = dofs.equation[it.row()];
      if (row_eq < 0) continue;
      const int col_eq = dofs.equation[col];
      if (col_eq >= 0) {
        ff.emplace_back(row_eq, col_eq, it.value());
      } else {
        fc.emplace_back(row_eq, constrained_index[col], it.value());
      }
    }
  }
  Partitioned p;
  p.ff.resize(dofs.n_free, dofs.n_free);
  p.ff.setFromTriplets(ff.begin(), ff.end());
  p.fc.resize(dofs.n_free, static_cast<Eigen::Index>(dofs.constrained_dofs.size()));
  p.fc.setFromTriplets(fc.begin(), fc.end());
  return p;
}

namespace {

// Weights summing to 1: half the length of each element edge whose both nodes lie in the set.
std::vector<double> consistent_edge_weights(const Mesh& mesh, const std::vector<int>& set_nodes,
                                            const std::string& set_name) {
  std::vector<char> in_set(mesh.n_nodes(), 0);
  for (int n : set_nodes) in_set[n] = 1;
  std::set<std::pair<int, int>> edges;
  for (const auto& b : mesh.blocks) {
    const int nn = nodes_per_element(b.type);
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e) {
      for (int a = 0; a < nn; ++a) {
        const int p = b.conn(e, a), q = b.conn(e, (a + 1) % nn);
        if (in_set[p] && in_set[q]) edges.insert({std::min(p, q), std::max(p, q)});
      }
    }
  }
  if (edges.empty())
    throw InputError(fmt::format("load split 'consistent' needs element edges in node set '{}', found none", set_name));
  std::vector<double> w(mesh.n_nodes(), 0.0);
  double total = 0.0;
  for (auto [p, q] : edges) {
    const double len = (mesh.coords.row(p) - mesh.coords.row(q)).norm();
    w[p] += 0.5 * len;
    w[q] += 0.5 * len;
    total += len;
  }
  for (double& v : w) v /= total;
  return w;
}

}  // namespace

Eigen::VectorXd load_vector(const Model& model) {
  const Mesh& mesh = model.mesh;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.n_nodes() * mesh.dim);
  for (const NodalLoad& load : model.loads) {
    auto set = model.node_sets.find(load.set);
    if (set == model.node_sets.end()) throw InputError(fmt::format("load on unknown node set '{}'", load.set));
    const auto& nodes = set->second;
    if (load.split == LoadSplit::equal) {
      for (int n : nodes) f[n * mesh.dim + load.direction] += load.total / static_cast<double>(nodes.size());
    } else {
      const std::vector<double> w = consistent_edge_weights(mesh, nodes, load.set);
      for (int n : nodes) f[n * mesh.dim + load.direction] += load.total * w[n];
    }
  }
  return f;
}

}  // namespace bb
