#include "articles/blade_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

#include "mesh/hex_block.hpp"

namespace bb {
namespace {

constexpr double kSame = 1e-9;  // [m] coordinates closer than this are one node

// Nodes by position, created on first use; the four Presams nodes of Fig. 2.19 are made first so
// that they get ids 1-4. Every coordinate comes from the same few line vectors, so a shared node is
// the same pair of doubles wherever it is asked for.
class PlaneNodes {
 public:
  int at(double x, double y) {
    const auto [it, fresh] = index_.try_emplace({x, y}, static_cast<int>(xy_.size()));
    if (fresh) xy_.emplace_back(x, y);
    return it->second;
  }
  const std::vector<Eigen::Vector2d>& positions() const { return xy_; }

 private:
  std::map<std::pair<double, double>, int> index_;
  std::vector<Eigen::Vector2d> xy_;
};

std::vector<double> divide(double a, double b, int n) {
  std::vector<double> v(static_cast<size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) v[static_cast<size_t>(i)] = i == n ? b : a + (b - a) * i / n;
  return v;
}

// Quadrilaterals (counterclockwise) and triangles of the plane pattern, as node indices.
struct PlanePattern {
  PlaneNodes nodes;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> corners;  // the platform's two damper-face triangles
};

void add_grid(PlanePattern& p, const std::vector<double>& xs, const std::vector<double>& ys) {
  for (size_t j = 0; j + 1 < ys.size(); ++j)
    for (size_t i = 0; i + 1 < xs.size(); ++i)
      p.quads.push_back({p.nodes.at(xs[i], ys[j]), p.nodes.at(xs[i + 1], ys[j]), p.nodes.at(xs[i + 1], ys[j + 1]),
                         p.nodes.at(xs[i], ys[j + 1])});
}

PlanePattern plane_pattern(const TwoBladeDimensions& d, const BladeSectionDivisions& n, bool corners) {
  const auto y = d.levels();
  const double x0 = d.x_n0(), x1 = d.x_n1, xc = d.x_c(), half = 0.5 * d.w;
  const double p0 = xc - 0.5 * d.B_p, p1 = xc + 0.5 * d.B_p;  // platform edges
  PlanePattern p;
  for (const auto& [x, yy] : {std::pair{0.0, y[2]}, {d.B_r, y[2]}, {d.B_r, y[3]}, {x1, y[3]}}) p.nodes.at(x, yy);
  // Column lines: the airfoil's, then the neck's faces, then the root shoulders.
  std::vector<double> airfoil = divide(xc - half, xc + half, n.airfoil_columns);
  std::vector<double> neck = airfoil;
  neck.insert(neck.begin(), x0);
  neck.push_back(x1);
  std::vector<double> root = divide(0.0, x0, n.root_side_columns);
  root.pop_back();
  root.insert(root.end(), neck.begin(), neck.end());
  const std::vector<double> right = divide(x1, d.B_r, n.root_side_columns);
  root.insert(root.end(), right.begin() + 1, right.end());
  std::vector<double> lip = neck;
  lip.insert(lip.begin(), p0);
  lip.push_back(p1);
  add_grid(p, root, divide(y[2], y[3], n.root_rows));
  add_grid(p, neck, divide(y[3], y[5], n.neck_rows));
  add_grid(p, neck, {y[5], y[6]});  // the platform between its two damper faces: one row, as the faces' triangles
  add_grid(p, lip, divide(y[6], y[7], n.lip_rows));
  add_grid(p, airfoil, divide(y[7], y[8], n.airfoil_rows));
  if (corners) {
    p.corners.push_back({p.nodes.at(x0, y[5]), p.nodes.at(x0, y[6]), p.nodes.at(p0, y[6])});
    p.corners.push_back({p.nodes.at(x1, y[5]), p.nodes.at(p1, y[6]), p.nodes.at(x1, y[6])});
  }
  return p;
}

void add_block(Mesh& mesh, ElementType type, const std::vector<std::vector<int>>& elements) {
  if (elements.empty()) return;
  ElementBlock b;
  b.type = type;
  b.conn.resize(static_cast<Eigen::Index>(elements.size()), static_cast<Eigen::Index>(elements.front().size()));
  for (size_t e = 0; e < elements.size(); ++e) {
    b.ids.push_back(static_cast<long>(mesh.n_elements()) + static_cast<long>(e) + 1);
    for (size_t a = 0; a < elements[e].size(); ++a)
      b.conn(static_cast<Eigen::Index>(e), static_cast<Eigen::Index>(a)) = elements[e][a];
  }
  mesh.blocks.push_back(std::move(b));
}

Mesh plane_mesh(const PlanePattern& p, ElementType element) {
  Mesh mesh;
  mesh.dim = 2;
  const auto& xy = p.nodes.positions();
  mesh.coords.resize(static_cast<Eigen::Index>(xy.size()), 2);
  for (size_t i = 0; i < xy.size(); ++i) {
    mesh.coords.row(static_cast<Eigen::Index>(i)) = xy[i].transpose();
    mesh.node_ids.push_back(static_cast<long>(i) + 1);
  }
  std::vector<std::vector<int>> quads, triangles;
  for (const auto& q : p.quads) {
    if (element == ElementType::q4) {
      quads.push_back({q[0], q[1], q[2], q[3]});
    } else {  // two triangles per rectangle, split along its 1-3 diagonal
      triangles.push_back({q[0], q[1], q[2]});
      triangles.push_back({q[0], q[2], q[3]});
    }
  }
  for (const auto& c : p.corners) triangles.push_back({c[0], c[1], c[2]});
  add_block(mesh, ElementType::q4, quads);
  add_block(mesh, ElementType::cst, triangles);
  mesh.rebuild_index();
  return mesh;
}

// The plane pattern extruded through the thickness in `layers` hex8 layers.
Mesh solid_mesh(const PlanePattern& p, double t, int layers) {
  std::vector<Mesh> parts;
  for (const auto& q : p.quads) {
    HexBlockSpec b;
    for (size_t a = 0; a < 4; ++a) {
      const Eigen::Vector2d c = p.nodes.positions()[static_cast<size_t>(q[a])];
      b.corners[a] = Eigen::Vector3d(c.x(), c.y(), 0.0);
      b.corners[a + 4] = Eigen::Vector3d(c.x(), c.y(), t);
    }
    b.nz = layers;
    b.element = ElementType::hex8;
    parts.push_back(generate_hex_block(b));
  }
  return merge_meshes(parts, kSame);
}

std::vector<int> nodes_where(const Mesh& mesh, const std::function<bool(const Eigen::VectorXd&)>& pick) {
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (pick(mesh.coords.row(n).transpose())) out.push_back(n);
  return out;
}

}  // namespace

std::span<const char* const> blade_section_set_names() {
  static const char* const names[] = {"root", "tip", "mid", "airfoil"};
  return names;
}

BladeSectionDivisions blade_section_divisions(ElementType element) {
  BladeSectionDivisions d;
  switch (element) {
    case ElementType::q4:  // 6x3 + 4x8 + 4 + 6x5 + 2x41 = 166 rectangles, 233 nodes: the counts of L722
      d = {1, 3, 8, 5, 2, 41, 4};
      break;
    case ElementType::cst:  // 2 (5x2 + 3x3 + 3 + 5x2 + 23) + 2 = 112 triangles: the count of L800
      d = {1, 2, 3, 2, 1, 23, 4};
      break;
    case ElementType::hex8:  // 4 x (5x2 + 3x2 + 3 + 5x2 + 20) = 196 hexahedra, 4 through t: L858-861
      d = {1, 2, 2, 2, 1, 20, 4};
      break;
    default:
      throw std::invalid_argument(fmt::format("blade_section: no thesis mesh with {} elements", element_name(element)));
  }
  return d;
}

BladeSection blade_section(const TwoBladeDimensions& dims, const BladeSectionDivisions& n, ElementType element) {
  dims.validate();
  if (element != ElementType::q4 && element != ElementType::cst && element != ElementType::hex8)
    throw std::invalid_argument(
        fmt::format("blade_section: element {} (expected q4, cst or hex8)", element_name(element)));
  for (int v : {n.root_side_columns, n.root_rows, n.neck_rows, n.lip_rows, n.airfoil_columns, n.airfoil_rows, n.layers})
    if (v < 1 || v > 10000) throw std::invalid_argument("blade_section: every division must lie in [1, 10000]");
  if (!(dims.w < dims.w_n))
    throw DimensionError("w", "blade_section: the airfoil (w) must be narrower than the neck (w_n)");
  const bool solid = element == ElementType::hex8;
  const PlanePattern pattern = plane_pattern(dims, n, !solid);  // "the two corners are avoided" in 3D (L858)
  BladeSection out;
  out.mesh = solid ? solid_mesh(pattern, dims.t, n.layers) : plane_mesh(pattern, element);
  const auto y = dims.levels();
  const double x_tip = dims.x_c() + 0.5 * dims.w, z_mid = 0.5 * dims.t;
  const auto mid_plane = [&](const Eigen::VectorXd& p) { return !solid || std::abs(p[2] - z_mid) < kSame; };
  out.sets["root"] = nodes_where(out.mesh, [&](const Eigen::VectorXd& p) {
    return p[1] < y[3] + kSame && (p[1] < kSame || p[0] < kSame || p[0] > dims.B_r - kSame);
  });
  out.sets["tip"] = nodes_where(out.mesh, [&](const Eigen::VectorXd& p) {
    return std::abs(p[0] - x_tip) < kSame && std::abs(p[1] - y[8]) < kSame && mid_plane(p);
  });
  const std::vector<int> face = nodes_where(out.mesh, [&](const Eigen::VectorXd& p) {
    return std::abs(p[0] - x_tip) < kSame && p[1] > y[7] - kSame && mid_plane(p);
  });
  const double y_mid = 0.5 * (y[7] + y[8]);
  out.sets["mid"] = {*std::min_element(face.begin(), face.end(), [&](int a, int b) {
    return std::abs(out.mesh.coords(a, 1) - y_mid) < std::abs(out.mesh.coords(b, 1) - y_mid);
  })};
  out.sets["airfoil"] = nodes_where(out.mesh, [&](const Eigen::VectorXd& p) { return p[1] > y[7] - kSame; });
  return out;
}

}  // namespace bb
