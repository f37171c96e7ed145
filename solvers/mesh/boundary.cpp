#include "mesh/boundary.hpp"

#include <algorithm>
#include <utility>
#include <array>
#include <map>
#include <tuple>

#include "mesh/element_topology.hpp"

namespace bb {

std::vector<Facet> boundary_facets(const Mesh& mesh) {
  // Key: the sorted corner nodes (2 or 4; unused slots -1). Value: uses, and the first facet seen.
  std::map<std::array<int, 4>, std::pair<int, Facet>> facets;
  for (size_t bi = 0; bi < mesh.blocks.size(); ++bi) {
    const ElementBlock& b = mesh.blocks[bi];
    const int n_facets = facet_count(b.type);
    std::vector<std::vector<int>> local(static_cast<size_t>(n_facets));
    for (int f = 0; f < n_facets; ++f) local[static_cast<size_t>(f)] = facet_nodes(b.type, f);
    const int corners = mesh.dim == 2 ? 2 : 4;
    for (Eigen::Index e = 0; e < b.conn.rows(); ++e)
      for (int f = 0; f < n_facets; ++f) {
        const std::vector<int>& l = local[static_cast<size_t>(f)];
        std::array<int, 4> key{-1, -1, -1, -1};
        for (int c = 0; c < corners; ++c) key[static_cast<size_t>(c)] = b.conn(e, l[static_cast<size_t>(c)]);
        // Sorted by fixed bounds: with corners as the end, GCC warns of indices it cannot rule out.
        if (corners == 4)
          std::sort(key.begin(), key.end());
        else if (key[1] < key[0])
          std::swap(key[0], key[1]);
        auto [it, fresh] = facets.try_emplace(key, 0, Facet{});
        if (fresh) {
          Facet& facet = it->second.second;
          facet = {static_cast<int>(bi), e, f, {}};
          for (int n : l) facet.nodes.push_back(b.conn(e, n));
        }
        ++it->second.first;
      }
  }
  std::vector<Facet> out;
  for (auto& [key, value] : facets)
    if (value.first == 1) out.push_back(std::move(value.second));
  // Element order, so that loads and plots do not depend on the map's node order.
  std::sort(out.begin(), out.end(), [](const Facet& a, const Facet& b) {
    return std::tie(a.block, a.element, a.local) < std::tie(b.block, b.element, b.local);
  });
  return out;
}

std::vector<Facet> boundary_facets_within(const Mesh& mesh, const std::vector<int>& nodes) {
  std::vector<char> in(static_cast<size_t>(mesh.n_nodes()), 0);
  for (int n : nodes) in[static_cast<size_t>(n)] = 1;
  std::vector<Facet> out;
  for (Facet& f : boundary_facets(mesh))
    if (std::all_of(f.nodes.begin(), f.nodes.end(), [&](int n) { return in[static_cast<size_t>(n)] != 0; }))
      out.push_back(std::move(f));
  return out;
}

}  // namespace bb
