// What a case says about its model, validated by the parser: how the mesh is made or read, the
// material, node sets, constraints and loads. model/build_model turns it into a Model.
#pragma once
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "articles/blade_section.hpp"
#include "articles/bladed_disk.hpp"
#include "articles/two_blade.hpp"
#include "common/source_location.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/mapped_quad.hpp"
#include "model/model.hpp"

namespace bb {

struct MeshSpec {
  enum class Kind {
    mapped_quad,
    csv,
    hex_blocks,
    gmsh,
    inp,
    two_blade,
    blade_section,
    bladed_disk,
    none
  } kind = Kind::mapped_quad;  // none: matrices only
  MappedQuadSpec mapped;
  std::filesystem::path nodes_csv;        // csv: columns id,x,y[,z]
  std::filesystem::path elements_csv;     // csv: columns id,n1..nN
  std::vector<HexBlockSpec> blocks;       // hex_blocks: merged at coincident nodes within a body
  std::vector<std::string> block_bodies;  // hex_blocks: the body of each block
  double merge_tolerance = 1e-9;          // [m]
  std::filesystem::path gmsh_file;        // gmsh: .msh 4.1 ASCII
  std::filesystem::path inp_file;         // inp: an Abaqus / CalculiX deck
  std::filesystem::path inp_folder;       // inp: the case's folder, where *INCLUDEs must lie
  std::vector<std::string> inp_notes;     // inp: what the case changes of the deck (its material replaced)
  TwoBladeDimensions two_blade;           // two_blade and blade_section: the thesis's test article, validated
  BladeSectionDivisions blade_divisions;  // blade_section: the chapter-2 blade's divisions
  BladedDiskDimensions bladed_disk;       // bladed_disk: one sector, validated
  ElementType element = ElementType::q4;
  // two_blade: false leaves the root interfaces (root on wedge, root shoulders under the fixture
  // arms) unmerged and names their surfaces (two_blade_contact_set_names()) for contact pairs.
  bool glue = true;
  SourceLocation at;

  int dim() const { return element_dimension(element); }
};

struct NodeSetSpec {
  std::string name;
  std::vector<long> ids;  // explicit ids, or empty
  std::string group;      // a Gmsh physical group name, or empty
  // Coordinate predicate: every given axis must match (|x - value| <= tol, or within a range).
  std::array<std::optional<double>, 3> equals;
  std::array<std::optional<std::pair<double, double>>, 3> range;
  double tol = 1e-9;
  std::string body;  // hex_blocks with bodies: only that body's nodes (the sides of an unmerged interface)
  SourceLocation at;
};

struct ConstraintSpec {
  Constraint constraint;
  SourceLocation at;
};

struct LoadSpec {
  NodalLoad load;
  SourceLocation at;
};

struct SurfaceLoadSpec {
  SurfaceLoad load;
  SourceLocation at;  // of the key naming the set
  std::string key;    // that key's path, e.g. "load[2].faces", for messages
};

struct BodyLoadSpec {
  BodyLoad load;
  SourceLocation at;
};

struct ContactPairSpec {
  std::string name;
  std::string contact, target;  // node sets whose boundary facets face each other
  bool interference = false;
  SourceLocation at;
};

struct ModelSpec {
  MeshSpec mesh;
  fe::PlaneSection section;  // E, nu, rho (and the thickness of plane meshes)
  std::vector<NodeSetSpec> sets;
  std::vector<ConstraintSpec> constraints;
  std::vector<LoadSpec> loads;
  std::vector<SurfaceLoadSpec> surface_loads;
  std::vector<BodyLoadSpec> body_loads;
  std::vector<ContactPairSpec> contact_pairs;
};

}  // namespace bb
