// What the [study] section of a case asks for: one accuracy-vs-cost study of the analysis (mesh
// refinement, element type, reduced-model size, harmonics, time step), run with --study.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/source_location.hpp"
#include "model/model.hpp"

namespace bb {

// Mesh-refinement study of a mapped-quad static case against Timoshenko beam theory.
struct RefinementStudySpec {
  std::vector<int> levels;  // factors applied to nx and ny
  std::string probe_set;    // node set whose mean displacement is tracked
  Direction probe_direction = 1;
  std::optional<LoadSplit> load_split;  // overrides every load's split rule in the study
  std::optional<std::string> load_set;  // moves every load onto this node set in the study
  double beam_length = 0.0;             // Timoshenko reference [m]
  double beam_height = 0.0;             // [m]
  double beam_load = 0.0;               // tip shear force [N], signed like the probe
  double shear_coefficient = 5.0 / 6.0;
  std::string note;  // assumptions, quoted in the report
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
  std::vector<int> modes;                                                     // fixed-interface modes to try
  std::vector<std::pair<std::string, std::vector<std::string>>> master_sets;  // name -> master points
  int compare_modes = 10;  // natural frequencies compared with the full mesh's
  std::string note;
  SourceLocation at;
};

// Convergence in the number of harmonics of the nonlinear forced response: peaks at each H
// against the largest, with the cost of each sweep.
struct HbmHarmonicsStudySpec {
  std::vector<int> harmonics;        // H values, the largest is the reference
  std::vector<double> force_levels;  // a subset of the analysis's levels [N]
  int time_samples = 0;              // AFT samples for every H; 0 = automatic (max(64, 16 (2H + 1)))
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

// Accuracy vs cost of a rotating scene's model levels: (1) the static centrifugal deflection with the
// pre-stressed rotating modes (no time run), (2) the floating frame without geometric stiffening,
// (3) with stiffening in modal bases of `basis_modes` modes, against (4) the finest: every free DOF.
struct RotatingFidelityStudySpec {
  std::vector<int> basis_modes;  // modal basis sizes tried with stiffening
  std::string note;
  SourceLocation at;
};

using StudySpec = std::variant<RefinementStudySpec, ModalRefinementStudySpec, RomStudySpec, HbmHarmonicsStudySpec,
                               TimeStepStudySpec, RotatingFidelityStudySpec>;

}  // namespace bb
