#include "cyclic/cyclic_boundary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "common/errors.hpp"

namespace bb {

Eigen::MatrixXd sector_rotation(int sectors, int dim) {
  const double a = 2 * std::numbers::pi / sectors;
  Eigen::MatrixXd r = Eigen::MatrixXd::Identity(dim, dim);
  if (dim >= 2) r.topLeftCorner(2, 2) << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return r;
}

SectorFaces pair_sector_faces(const Mesh& mesh, const std::vector<int>& left, const std::vector<int>& right,
                              int sectors, double tolerance, const std::string& what) {
  if (left.size() != right.size())
    throw InputError(
        fmt::format("{}: the left face has {} nodes and the right face {}: they cannot match by the "
                    "sector rotation",
                    what, left.size(), right.size()));
  const Eigen::MatrixXd rotation = sector_rotation(sectors, mesh.dim);
  // Images of the left nodes on a grid of `tolerance` cells: each right node looks in its cell
  // and the neighbours, so the pairing is linear in the face size.
  const double cell = std::max(tolerance, 1e-300);
  auto key = [&](const Eigen::VectorXd& p, int shift_x, int shift_y, int shift_z) {
    return std::array<long long, 3>{static_cast<long long>(std::floor(p[0] / cell)) + shift_x,
                                    static_cast<long long>(std::floor(p[1] / cell)) + shift_y,
                                    mesh.dim > 2 ? static_cast<long long>(std::floor(p[2] / cell)) + shift_z : 0};
  };
  std::map<std::array<long long, 3>, std::vector<int>> grid;
  std::vector<Eigen::VectorXd> image(left.size());
  for (size_t i = 0; i < left.size(); ++i) {
    image[i] = rotation * mesh.coords.row(left[i]).transpose();
    grid[key(image[i], 0, 0, 0)].push_back(static_cast<int>(i));
  }
  const std::set<int> on_left(left.begin(), left.end());
  SectorFaces faces;
  std::vector<bool> taken(left.size(), false);
  for (int n : right) {
    if (on_left.count(n))
      throw InputError(
          fmt::format("{}: node {} lies on both cyclic faces (on the axis?): a sector needs a bore or a "
                      "hub node of its own",
                      what, mesh.node_ids[static_cast<size_t>(n)]));
    const Eigen::VectorXd p = mesh.coords.row(n).transpose();
    int match = -1;
    for (int sx = -1; sx <= 1 && match < 0; ++sx)
      for (int sy = -1; sy <= 1 && match < 0; ++sy)
        for (int sz = -1; sz <= 1 && match < 0; ++sz)
          if (auto it = grid.find(key(p, sx, sy, sz)); it != grid.end())
            for (int i : it->second)
              if (!taken[static_cast<size_t>(i)] && (image[static_cast<size_t>(i)] - p).norm() <= tolerance) {
                match = i;
                break;
              }
    if (match < 0) {
      const Eigen::VectorXd q = rotation.transpose() * p;
      size_t nearest = 0;  // the closest image, to say how far the faces miss
      for (size_t i = 1; i < image.size(); ++i)
        if ((image[i] - p).norm() < (image[nearest] - p).norm()) nearest = i;
      throw InputError(fmt::format(
          "{}: right-face node {} at ({:.6g}, {:.6g}, {:.6g}) is not the image of any left-face node under a "
          "rotation by 360/{} deg about z (no left node within {:.3g} m of ({:.6g}, {:.6g}, {:.6g}); the nearest "
          "image, of left node {}, is {:.3g} m away)",
          what, mesh.node_ids[static_cast<size_t>(n)], p[0], p[1], mesh.dim > 2 ? p[2] : 0.0, sectors, tolerance, q[0],
          q[1], mesh.dim > 2 ? q[2] : 0.0, mesh.node_ids[static_cast<size_t>(left[nearest])],
          (image[nearest] - p).norm()));
    }
    taken[static_cast<size_t>(match)] = true;
    faces.left.push_back(left[static_cast<size_t>(match)]);
    faces.right.push_back(n);
  }
  return faces;
}

CyclicDofs cyclic_dofs(const Mesh& mesh, const DofMap& dofs, const SectorFaces& faces, int sectors) {
  CyclicDofs c;
  c.sectors = sectors;
  c.dim = dofs.dim;
  c.rotation = sector_rotation(sectors, dofs.dim);
  for (size_t i = 0; i < faces.left.size(); ++i) {
    // The rotation mixes x and y: a pair may fix them only together, and alike on both faces.
    const int l0 = faces.left[i] * dofs.dim, r0 = faces.right[i] * dofs.dim;
    bool alike = true, fixed_xy = false, free_xy = false;
    for (int d = 0; d < dofs.dim; ++d) {
      const bool lf = dofs.equation[static_cast<size_t>(l0 + d)] < 0,
                 rf = dofs.equation[static_cast<size_t>(r0 + d)] < 0;
      alike = alike && lf == rf;
      if (d < 2) (lf ? fixed_xy : free_xy) = true;
    }
    if (!alike || (fixed_xy && free_xy))
      throw InputError(fmt::format(
          "cyclic symmetry: node pair {} / {} is constrained differently on the two faces, or "
          "in x but not y: the sector's constraints must be cyclic (whole nodes, or z alone)",
          mesh.node_ids[static_cast<size_t>(faces.left[i])], mesh.node_ids[static_cast<size_t>(faces.right[i])]));
    for (int d = 0; d < dofs.dim; ++d) {
      c.left.push_back(dofs.equation[static_cast<size_t>(l0 + d)]);
      c.right.push_back(dofs.equation[static_cast<size_t>(r0 + d)]);
    }
  }
  return c;
}

}  // namespace bb
