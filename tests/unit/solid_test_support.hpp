// Helpers for the 3D solid element tests: element kinds, reference shapes, linear fields, rigid
// motions, and a small structured hex mesh with dense assembly (for patch tests and a cantilever,
// independent of mesh/ and assembly/). Units: SI.
#pragma once
#include <Eigen/Dense>

#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fe/solid.hpp"
#include "mesh/mesh.hpp"

namespace bb::test {

enum class SolidKind { hex8, hex8i, hex20 };

inline std::string solid_kind_name(SolidKind kind) {
  switch (kind) {
    case SolidKind::hex8:
      return "Hex8";
    case SolidKind::hex8i:
      return "Hex8Incompatible";
    case SolidKind::hex20:
      return "Hex20";
  }
  return "?";
}

inline int solid_kind_nodes(SolidKind kind) { return kind == SolidKind::hex20 ? 20 : 8; }

inline fe::SolidMaterial steel_solid() { return {.youngs_modulus = 2.0e11, .poisson_ratio = 0.3, .density = 7800.0}; }

// Natural coordinates of the hex20 nodes in Ansys/CalculiX order (the first 8 are the hex8's),
// written out here from the documented convention rather than taken from the implementation.
inline Eigen::Matrix<double, 20, 3> hex20_natural_nodes() {
  Eigen::Matrix<double, 20, 3> n;
  n << -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,  // 1-4
      -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1,       // 5-8
      0, -1, -1, 1, 0, -1, 0, 1, -1, -1, 0, -1,     // 9-12: edges 1-2, 2-3, 3-4, 4-1
      0, -1, 1, 1, 0, 1, 0, 1, 1, -1, 0, 1,         // 13-16: edges 5-6, 6-7, 7-8, 8-5
      -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0;       // 17-20: edges 1-5, 2-6, 3-7, 4-8
  return n;
}

// The two corners (0-based) joined by each mid-edge node 9-20.
inline constexpr int kHex20EdgeEnds[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// Hex20 with straight edges: mid-edge nodes at the midpoints of the corners' edges.
inline fe::Hex20Coords hex20_from_corners(const fe::Hex8Coords& corners) {
  fe::Hex20Coords xyz;
  xyz.topRows<8>() = corners;
  for (int e = 0; e < 12; ++e)
    xyz.row(8 + e) = 0.5 * (corners.row(kHex20EdgeEnds[e][0]) + corners.row(kHex20EdgeEnds[e][1]));
  return xyz;
}

inline Eigen::MatrixXd solid_stiffness(SolidKind kind, const Eigen::MatrixXd& xyz, const fe::SolidMaterial& m) {
  switch (kind) {
    case SolidKind::hex8:
      return fe::hex8_stiffness(fe::Hex8Coords(xyz), m);
    case SolidKind::hex8i:
      return fe::hex8_incompatible_stiffness(fe::Hex8Coords(xyz), m);
    case SolidKind::hex20:
      return fe::hex20_stiffness(fe::Hex20Coords(xyz), m);
  }
  throw std::logic_error("unknown solid kind");
}

// hex8i carries the hex8 consistent mass (the bubbles are condensed out of the stiffness only).
inline Eigen::MatrixXd solid_mass(SolidKind kind, const Eigen::MatrixXd& xyz, const fe::SolidMaterial& m) {
  if (kind == SolidKind::hex20) return fe::hex20_consistent_mass(fe::Hex20Coords(xyz), m);
  return fe::hex8_consistent_mass(fe::Hex8Coords(xyz), m);
}

inline double solid_volume(SolidKind kind, const Eigen::MatrixXd& xyz) {
  if (kind == SolidKind::hex20) return fe::hex20_volume(fe::Hex20Coords(xyz));
  return fe::hex8_volume(fe::Hex8Coords(xyz));
}

// Linear displacement field u(x) = u0 + grad x. Its small strain is sym(grad); the skew part is
// an infinitesimal rotation and must not contribute to the energy.
struct LinearField3 {
  Eigen::Vector3d u0;
  Eigen::Matrix3d grad;
  Eigen::Vector3d at(const Eigen::Vector3d& x) const { return u0 + grad * x; }
  // Voigt (xx, yy, zz, xy, yz, zx), engineering shear.
  Eigen::Matrix<double, 6, 1> strain() const {
    Eigen::Matrix<double, 6, 1> e;
    e << grad(0, 0), grad(1, 1), grad(2, 2), grad(0, 1) + grad(1, 0), grad(1, 2) + grad(2, 1), grad(2, 0) + grad(0, 2);
    return e;
  }
};

// Nodal values (ux1, uy1, uz1, ux2, ...) of a field at the rows of xyz.
inline Eigen::VectorXd sample_field(const LinearField3& f, const Eigen::MatrixXd& xyz) {
  Eigen::VectorXd u(3 * xyz.rows());
  for (Eigen::Index a = 0; a < xyz.rows(); ++a) u.segment<3>(3 * a) = f.at(xyz.row(a).transpose());
  return u;
}

// The six rigid-body motions at the given nodes: x, y, z translations and the infinitesimal
// rotations about the x, y and z axes through the origin (u = omega x r).
inline Eigen::MatrixXd rigid_body_modes_3d(const Eigen::MatrixXd& xyz) {
  const Eigen::Index n = xyz.rows();
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(3 * n, 6);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Eigen::Vector3d x = xyz.row(a).transpose();
    for (int d = 0; d < 3; ++d) {
      r(3 * a + d, d) = 1.0;
      r.block<3, 1>(3 * a, 3 + d) = Eigen::Vector3d::Unit(d).cross(x);
    }
  }
  return r;
}

// A structured block of nx x ny x nz hexahedra on a lattice of (2nx+1)(2ny+1)(2nz+1) points:
// corners sit at even lattice indices, hex20 mid-edge nodes at points with exactly one odd index.
// corner(i, j, k) places the corners (even indices); a mid-edge node is at the midpoint of its two
// corners plus midedge_offset(i, j, k) (zero gives straight edges).
struct HexGrid {
  int nx = 0, ny = 0, nz = 0;
  Eigen::MatrixXd coords;                  // n_nodes x 3
  std::vector<Eigen::Vector3i> lattice;    // lattice index of each node
  std::vector<std::vector<int>> elements;  // node indices, Ansys/CalculiX order
  int n_dofs() const { return 3 * static_cast<int>(coords.rows()); }
  bool on_boundary(int node) const {
    const Eigen::Vector3i& l = lattice[static_cast<size_t>(node)];
    return l[0] == 0 || l[1] == 0 || l[2] == 0 || l[0] == 2 * nx || l[1] == 2 * ny || l[2] == 2 * nz;
  }
  Eigen::MatrixXd element_coords(size_t e) const {
    const std::vector<int>& conn = elements[e];
    Eigen::MatrixXd xyz(static_cast<Eigen::Index>(conn.size()), 3);
    for (size_t a = 0; a < conn.size(); ++a) xyz.row(static_cast<Eigen::Index>(a)) = coords.row(conn[a]);
    return xyz;
  }
};

using LatticeMap = std::function<Eigen::Vector3d(int, int, int)>;

inline HexGrid make_hex_grid(int nx, int ny, int nz, int nodes_per_element, const LatticeMap& corner,
                             const LatticeMap& midedge_offset = nullptr) {
  HexGrid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  const int lx = 2 * nx + 1, ly = 2 * ny + 1, lz = 2 * nz + 1;
  std::vector<int> index(static_cast<size_t>(lx * ly * lz), -1);
  auto slot = [&](int i, int j, int k) -> int& { return index[static_cast<size_t>((k * ly + j) * lx + i)]; };
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < lz; ++k)
    for (int j = 0; j < ly; ++j)
      for (int i = 0; i < lx; ++i) {
        const int odd = (i % 2) + (j % 2) + (k % 2);
        if (odd > 1 || (odd == 1 && nodes_per_element == 8)) continue;
        Eigen::Vector3d x;
        if (odd == 0) {
          x = corner(i, j, k);
        } else {
          const Eigen::Vector3i s(i % 2, j % 2, k % 2);  // the edge direction
          x = 0.5 * (corner(i - s[0], j - s[1], k - s[2]) + corner(i + s[0], j + s[1], k + s[2]));
          if (midedge_offset) x += midedge_offset(i, j, k);
        }
        slot(i, j, k) = static_cast<int>(pts.size());
        pts.push_back(x);
        g.lattice.emplace_back(i, j, k);
      }
  g.coords.resize(static_cast<Eigen::Index>(pts.size()), 3);
  for (size_t a = 0; a < pts.size(); ++a) g.coords.row(static_cast<Eigen::Index>(a)) = pts[a].transpose();
  const Eigen::Matrix<double, 20, 3> nat = hex20_natural_nodes();
  for (int ek = 0; ek < nz; ++ek)
    for (int ej = 0; ej < ny; ++ej)
      for (int ei = 0; ei < nx; ++ei) {
        std::vector<int> conn;
        for (int a = 0; a < nodes_per_element; ++a)
          conn.push_back(slot(2 * ei + 1 + static_cast<int>(nat(a, 0)), 2 * ej + 1 + static_cast<int>(nat(a, 1)),
                              2 * ek + 1 + static_cast<int>(nat(a, 2))));
        g.elements.push_back(conn);
      }
  return g;
}

