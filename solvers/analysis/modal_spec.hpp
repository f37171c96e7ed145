// What a modal analysis computes: which modes, the eigensolver's options, and optionally the labels
// of the modes of two identical bodies side by side (analysis/mode_pairs.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/source_location.hpp"
#include "linalg/modal_solver.hpp"
#include "model/model.hpp"

namespace bb {

// Which modes a modal analysis returns.
struct ModeSelection {
  int lowest = 6;                     // the lowest n modes, when no band is given
  std::optional<double> band_min_hz;  // all modes with band_min_hz <= f <= band_max_hz
  std::optional<double> band_max_hz;
};

struct ModePairSpec {
  std::string left;         // single-node set on body 1 (e.g. "T1", the tip centre)
  std::string right;        // single-node set on body 2 at the corresponding place ("T2")
  Direction direction = 0;  // component compared for IP / OOP, unless the nodes hardly move along it
  std::string left_tip;     // node sets of the tip faces (blade axis along y): the mode type
  std::string right_tip;
  SourceLocation at;  // of [analysis.pairs]
};

struct ModalSpec {
  ModeSelection modes;
  ModalOptions options;
  std::optional<ModePairSpec> pairs;
  // Modes (1-based) whose stresses are recovered and written (nodal_stresses_mode<k>.csv): the
  // stress per unit modal coordinate of the mass-normalized shape, for where a mode strains the
  // part most (gauges, fatigue). Empty: none, the recovery costs one pass over the mesh per mode.
  std::vector<int> stress_modes;
};

}  // namespace bb
