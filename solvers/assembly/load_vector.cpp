#include "assembly/load_vector.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "assembly/element_traits.hpp"
#include "common/errors.hpp"
#include "fe/surface_load.hpp"
#include "mesh/boundary.hpp"
#include "mesh/element_topology.hpp"

namespace bb {

namespace {

// Weights summing to 1: half the length of each element edge whose both nodes lie in the set.
std::vector<double> consistent_edge_weights(const Mesh& mesh, const std::vector<int>& set_nodes,
                                            const std::string& set_name) {
  std::vector<char> in_set(mesh.n_nodes(), 0);
  for (int n : set_nodes) in_set[n] = 1;
  std::set<std::pair<int, int>> edges;
  for (const auto& b : mesh.blocks)
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (const auto& [i, j] : topology(b.type).edges) {
        const int p = b.conn(e, i), q = b.conn(e, j);
        if (in_set[p] && in_set[q]) edges.insert({std::min(p, q), std::max(p, q)});
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

// The acceleration of a body load at a point (3D coordinates; a plane mesh has z = 0) [m/s^2].
Eigen::Vector3d body_acceleration(const BodyLoad& load, const Eigen::Vector3d& x) {
  if (load.kind == BodyLoad::Kind::gravity) return load.acceleration;
  const Eigen::Vector3d r = x - load.origin;
  return load.speed * load.speed * (r - load.axis * load.axis.dot(r));
}

// f_e = M_e b over one block, b the nodal accelerations: N_a reproduces b exactly when b is linear in x.
template <int N, int D, typename MassFn>
void add_body_block(const Mesh& mesh, const ElementBlock& block, const BodyLoad& load, MassFn mass,
                    Eigen::VectorXd& f) {
  for (Eigen::Index e = 0; e < block.conn.rows(); ++e) {
    const int* nodes = block.conn.row(e).data();
    Eigen::Matrix<double, N, D> xyz;
    Eigen::Matrix<double, N * D, 1> b;
    for (int a = 0; a < N; ++a) {
      xyz.row(a) = mesh.coords.row(nodes[a]).template head<D>();
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      x.head<D>() = xyz.row(a).transpose();
      b.template segment<D>(D * a) = body_acceleration(load, x).head<D>();
    }
    Eigen::Matrix<double, N * D, 1> fe_body;
    try {
      fe_body = mass(xyz) * b;
    } catch (const std::domain_error& err) {
      throw InputError(
          fmt::format("element {} ({}): {}", block.ids[static_cast<size_t>(e)], element_name(block.type), err.what()));
    }
    for (int a = 0; a < N; ++a)
      f.segment<D>(static_cast<Eigen::Index>(nodes[a]) * D) += fe_body.template segment<D>(D * a);
  }
}

}  // namespace

Eigen::VectorXd surface_load_vector(const Mesh& mesh, double thickness, const SurfaceLoad& load,
                                    const std::vector<int>& set_nodes) {
  const std::vector<Facet> facets = boundary_facets_within(mesh, set_nodes);
  if (facets.empty())
    throw InputError(fmt::format("node set '{}' holds no boundary {} of the mesh for a distributed load", load.set,
                                 mesh.dim == 2 ? "edge" : "face"));
  const double pressure = load.kind == SurfaceLoad::Kind::pressure ? load.pressure : 0.0;
  const Eigen::Vector3d traction = load.kind == SurfaceLoad::Kind::traction ? load.traction : Eigen::Vector3d::Zero();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.n_nodes()) * mesh.dim);
  const int dim = mesh.dim;
  auto scatter = [&](const std::vector<int>& nodes, const auto& fe_load) {
    for (size_t a = 0; a < nodes.size(); ++a)
      f.segment(static_cast<Eigen::Index>(nodes[a]) * dim, dim) +=
          fe_load.segment(static_cast<Eigen::Index>(a) * dim, dim);
  };
  for (const Facet& facet : facets) {
    if (dim == 2) {
      Eigen::Matrix<double, 2, 2> xy;
      for (int a = 0; a < 2; ++a) xy.row(a) = mesh.coords.row(facet.nodes[static_cast<size_t>(a)]).head<2>();
      scatter(facet.nodes, fe::edge2_load(xy, thickness, pressure, traction.head<2>()));
    } else if (facet.nodes.size() == 4) {
      Eigen::Matrix<double, 4, 3> xyz;
      for (int a = 0; a < 4; ++a) xyz.row(a) = mesh.coords.row(facet.nodes[static_cast<size_t>(a)]);
      scatter(facet.nodes, fe::quad4_face_load(xyz, pressure, traction));
    } else {
      Eigen::Matrix<double, 8, 3> xyz;
      for (int a = 0; a < 8; ++a) xyz.row(a) = mesh.coords.row(facet.nodes[static_cast<size_t>(a)]);
      scatter(facet.nodes, fe::quad8_face_load(xyz, pressure, traction));
    }
  }
  return f;
}

Eigen::VectorXd body_load_vector(const Mesh& mesh, const fe::PlaneSection& section, const BodyLoad& load) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.n_nodes()) * mesh.dim);
  const fe::SolidMaterial solid{section.youngs_modulus, section.poisson_ratio, section.density};
  const ElementMaterials materials{section, solid};
  for (const ElementBlock& b : mesh.blocks)
    with_element(b.type, [&]<class E>(E) {
      add_body_block<E::nodes, E::dim>(
          mesh, b, load, [&](const auto& x) { return E::mass(x, materials); }, f);
    });
  return f;
}

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
  for (const SurfaceLoad& load : model.surface_loads) {
    auto set = model.node_sets.find(load.set);
    if (set == model.node_sets.end()) throw InputError(fmt::format("load on unknown node set '{}'", load.set));
    f += surface_load_vector(mesh, model.section.thickness, load, set->second);
  }
  for (const BodyLoad& load : model.body_loads) f += body_load_vector(mesh, model.section, load);
  return f;
}

}  // namespace bb