// Dense global stiffness: fine for the few hundred DOFs of a test mesh.
inline Eigen::MatrixXd assemble_dense(const HexGrid& g, SolidKind kind, const fe::SolidMaterial& m) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(g.n_dofs(), g.n_dofs());
  for (size_t e = 0; e < g.elements.size(); ++e) {
    const Eigen::MatrixXd ke = solid_stiffness(kind, g.element_coords(e), m);
    const std::vector<int>& conn = g.elements[e];
    for (size_t a = 0; a < conn.size(); ++a)
      for (size_t b = 0; b < conn.size(); ++b)
        k.block<3, 3>(3 * conn[a], 3 * conn[b]) +=
            ke.block<3, 3>(3 * static_cast<Eigen::Index>(a), 3 * static_cast<Eigen::Index>(b));
  }
  return k;
}

// Solves K u = f for the DOFs not in `fixed`, with u = prescribed on the fixed ones. Returns u.
inline Eigen::VectorXd solve_with_prescribed(const Eigen::MatrixXd& k, const Eigen::VectorXd& f,
                                             const std::vector<bool>& fixed, const Eigen::VectorXd& prescribed) {
  std::vector<Eigen::Index> free_dofs, fixed_dofs;
  for (Eigen::Index i = 0; i < k.rows(); ++i) (fixed[static_cast<size_t>(i)] ? fixed_dofs : free_dofs).push_back(i);
  const auto nf = static_cast<Eigen::Index>(free_dofs.size());
  const auto np = static_cast<Eigen::Index>(fixed_dofs.size());
  Eigen::MatrixXd kff(nf, nf), kfp(nf, np);
  Eigen::VectorXd rhs(nf), up(np);
  for (Eigen::Index q = 0; q < np; ++q) up[q] = prescribed[fixed_dofs[static_cast<size_t>(q)]];
  for (Eigen::Index r = 0; r < nf; ++r) {
    const Eigen::Index i = free_dofs[static_cast<size_t>(r)];
    rhs[r] = f[i];
    for (Eigen::Index c = 0; c < nf; ++c) kff(r, c) = k(i, free_dofs[static_cast<size_t>(c)]);
    for (Eigen::Index q = 0; q < np; ++q) kfp(r, q) = k(i, fixed_dofs[static_cast<size_t>(q)]);
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(kff);
  if (llt.info() != Eigen::Success) throw std::runtime_error("free-free stiffness not positive definite");
  const Eigen::VectorXd uf = llt.solve(rhs - kfp * up);
  Eigen::VectorXd u = prescribed;
  for (Eigen::Index r = 0; r < nf; ++r) u[free_dofs[static_cast<size_t>(r)]] = uf[r];
  return u;
}

// The grid as a bb::Mesh of one block (node ids 1..n, element ids 1..m), for tests of the mesh-level
// code (assembly, loads, stress recovery).
inline Mesh mesh_from_grid(const HexGrid& grid, ElementType type) {
  Mesh mesh;
  mesh.dim = 3;
  mesh.coords = grid.coords;
  for (Eigen::Index a = 0; a < grid.coords.rows(); ++a) mesh.node_ids.push_back(a + 1);
  mesh.rebuild_index();
  ElementBlock block;
  block.type = type;
  const int nodes = nodes_per_element(type);
  block.conn.resize(static_cast<Eigen::Index>(grid.elements.size()), nodes);
  for (size_t e = 0; e < grid.elements.size(); ++e) {
    for (int a = 0; a < nodes; ++a)
      block.conn(static_cast<Eigen::Index>(e), a) = grid.elements[e][static_cast<size_t>(a)];
    block.ids.push_back(static_cast<long>(e) + 1);
  }
  mesh.blocks.push_back(std::move(block));
  return mesh;
}

}  // namespace bb::test
