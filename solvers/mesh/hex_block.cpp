// Structured hexahedral blocks and the merging of meshes at coincident nodes. Units: SI (m).
#include "mesh/hex_block.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "mesh/element_topology.hpp"

namespace bb {
namespace {

// Parameter-space position of the hex20 nodes in the doubled lattice of one cell (corners at 0
// and 2, mid-edge nodes at 1), in the node order of mesh/mesh.hpp.
constexpr std::array<std::array<int, 3>, 8> kCorner = {{
    {0, 0, 0},
    {2, 0, 0},
    {2, 2, 0},
    {0, 2, 0},
    {0, 0, 2},
    {2, 0, 2},
    {2, 2, 2},
    {0, 2, 2},
}};
// Mid-edge nodes 9-20 (1-based): the corner pairs of each edge, 0-based.
constexpr std::array<std::array<int, 2>, 12> kHex20Edge = {{
    {0, 1},
    {1, 2},
    {2, 3},
    {3, 0},
    {4, 5},
    {5, 6},
    {6, 7},
    {7, 4},
    {0, 4},
    {1, 5},
    {2, 6},
    {3, 7},
}};

Eigen::Vector3d trilinear(const std::array<Eigen::Vector3d, 8>& c, double s, double r, double t) {
  return (1 - s) * (1 - r) * (1 - t) * c[0] + s * (1 - r) * (1 - t) * c[1] + s * r * (1 - t) * c[2] +
         (1 - s) * r * (1 - t) * c[3] + (1 - s) * (1 - r) * t * c[4] + s * (1 - r) * t * c[5] + s * r * t * c[6] +
         (1 - s) * r * t * c[7];
}

// Jacobian determinant of the trilinear map at a corner of the unit cube: the triple product of
// the three block edges leaving that corner, each taken in the direction of increasing parameter.
double corner_jacobian(const std::array<Eigen::Vector3d, 8>& c, int corner) {
  const auto& p = kCorner[static_cast<size_t>(corner)];
  auto neighbour = [&](int axis) {
    std::array<int, 3> q = p;
    q[static_cast<size_t>(axis)] = 2 - q[static_cast<size_t>(axis)];
    for (int a = 0; a < 8; ++a)
      if (kCorner[static_cast<size_t>(a)] == q) return a;
    return corner;
  };
  Eigen::Matrix3d edges;
  for (int axis = 0; axis < 3; ++axis) {
    const double sign = p[static_cast<size_t>(axis)] == 0 ? 1.0 : -1.0;
    edges.col(axis) = sign * (c[static_cast<size_t>(neighbour(axis))] - c[static_cast<size_t>(corner)]);
  }
  return edges.determinant();
}

struct CellKey {
  std::int64_t i, j, k;
  bool operator==(const CellKey&) const = default;
};

struct CellKeyHash {
  size_t operator()(const CellKey& key) const {
    std::uint64_t h = static_cast<std::uint64_t>(key.i) * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(key.j) + 0x9E3779B97F4A7C15ULL + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(key.k) + 0x9E3779B97F4A7C15ULL + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};

std::string element_label(const ElementBlock& b, Eigen::Index row) {
  const auto r = static_cast<size_t>(row);
  return r < b.ids.size() ? std::to_string(b.ids[r]) : "#" + std::to_string(row + 1);
}

}  // namespace

int inverted_corner(const std::array<Eigen::Vector3d, 8>& corners) {
  for (int a = 0; a < 8; ++a)
    if (!(corner_jacobian(corners, a) > 0.0)) return a + 1;
  return 0;
}

Mesh generate_hex_block(const HexBlockSpec& spec) {
  if (spec.nx < 1 || spec.ny < 1 || spec.nz < 1) throw std::invalid_argument("nx, ny and nz must be >= 1");
  if (topology(spec.element).dimension != 3)
    throw std::invalid_argument("a hex block needs a solid element type (hex8, hex8i or hex20), not " +
                                std::string(element_name(spec.element)));
  // Only a necessary condition for a valid block, but it catches the common mistake: corners
  // given clockwise, or 5-8 below 1-4, which would make every element inside-out.
  if (const int a = inverted_corner(spec.corners); a > 0)
    throw std::invalid_argument("hex block corner " + std::to_string(a) +
                                ": corners 1->2, 1->4, 1->5 must form a right-handed frame (inverted or flat block)");

  // Nodes live on a lattice of `step` points per division: every point for hex8; for hex20 the
  // doubled lattice without face and cell centres (points with two or three odd indices).
  const bool quadratic = topology(spec.element).quadratic();
  const int step = quadratic ? 2 : 1;
  const int mx = step * spec.nx + 1, my = step * spec.ny + 1, mz = step * spec.nz + 1;
  auto lattice = [mx, my](int i, int j, int k) {
    return (static_cast<size_t>(k) * static_cast<size_t>(my) + static_cast<size_t>(j)) * static_cast<size_t>(mx) +
           static_cast<size_t>(i);
  };
  std::vector<int> node_at(static_cast<size_t>(mx) * static_cast<size_t>(my) * static_cast<size_t>(mz), -1);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < mz; ++k)
    for (int j = 0; j < my; ++j)
      for (int i = 0; i < mx; ++i) {
        if (quadratic && (i % 2) + (j % 2) + (k % 2) > 1) continue;
        node_at[lattice(i, j, k)] = static_cast<int>(points.size());
        points.push_back(trilinear(spec.corners, static_cast<double>(i) / (mx - 1), static_cast<double>(j) / (my - 1),
                                   static_cast<double>(k) / (mz - 1)));
      }

