// Cyclic modal analysis: the sector's modes per nodal diameter (cyclic/cyclic_modes.hpp), the
// whole structure's for verification, the engine-order resonances of the interference diagram.
#pragma once
#include <optional>
#include <vector>

#include "analysis/cyclic_modal_spec.hpp"
#include "assembly/dof_map.hpp"
#include "cyclic/cyclic_campbell.hpp"
#include "cyclic/cyclic_modes.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

struct WholeStructureCheck {
  int free_dofs = 0;
  double cut_hz = 0.0;       // the compared spectrum lies below it (just under the lowest top family)
  Eigen::VectorXd whole_hz;  // the whole structure's lowest modes below the cut
  Eigen::VectorXd union_hz;  // the nodal diameters' families below the cut, pairs twice, ascending
  std::vector<int> union_diameter;
  int whole_count = -1;       // Sturm count of the whole structure at the cut
  int sector_count_sum = -1;  // sum over nodal diameters of their counts (pairs twice)
  double seconds = 0.0;
};

struct EngineOrderResonance {
  int engine_order = 0;
  int nodal_diameter = 0;
  int family = 0;  // 1-based
  double frequency_hz = 0.0;
  double speed_rpm = 0.0;  // where EO x speed / 60 equals the (stationary) frequency
};

struct CyclicModalOutcome {
  int sectors = 0;
  DofMap dofs;  // the sector's, for the wave shapes
  std::vector<NodalDiameterModes> diameters;
  std::optional<WholeStructureCheck> whole;
  std::vector<EngineOrderResonance> resonances;  // at rest
  std::optional<CyclicCampbell> campbell;
  std::vector<CyclicCrossing> crossings;  // on the Campbell diagram
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;
};

// Throws InputError for unknown or unmatched face sets, SolverError when a solve fails.
CyclicModalOutcome run_cyclic_modal(const Model& model, const CyclicModalSpec& spec);

// nodal_diameter_map (f1_hz.. per nodal diameter), cyclic_completeness, and with the whole
// structure cyclic_spectrum, whole_spectrum and whole_count; engine_order_resonances; with speeds
// campbell (row, speed_rpm, nodal_diameter, f1_hz..) and engine_order_crossings.
ResultTables cyclic_modal_tables(const CyclicModalOutcome& outcome);

}  // namespace bb
