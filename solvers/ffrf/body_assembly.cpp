#include "ffrf/body_assembly.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "assembly/element_traits.hpp"
#include "assembly/sparsity.hpp"
#include "common/errors.hpp"
#include "mesh/element_coords.hpp"

namespace bb::ffrf {
namespace {

template <int N, int D>
Eigen::Matrix<double, N * D, 1> element_displacement(const Eigen::VectorXd& u, const int* nodes) {
  Eigen::Matrix<double, N * D, 1> ue;
  for (int a = 0; a < N; ++a) ue.template segment<D>(D * a) = u.segment<D>(static_cast<Eigen::Index>(nodes[a]) * D);
  return ue;
}

// Calls fn(e, nodes) for every element of a block, turning a std::domain_error into an InputError
// that names the element (as assembly/assemble does).
template <typename Fn>
void for_each_element(const ElementBlock& block, Fn fn) {
  for (Eigen::Index e = 0; e < block.conn.rows(); ++e) {
    try {
      fn(block.conn.row(e).data());
    } catch (const std::domain_error& err) {
      throw InputError(
          fmt::format("element {} ({}): {}", block.ids[static_cast<size_t>(e)], element_name(block.type), err.what()));
    }
  }
}

// The scalar consistent mass m_ab of an element, whatever its type.
Eigen::MatrixXd scalar_mass(ElementType type, const Mesh& mesh, const int* nodes, const fe::PlaneSection& section) {
  const fe::SolidMaterial solid{section.youngs_modulus, section.poisson_ratio, section.density};
  const ElementMaterials materials{section, solid};
  const Eigen::MatrixXd expanded = with_element(type, [&]<class E>(E) -> Eigen::MatrixXd {
    return E::mass(element_coords<E::nodes, E::dim>(mesh, nodes), materials);
  });
  const int dim = element_dimension(type), n = nodes_per_element(type);
  Eigen::MatrixXd m(n, n);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) m(a, b) = expanded(dim * a, dim * b);
  return m;
}

Eigen::MatrixXd kron(const Eigen::MatrixXd& m, const Eigen::MatrixXd& block) {
  const auto n = m.rows(), d = block.rows();
  Eigen::MatrixXd out(n * d, n * d);
  for (Eigen::Index b = 0; b < n; ++b)
    for (Eigen::Index a = 0; a < n; ++a) out.block(a * d, b * d, d, d) = m(a, b) * block;
  return out;
}

void add_geometric_stiffness(const Mesh& mesh, const ElementBlock& block, const fe::PlaneSection& section,
                             const Eigen::VectorXd& u, const NodalPattern& pattern, Eigen::SparseMatrix<double>& k) {
  const fe::SolidMaterial solid{section.youngs_modulus, section.poisson_ratio, section.density};
  const ElementMaterials materials{section, solid};
  with_element(block.type, [&]<class E>(E) {
    for_each_element(block, [&](const int* nodes) {
      const auto xyz = element_coords<E::nodes, E::dim>(mesh, nodes);
      const auto s = E::point_stresses(xyz, element_displacement<E::nodes, E::dim>(u, nodes), materials);
      pattern.add(k, nodes, E::nodes, E::geometric_stiffness(xyz, s, materials));
    });
  });
}

}  // namespace

InertiaOperators assemble_inertia(const Mesh& mesh, const fe::PlaneSection& section,
                                  const Eigen::Vector3d& axis_direction) {
  const int dim = mesh.dim;
  Eigen::MatrixXd projector, skew;
  if (dim == 2) {
    projector = Eigen::Matrix2d::Identity();
    skew = axis_direction.z() * (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  } else {
    const Eigen::Vector3d a = axis_direction;
    projector = Eigen::Matrix3d::Identity() - a * a.transpose();
    skew = (Eigen::Matrix3d() << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0).finished();
  }
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(dim, dim);
  const NodalPattern pattern(mesh);
  InertiaOperators ops{pattern.zero_matrix(), pattern.zero_matrix(), pattern.zero_matrix()};
  for (const auto& block : mesh.blocks) {
    if (element_dimension(block.type) != dim)
      throw InputError(fmt::format("{} elements in a {}D mesh", element_name(block.type), dim));
    const int n = nodes_per_element(block.type);
    for_each_element(block, [&](const int* nodes) {
      const Eigen::MatrixXd m = scalar_mass(block.type, mesh, nodes, section);
      pattern.add(ops.mass, nodes, n, kron(m, identity));
      pattern.add(ops.projected_mass, nodes, n, kron(m, projector));
      pattern.add(ops.gyroscopic, nodes, n, kron(m, skew));
    });
  }
  return ops;
}

Eigen::SparseMatrix<double> assemble_geometric_stiffness(const Mesh& mesh, const fe::PlaneSection& section,
                                                         const Eigen::VectorXd& u) {
  if (u.size() != static_cast<Eigen::Index>(mesh.n_nodes()) * mesh.dim)
    throw std::invalid_argument("assemble_geometric_stiffness: displacement size != nodes * dim");
  const NodalPattern pattern(mesh);
  Eigen::SparseMatrix<double> k = pattern.zero_matrix();
  for (const auto& block : mesh.blocks) add_geometric_stiffness(mesh, block, section, u, pattern, k);
  return k;
}

}  // namespace bb::ffrf
