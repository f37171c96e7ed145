// Small helpers shared by the unit tests: hand-built meshes, single-node sets, linear fields.
// Units: SI.
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <initializer_list>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "fe/plane_stress.hpp"
#include "mesh/mesh.hpp"
#include "model/model.hpp"

namespace bb {
// gtest prints a parameter in the test's name; "q4" reads better than its enumerator's value.
inline void PrintTo(ElementType type, std::ostream* os) { *os << element_name(type); }
}  // namespace bb

namespace bb::test {

// A steel-like section; any positive values would do, these keep magnitudes realistic.
inline fe::PlaneSection steel_section(double thickness = 0.1) {
  return {.youngs_modulus = 2.0e11, .poisson_ratio = 0.3, .density = 7800.0, .thickness = thickness};
}

struct Block {
  ElementType type;
  std::vector<std::vector<long>> elements;  // user node ids, counterclockwise
};

// Mesh from user node ids and coordinates, and blocks whose connectivity names user ids.
inline Mesh make_mesh(const std::vector<std::pair<long, Eigen::Vector2d>>& nodes, const std::vector<Block>& blocks) {
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords.resize(static_cast<Eigen::Index>(nodes.size()), 2);
  for (size_t i = 0; i < nodes.size(); ++i) {
    mesh.node_ids.push_back(nodes[i].first);
    mesh.coords.row(static_cast<Eigen::Index>(i)) = nodes[i].second.transpose();
  }
  mesh.rebuild_index();
  long next_element = 1;
  for (const Block& b : blocks) {
    ElementBlock block;
    block.type = b.type;
    block.conn.resize(static_cast<Eigen::Index>(b.elements.size()), nodes_per_element(b.type));
    for (size_t e = 0; e < b.elements.size(); ++e) {
      for (int a = 0; a < nodes_per_element(b.type); ++a)
        block.conn(static_cast<Eigen::Index>(e), a) = mesh.index_of(b.elements[e][static_cast<size_t>(a)]);
      block.ids.push_back(next_element++);
    }
    mesh.blocks.push_back(std::move(block));
  }
  return mesh;
}

// Internal indices of the given user node ids, sorted (the Model's convention).
inline std::vector<int> node_set(const Mesh& mesh, std::initializer_list<long> ids) {
  std::vector<int> out;
  for (long id : ids) out.push_back(mesh.index_of(id));
  std::sort(out.begin(), out.end());
  return out;
}

// A linear displacement field u = a0 + a1 x + a2 y, v = b0 + b1 x + b2 y.
struct LinearField {
  double a0, a1, a2, b0, b1, b2;
  Eigen::Vector2d at(double x, double y) const { return {a0 + a1 * x + a2 * y, b0 + b1 * x + b2 * y}; }
  // Engineering strains (exx, eyy, gxy).
  Eigen::Vector3d strain() const { return {a1, b2, a2 + b1}; }
};

// Element nodal displacements (ux1, uy1, ux2, ...) of a field sampled at the element's nodes.
template <int N>
Eigen::Matrix<double, 2 * N, 1> sample(const LinearField& f, const Eigen::Matrix<double, N, 2>& xy) {
  Eigen::Matrix<double, 2 * N, 1> u;
  for (int a = 0; a < N; ++a) u.template segment<2>(2 * a) = f.at(xy(a, 0), xy(a, 1));
  return u;
}

// The three rigid-body motions of a plane body sampled at the given nodes: x, y translation and
// the infinitesimal rotation about the origin (u, v) = (-y, x). One column each.
inline Eigen::MatrixXd rigid_body_modes(const Eigen::MatrixXd& xy) {
  const Eigen::Index n = xy.rows();
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(2 * n, 3);
  for (Eigen::Index a = 0; a < n; ++a) {
    r(2 * a, 0) = 1.0;
    r(2 * a + 1, 1) = 1.0;
    r(2 * a, 2) = -xy(a, 1);
    r(2 * a + 1, 2) = xy(a, 0);
  }
  return r;
}

// Signed area of a polygon given counterclockwise (shoelace).
inline double polygon_area(const Eigen::MatrixXd& xy) {
  double twice = 0.0;
  for (Eigen::Index i = 0; i < xy.rows(); ++i) {
    const Eigen::Index j = (i + 1) % xy.rows();
    twice += xy(i, 0) * xy(j, 1) - xy(j, 0) * xy(i, 1);
  }
  return 0.5 * twice;
}

}  // namespace bb::test
