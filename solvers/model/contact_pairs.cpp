#include "model/contact_pairs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "mesh/boundary.hpp"

namespace bb {
namespace {

Eigen::Vector3d centroid(const Mesh& mesh, const std::vector<int>& nodes) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int n : nodes) c += mesh.coords.row(n).transpose();
  return c / static_cast<double>(nodes.size());
}

}  // namespace

ContactPair build_contact_pair(const Model& model, const ContactPairSpec& spec) {
  const Mesh& mesh = model.mesh;
  const std::string where = fmt::format("{}: contact pair '{}'", spec.at.where(), spec.name);
  auto nodes_of = [&](const std::string& key, const std::string& set) {
    const auto it = model.node_sets.find(set);
    if (it == model.node_sets.end()) throw InputError(fmt::format("{}: '{}': unknown node set '{}'", where, key, set));
    return &it->second;
  };
  auto facets_of = [&](const std::string& key, const std::string& set, const std::vector<int>& nodes) {
    std::vector<Facet> facets = boundary_facets_within(mesh, nodes);
    if (facets.empty())
      throw InputError(fmt::format("{}: '{}': node set '{}' holds no boundary face of the mesh (a face counts when "
                                   "all its nodes lie in the set)",
                                   where, key, set));
    return facets;
  };
  const std::vector<int>* contact_nodes = nodes_of("contact", spec.contact);
  const std::vector<int>* target_nodes = nodes_of("target", spec.target);
  std::vector<int> shared;
  std::set_intersection(contact_nodes->begin(), contact_nodes->end(), target_nodes->begin(), target_nodes->end(),
                        std::back_inserter(shared));
  if (!shared.empty())
    throw InputError(fmt::format("{}: node {} belongs to both '{}' and '{}': the surfaces are glued there (merged "
                                 "nodes), not in contact{}",
                                 where, mesh.node_ids[static_cast<size_t>(shared.front())], spec.contact, spec.target,
                                 shared.size() > 1 ? fmt::format(" ({} such nodes)", shared.size()) : ""));
  const std::vector<Facet> contact_facets = facets_of("contact", spec.contact, *contact_nodes);
  const std::vector<Facet> target_facets = facets_of("target", spec.target, *target_nodes);

  // Coincidence within a millionth of the smallest facet's size.
  double size = INFINITY;
  for (const Facet& f : contact_facets)
    for (size_t a = 0; a + 1 < f.nodes.size(); ++a)
      size = std::min(size, (mesh.coords.row(f.nodes[a]) - mesh.coords.row(f.nodes[a + 1])).norm());
  const double tol = 1e-6 * size;
  ContactPair pair;
  pair.name = spec.name;
  pair.contact_set = spec.contact;
  pair.target_set = spec.target;
  pair.interference = spec.interference;
  std::vector<Eigen::Vector3d> target_centroids;
  for (const Facet& f : target_facets) target_centroids.push_back(centroid(mesh, f.nodes));
  for (const Facet& f : contact_facets) {
    const Eigen::Vector3d c = centroid(mesh, f.nodes);
    const Facet* match = nullptr;
    for (size_t t = 0; t < target_facets.size() && !match; ++t)
      if ((target_centroids[t] - c).norm() <= tol && target_facets[t].nodes.size() == f.nodes.size())
        match = &target_facets[t];
    ContactFacetPair fp{f.nodes, {}};
    if (match)
      for (int a : f.nodes) {
        int found = -1;
        for (int b : match->nodes)
          if ((mesh.coords.row(a) - mesh.coords.row(b)).norm() <= tol) found = b;
        if (found < 0) break;
        fp.target.push_back(found);
      }
    if (fp.target.size() != f.nodes.size())
      throw InputError(fmt::format("{}: the face of '{}' centred at ({:.6g}, {:.6g}, {:.6g}) m has no coincident face "
                                   "in '{}': contact pairs need conforming meshes (facing faces with the same nodes)",
                                   where, spec.contact, c.x(), c.y(), c.z(), spec.target));
    pair.facets.push_back(std::move(fp));
  }
  return pair;
}

}  // namespace bb
