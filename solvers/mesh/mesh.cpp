#include "mesh/mesh.hpp"

namespace bb {

int nodes_per_element(ElementType type) {
  switch (type) {
    case ElementType::q4: return 4;
    case ElementType::cst: return 3;
    case ElementType::hex8:
    case ElementType::hex8i: return 8;
    case ElementType::hex20: return 20;
  }
  return 0;
}

int element_dimension(ElementType type) {
  return type == ElementType::q4 || type == ElementType::cst ? 2 : 3;
}

std::string_view element_name(ElementType type) {
  switch (type) {
    case ElementType::q4: return "q4";
    case ElementType::cst: return "cst";
    case ElementType::hex8: return "hex8";
    case ElementType::hex8i: return "hex8i";
    case ElementType::hex20: return "hex20";
  }
  return "?";
}

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
