// The validated model a solver sees: mesh, section, node sets, constraints and loads.
// Built from a case file by cases/build_model; solvers never see TOML.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "fe/plane_stress.hpp"
#include "mesh/mesh.hpp"

namespace bb {

// Direction index of a nodal DOF: 0 = x, 1 = y, 2 = z.
using Direction = int;

struct Constraint {
  std::string set;
  std::vector<Direction> directions;
  double value = 0.0;  // prescribed displacement [m]
};

enum class LoadSplit {
  equal,            // total / number of nodes
  consistent_edge,  // work-equivalent nodal forces of a uniform traction on the set's element edges
};

struct NodalLoad {
  std::string set;
  Direction direction = 0;
  double total = 0.0;  // [N]
  LoadSplit split = LoadSplit::equal;
};

struct Model {
  Mesh mesh;
  fe::PlaneSection section;
  std::map<std::string, std::vector<int>> node_sets;  // internal node indices, sorted
  std::vector<Constraint> constraints;
  std::vector<NodalLoad> loads;
};

}  // namespace bb
