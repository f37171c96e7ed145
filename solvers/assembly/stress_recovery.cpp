#include "assembly/stress_recovery.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "assembly/element_traits.hpp"
#include "common/errors.hpp"
#include "mesh/element_coords.hpp"

namespace bb {
namespace {

template <int N, int D>
Eigen::Matrix<double, N * D, 1> element_displacements(const Eigen::MatrixXd& u, const int* nodes) {
  Eigen::Matrix<double, N * D, 1> ue;
  for (int a = 0; a < N; ++a) ue.template segment<D>(D * a) = u.row(nodes[a]).template head<D>().transpose();
  return ue;
}

// Every element's nodal (extrapolated) stresses, kept for the scatter pass: per block, one row per
// element node, in element order.
struct BlockNodal {
  Eigen::MatrixXd values;  // (elements * nodes) x components
};

// The element's Gauss-point stresses (components x points) on every element of the block,
// extrapolated to its nodes; the points' coordinates too where `points` asks.
template <class E>
BlockNodal recover_block(const Mesh& mesh, const ElementBlock& block, const Eigen::MatrixXd& u,
                         const ElementMaterials& materials, IntegrationPointStresses* points, Eigen::MatrixXd& sum,
                         Eigen::VectorXi& count) {
  constexpr int N = E::nodes, D = E::dim, P = E::points, C = D == 2 ? 3 : 6;
  BlockNodal out;
  out.values.resize(block.conn.rows() * N, C);
  for (Eigen::Index e = 0; e < block.conn.rows(); ++e) {
    const int* nodes = block.conn.row(e).data();
    const auto xyz = element_coords<N, D>(mesh, nodes);
    Eigen::Matrix<double, C, P> s;
    try {
      s = E::point_stresses(xyz, element_displacements<N, D>(u, nodes), materials);
    } catch (const std::domain_error& err) {
      throw InputError(
          fmt::format("element {} ({}): {}", block.ids[static_cast<size_t>(e)], element_name(block.type), err.what()));
    }
    const Eigen::Matrix<double, N, C> nodal = E::extrapolation() * s.transpose();
    out.values.middleRows(e * N, N) = nodal;
    for (int a = 0; a < N; ++a) {
      sum.row(nodes[a]) += nodal.row(a);
      ++count[nodes[a]];
    }
    if (points) {
      const Eigen::Matrix<double, D, P> x = E::integration_points(xyz);
      const Eigen::Index first = static_cast<Eigen::Index>(points->element.size());  // rows allocated up front
      for (int p = 0; p < P; ++p) {
        points->element.push_back(block.ids[static_cast<size_t>(e)]);
        points->point.push_back(p + 1);
        points->coords.row(first + p) = x.col(p).transpose();
        points->stress.row(first + p) = s.col(p).transpose();
      }
    }
  }
  return out;
}

int integration_point_count(ElementType type) {
  return with_element(type, []<class E>(E) { return E::points; });
}

}  // namespace

double von_mises(const Eigen::Ref<const Eigen::RowVectorXd>& stress) {
  if (stress.size() == 3) return fe::von_mises_plane(stress.transpose());
  if (stress.size() == 6) return fe::von_mises_solid(stress.transpose());
  throw std::invalid_argument("von_mises: a stress has 3 (plane) or 6 (solid) components");
}

StressField recover_stresses(const Mesh& mesh, const fe::PlaneSection& section, const Eigen::MatrixXd& displacements,
                             const StressRecoveryOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (displacements.rows() != mesh.n_nodes() || displacements.cols() != mesh.dim)
    throw std::invalid_argument("recover_stresses: displacements must be n_nodes x dim");
  StressField field;
  field.components = mesh.dim == 2 ? 3 : 6;
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(mesh.n_nodes(), field.components);
  field.elements = Eigen::VectorXi::Zero(mesh.n_nodes());
  if (options.integration_points) {
    Eigen::Index n_points = 0;
    for (const ElementBlock& b : mesh.blocks)
      n_points += b.conn.rows() * static_cast<Eigen::Index>(integration_point_count(b.type));
    field.points.emplace();
    field.points->coords.resize(n_points, mesh.dim);
    field.points->stress.resize(n_points, field.components);
    field.points->element.reserve(static_cast<size_t>(n_points));
    field.points->point.reserve(static_cast<size_t>(n_points));
  }
  IntegrationPointStresses* points = field.points ? &*field.points : nullptr;
  const fe::SolidMaterial solid{section.youngs_modulus, section.poisson_ratio, section.density};
  const ElementMaterials materials{section, solid};
  const Eigen::MatrixXd& u = displacements;
  std::vector<BlockNodal> per_block;
  for (const ElementBlock& b : mesh.blocks) {
    if (element_dimension(b.type) != mesh.dim)
      throw InputError(fmt::format("{} elements in a {}D mesh", element_name(b.type), mesh.dim));
    with_element(b.type, [&]<class E>(E) {
      per_block.push_back(recover_block<E>(mesh, b, u, materials, points, sum, field.elements));
    });
  }
  field.nodal = sum;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (field.elements[n] > 0) field.nodal.row(n) /= static_cast<double>(field.elements[n]);
  field.scatter = Eigen::VectorXd::Zero(mesh.n_nodes());
  for (size_t bi = 0; bi < mesh.blocks.size(); ++bi) {
    const ElementBlock& b = mesh.blocks[bi];
    const Eigen::Index n_per = b.conn.cols();
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (Eigen::Index a = 0; a < n_per; ++a) {
        const int node = b.conn(e, a);
        const double jump = von_mises(per_block[bi].values.row(e * n_per + a) - field.nodal.row(node));
        field.scatter[node] = std::max(field.scatter[node], jump);
      }
  }
  field.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return field;
}

}  // namespace bb
