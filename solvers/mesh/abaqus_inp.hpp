// Abaqus / CalculiX input decks (.inp): the model data a structural engineer's deck holds, read into
// a Mesh with its node sets, material and boundary conditions. The analysis is the case's: a
// deck's steps are read only for their *BOUNDARY.
#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace bb {

struct InpMaterial {
  std::string name;
  std::optional<double> youngs_modulus, poisson_ratio, density;
  std::string where;  // "file:line" of *MATERIAL
};

// One *BOUNDARY data line: DOFs first..last (1 = x) of a node set held at `value` [m].
struct InpBoundary {
  std::string set;  // a *NSET name, or "INP_NODE_<id>" for a line that names one node
  int first = 1, last = 1;
  double value = 0.0;
  std::string where;
};

struct InpDeck {
  Mesh mesh;  // dim 3 for C3D*, 2 for CPS*; node and element ids as in the deck
  // Node sets by upper-case name (Abaqus compares names case-insensitively): *NSET, *NODE NSET=,
  // and single nodes named by *BOUNDARY; internal node indices, sorted.
  std::map<std::string, std::vector<int>> node_sets;
  std::vector<InpMaterial> materials;  // the materials the *SOLID SECTIONs name
  std::optional<double> thickness;     // plane elements: the *SOLID SECTION's thickness
  std::string thickness_where;
  std::vector<InpBoundary> boundaries;
  std::vector<std::string> notes;  // what was read differently from the deck's own solver (C3D20R, steps)
};

// `folder`: *INCLUDE files must lie inside it (the case's folder). Header only: the keywords and the
// small data (materials, sections, element types) without the node, element and set lists, for the
// case parser. Throws InputError naming file:line and keyword for an element type or keyword
// bladebench does not read, a set or element naming an undefined node, a node or element number given
// twice, a number that is not one, an *INCLUDE outside `folder`.
InpDeck read_abaqus_inp(const std::filesystem::path& file, const std::filesystem::path& folder,
                        bool header_only = false);

}  // namespace bb
