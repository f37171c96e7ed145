// A case file parsed into plain, validated structs (parse once, at the edge).
#pragma once
#include <filesystem>
#include <toml++/toml.h>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/contact_loop_spec.hpp"
#include "analysis/frf_spec.hpp"
#include "analysis/hbm_spec.hpp"
#include "analysis/time_spec.hpp"
#include "analysis/modal_analysis.hpp"
#include "analysis/mode_pairs.hpp"
#include "articles/two_blade.hpp"
#include "common/source_location.hpp"
#include "linalg/modal_solver.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/mapped_quad.hpp"
#include "model/model.hpp"

namespace bb {

struct MeshSpec {
  enum class Kind { mapped_quad, csv, hex_blocks, gmsh, two_blade, none } kind = Kind::mapped_quad;  // none: matrices only
  MappedQuadSpec mapped;
  std::filesystem::path nodes_csv;     // csv: columns id,x,y[,z]
  std::filesystem::path elements_csv;  // csv: columns id,n1..nN
  std::vector<HexBlockSpec> blocks;    // hex_blocks: merged at coincident nodes
  double merge_tolerance = 1e-9;       // [m]
  std::filesystem::path gmsh_file;     // gmsh: .msh 4.1 ASCII
  TwoBladeDimensions two_blade;        // two_blade: the thesis's test article, validated
  ElementType element = ElementType::q4;
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

enum class AnalysisType { static_linear, modal, frf, hbm, time, contact_loop };

struct AnalysisSpec {
  AnalysisType type = AnalysisType::static_linear;
  ModeSelection modes;
  ModalOptions modal;
  FrfSpec frf;                        // frf: linear forced response
  HbmSpec hbm;                        // hbm: nonlinear forced response (harmonic balance)
  TimeSpec time;                      // time: forced response by time integration (stepped sine)
  ContactLoopSpec contact_loop;       // contact_loop: one contact under imposed relative motion (test rig)
  std::optional<ModePairSpec> pairs;  // modal, frf: in-phase / out-of-phase and type of each mode
  SourceLocation pairs_at;
};

// Compare result columns to reference columns, row by row on a shared integer key.
struct CheckSpec {
  std::string name;
  std::string result;                 // result table, e.g. "nodal_displacements"
  std::filesystem::path reference;    // CSV, resolved against the case file's folder; or empty when
  std::string reference_result;       // another result table of the same run is the reference
  std::string key;                    // key column of the reference, e.g. "node"
  std::vector<std::pair<std::string, std::string>> compare;  // result column -> reference column
  std::vector<long> keys;             // compare only these reference rows; empty = every row
  double abs_tol = 0.0;
  double rel_tol = 0.0;
  std::string source;                 // where the reference values come from (for the report)
  SourceLocation at;
};

// Mesh-refinement study of a mapped-quad static case against Timoshenko beam theory.
struct RefinementStudySpec {
  std::vector<int> levels;                   // factors applied to nx and ny
  std::string probe_set;                     // node set whose mean displacement is tracked
  Direction probe_direction = 1;
  std::optional<LoadSplit> load_split;       // overrides every load's split rule in the study
  std::optional<std::string> load_set;       // moves every load onto this node set in the study
  double beam_length = 0.0;                  // Timoshenko reference [m]
  double beam_height = 0.0;                  // [m]
  double beam_load = 0.0;                    // tip shear force [N], signed like the probe
  double shear_coefficient = 5.0 / 6.0;
  std::string note;                          // assumptions, quoted in the report
  SourceLocation at;
};

// Mesh-refinement study of a solid modal case: the first `modes` frequencies for every element
// type at every refinement level, against the finest hex20 mesh, with the cost of each.
struct ModalRefinementStudySpec {
  std::vector<int> refinements;       // two_blade: the article's refinement; hex_blocks: factor on nx, ny, nz
  std::vector<ElementType> elements;  // solid element types to compare
  int modes = 10;
  std::string note;
  SourceLocation at;
};

// Accuracy vs cost of reduced models: fixed-interface modes x master sets, against the full mesh.
struct RomStudySpec {
  std::vector<int> modes;                                                   // fixed-interface modes to try
  std::vector<std::pair<std::string, std::vector<std::string>>> master_sets;  // name -> master points
  int compare_modes = 10;  // natural frequencies compared with the full mesh's
  std::string note;
  SourceLocation at;
};

// Convergence in the number of harmonics of the nonlinear forced response: peaks at each H
// against the largest, with the cost of each sweep.
struct HbmHarmonicsStudySpec {
  std::vector<int> harmonics;       // H values, the largest is the reference
  std::vector<double> force_levels; // a subset of the analysis's levels [N]
  int time_samples = 0;             // AFT samples for every H; 0 = automatic (max(64, 16 (2H + 1)))
  std::string note;
  SourceLocation at;
};

// Accuracy vs cost of the time integration: steps per period x steady-state tolerance, each
// variant's peaks and FRF against the finest variant, with its cost.
struct TimeStepStudySpec {
  std::vector<int> steps_per_period;
  std::vector<double> steady_tolerances;
  std::string note;
  SourceLocation at;
};

struct CaseSpec {
  std::filesystem::path file;
  std::string name;
  std::string title;
  std::string description;
  std::filesystem::path model_from;  // the case whose material, mesh, sets and constraints these are
  MeshSpec mesh;
  fe::PlaneSection section;
  std::vector<NodeSetSpec> sets;
  std::vector<ConstraintSpec> constraints;
  std::vector<LoadSpec> loads;
  AnalysisSpec analysis;
  std::vector<CheckSpec> checks;
  std::optional<RefinementStudySpec> study;
  std::optional<ModalRefinementStudySpec> modal_study;
  std::optional<RomStudySpec> rom_study;
  std::optional<HbmHarmonicsStudySpec> hbm_study;
  std::optional<TimeStepStudySpec> time_study;
};

// Throws InputError naming file, line and key for every malformed or missing entry.
CaseSpec parse_case_file(const std::filesystem::path& file);

// The same in two steps, so a caller can change values (e.g. calibration parameters) between
// reading and parsing; `file` locates relative paths and names the source in messages.
toml::table read_case_table(const std::filesystem::path& file);
CaseSpec parse_case_table(const toml::table& root, const std::filesystem::path& file);

// Mesh, sets, constraints and loads resolved against the mesh. Throws InputError.
Model build_model(const CaseSpec& spec);

// Node set resolution on its own, also used by the refinement study on refined meshes.
using NodeGroups = std::map<std::string, std::vector<int>>;  // e.g. Gmsh physical groups
std::vector<int> select_nodes(const Mesh& mesh, const NodeSetSpec& set, const NodeGroups* groups = nullptr);

}  // namespace bb
