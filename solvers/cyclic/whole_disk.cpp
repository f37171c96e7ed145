#include "cyclic/whole_disk.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "cyclic/cyclic_boundary.hpp"
#include "mesh/hex_block.hpp"

namespace bb {

Model whole_from_sector(const Model& sector, int sectors, double tolerance) {
  if (!sector.loads.empty() || !sector.surface_loads.empty() || !sector.body_loads.empty() ||
      !sector.contact_pairs.empty())
    throw InputError(
        "whole structure from a sector: the sector's loads and contact pairs are not carried over; "
        "a verification needs a model without them");
  const Eigen::MatrixXd step = sector_rotation(sectors, sector.mesh.dim);
  std::vector<Mesh> copies;
  Eigen::MatrixXd turn = Eigen::MatrixXd::Identity(sector.mesh.dim, sector.mesh.dim);
  for (int j = 0; j < sectors; ++j) {
    Mesh copy = sector.mesh;
    copy.coords = sector.mesh.coords * turn.transpose();
    copies.push_back(std::move(copy));
    turn = step * turn;
  }
  std::vector<std::vector<int>> origin;
  Model whole;
  whole.mesh = merge_meshes(copies, tolerance, &origin);
  whole.section = sector.section;
  whole.constraints = sector.constraints;
  for (const auto& [name, nodes] : sector.node_sets) {
    std::vector<int>& all = whole.node_sets[name];
    for (const auto& map : origin)
      for (int n : nodes) all.push_back(map[static_cast<size_t>(n)]);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (nodes.size() == 1)  // a point: each copy's too, as "<name>@<j>"
      for (size_t j = 0; j < origin.size(); ++j)
        whole.node_sets[name + "@" + std::to_string(j)] = {origin[j][static_cast<size_t>(nodes.front())]};
  }
  return whole;
}

}  // namespace bb