  Mesh mesh;
  mesh.dim = 3;
  const auto n_nodes = static_cast<Eigen::Index>(points.size());
  mesh.coords.resize(n_nodes, 3);
  mesh.node_ids.resize(points.size());
  for (Eigen::Index n = 0; n < n_nodes; ++n) {
    mesh.coords.row(n) = points[static_cast<size_t>(n)].transpose();
    mesh.node_ids[static_cast<size_t>(n)] = spec.first_node_id + n;
  }

  ElementBlock block;
  block.type = spec.element;
  const int per_element = nodes_per_element(spec.element);
  const Eigen::Index n_elem = static_cast<Eigen::Index>(spec.nx) * spec.ny * spec.nz;
  block.conn.resize(n_elem, per_element);
  block.ids.resize(static_cast<size_t>(n_elem));
  Eigen::Index e = 0;
  for (int k = 0; k < spec.nz; ++k)
    for (int j = 0; j < spec.ny; ++j)
      for (int i = 0; i < spec.nx; ++i, ++e) {
        // Lattice position of a node given in the doubled cell coordinates (0, 1, 2 per axis).
        auto node = [&](int a, int b, int c) {
          return node_at[lattice(step * i + a * step / 2, step * j + b * step / 2, step * k + c * step / 2)];
        };
        for (int a = 0; a < 8; ++a) {
          const auto& p = kCorner[static_cast<size_t>(a)];
          block.conn(e, a) = node(p[0], p[1], p[2]);
        }
        if (quadratic) {
          for (int m = 0; m < 12; ++m) {
            const auto& p = kCorner[static_cast<size_t>(kHex20Edge[static_cast<size_t>(m)][0])];
            const auto& q = kCorner[static_cast<size_t>(kHex20Edge[static_cast<size_t>(m)][1])];
            block.conn(e, 8 + m) = node((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2);
          }
        }
        block.ids[static_cast<size_t>(e)] = spec.first_element_id + e;
      }
  mesh.blocks.push_back(std::move(block));
  mesh.rebuild_index();
  return mesh;
}

namespace {

// merge_meshes, or with merge = false a plain concatenation that keeps coincident nodes apart.
Mesh combine_meshes(const std::vector<Mesh>& parts, double tolerance, bool merge,
                    std::vector<std::vector<int>>* node_origin) {
  if (parts.empty()) throw std::invalid_argument("merge_meshes: no meshes to merge");
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("merge_meshes: tolerance must be a finite number >= 0");
  const int dim = parts.front().dim;
  if (dim != 2 && dim != 3) throw std::invalid_argument("merge_meshes: meshes must be 2D or 3D");
  Eigen::Index total_nodes = 0;
  double extent = 0.0;
  for (size_t p = 0; p < parts.size(); ++p) {
    const Mesh& part = parts[p];
    if (part.dim != dim)
      throw std::invalid_argument("merge_meshes: mesh " + std::to_string(p) + " has dimension " +
                                  std::to_string(part.dim) + ", mesh 0 has " + std::to_string(dim));
    if (part.coords.rows() != part.n_nodes() || (part.n_nodes() > 0 && part.coords.cols() != dim))
      throw std::invalid_argument("merge_meshes: mesh " + std::to_string(p) +
                                  " has coordinates that do not match its nodes");
    total_nodes += part.n_nodes();
    if (part.coords.size() > 0) extent = std::max(extent, part.coords.cwiseAbs().maxCoeff());
  }
  if (!std::isfinite(extent)) throw std::invalid_argument("merge_meshes: non-finite node coordinates");

  // Buckets of side h >= tolerance, so two nodes within the tolerance sit in the same or in
  // adjacent buckets. h is never so small that bucket indices could overflow; a larger h only
  // puts more nodes in each bucket, it never misses a match.
  double h = std::max(tolerance, extent * 1e-12);
  if (h == 0.0) h = 1.0;  // every node at the origin and an exact-match tolerance
  auto bucket_of = [h](const Eigen::Vector3d& x) {
    return CellKey{static_cast<std::int64_t>(std::floor(x(0) / h)), static_cast<std::int64_t>(std::floor(x(1) / h)),
                   static_cast<std::int64_t>(std::floor(x(2) / h))};
  };
  std::unordered_map<CellKey, std::vector<int>, CellKeyHash> buckets;
  buckets.reserve(static_cast<size_t>(total_nodes));
  std::vector<Eigen::Vector3d> merged;  // z = 0 in 2D
  merged.reserve(static_cast<size_t>(total_nodes));
  std::vector<std::vector<int>> origin(parts.size());
  const double tol2 = tolerance * tolerance;
  for (size_t p = 0; p < parts.size(); ++p) {
    const Mesh& part = parts[p];
    origin[p].resize(static_cast<size_t>(part.n_nodes()));
    for (int n = 0; n < part.n_nodes(); ++n) {
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      x.head(dim) = part.coords.row(n).transpose();
      const CellKey key = bucket_of(x);
      int match = -1;
      const std::int64_t dk = dim == 3 ? 1 : 0;
      for (std::int64_t a = -1; a <= 1 && merge; ++a)
        for (std::int64_t b = -1; b <= 1; ++b)
          for (std::int64_t c = -dk; c <= dk; ++c) {
            auto it = buckets.find({key.i + a, key.j + b, key.k + c});
            if (it == buckets.end()) continue;
            // The earliest node wins, so the result does not depend on the bucket visiting order.
            for (int m : it->second)
              if ((match < 0 || m < match) && (merged[static_cast<size_t>(m)] - x).squaredNorm() <= tol2) match = m;
          }
      if (match < 0) {
        match = static_cast<int>(merged.size());
        merged.push_back(x);
        buckets[key].push_back(match);
      }
      origin[p][static_cast<size_t>(n)] = match;
    }
  }

  Mesh out;
  out.dim = dim;
  const auto n_out = static_cast<Eigen::Index>(merged.size());
  out.coords.resize(n_out, dim);
  out.node_ids.resize(merged.size());
  for (Eigen::Index n = 0; n < n_out; ++n) {
    out.coords.row(n) = merged[static_cast<size_t>(n)].head(dim).transpose();
    out.node_ids[static_cast<size_t>(n)] = n + 1;
  }

  // One block per element type, in order of first appearance.
  std::vector<ElementType> types;
  for (const Mesh& part : parts)
    for (const ElementBlock& b : part.blocks)
      if (std::find(types.begin(), types.end(), b.type) == types.end()) types.push_back(b.type);
  long next_id = 1;
  for (ElementType type : types) {
    Eigen::Index rows = 0;
    for (const Mesh& part : parts)
      for (const ElementBlock& b : part.blocks)
        if (b.type == type) rows += b.conn.rows();
    ElementBlock block;
    block.type = type;
    const int per_element = nodes_per_element(type);
    block.conn.resize(rows, per_element);
    block.ids.reserve(static_cast<size_t>(rows));
    Eigen::Index e = 0;
    for (size_t p = 0; p < parts.size(); ++p)
      for (const ElementBlock& b : parts[p].blocks) {
        if (b.type != type) continue;
        if (b.conn.cols() != per_element)
          throw std::invalid_argument("merge_meshes: a " + std::string(element_name(type)) + " block of mesh " +
                                      std::to_string(p) + " has " + std::to_string(b.conn.cols()) +
                                      " nodes per element");
        for (Eigen::Index r = 0; r < b.conn.rows(); ++r, ++e) {
          for (int a = 0; a < per_element; ++a) {
            const int local = b.conn(r, a);
            if (local < 0 || local >= parts[p].n_nodes())
              throw std::invalid_argument("merge_meshes: mesh " + std::to_string(p) +
                                          " has an element with node index " + std::to_string(local) + " out of range");
            block.conn(e, a) = origin[p][static_cast<size_t>(local)];
          }
          // A tolerance larger than an element would collapse it; that is never what was meant.
          for (int a = 0; a < per_element; ++a)
            for (int c = a + 1; c < per_element; ++c)
              if (block.conn(e, a) == block.conn(e, c))
                throw std::invalid_argument("merge_meshes: tolerance " + std::to_string(tolerance) +
                                            " merges two nodes of element " + element_label(b, r) + " of mesh " +
                                            std::to_string(p));
          block.ids.push_back(next_id++);
        }
      }
    out.blocks.push_back(std::move(block));
  }
  out.rebuild_index();
  if (node_origin) *node_origin = std::move(origin);
  return out;
}

}  // namespace

Mesh merge_meshes(const std::vector<Mesh>& parts, double tolerance, std::vector<std::vector<int>>* node_origin) {
  return combine_meshes(parts, tolerance, true, node_origin);
}

Mesh concatenate_meshes(const std::vector<Mesh>& parts, std::vector<std::vector<int>>* node_origin) {
  return combine_meshes(parts, 0.0, false, node_origin);
}

}  // namespace bb
