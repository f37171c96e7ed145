#include "mesh/mesh.hpp"

#include "mesh/element_topology.hpp"

namespace bb {

int nodes_per_element(ElementType type) { return topology(type).nodes; }

int element_dimension(ElementType type) { return topology(type).dimension; }

std::string_view element_name(ElementType type) { return topology(type).name; }

int Mesh::n_elements() const {
  int n = 0;
  for (const auto& b : blocks) n += static_cast<int>(b.ids.size());
  return n;
}

int Mesh::index_of(long node_id) const {
  auto it = index_.find(node_id);
  return it == index_.end() ? -1 : it->second;
}

void Mesh::rebuild_index() {
  index_.clear();
  index_.reserve(node_ids.size());
  for (int i = 0; i < n_nodes(); ++i) index_.emplace(node_ids[i], i);
}

}  // namespace bb
