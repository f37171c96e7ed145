// ModelSpec -> Model: mesh generation or import, node-set resolution, constraints and loads.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "model/model_spec.hpp"

namespace bb {

// Throws InputError naming file, line and key for a missing file, an unknown set or direction.
// A spec without a mesh (MeshSpec::Kind::none) gives an empty model.
Model build_model(const ModelSpec& spec);

// Node set resolution on its own, also used by the refinement studies on refined meshes.
using NodeGroups = std::map<std::string, std::vector<int>>;  // e.g. Gmsh physical groups
std::vector<int> select_nodes(const Mesh& mesh, const NodeSetSpec& set, const NodeGroups* groups = nullptr);

}  // namespace bb
