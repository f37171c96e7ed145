// The nonlinear modal model (analysis type "nonlinear_modal", analysis/nonlinear_modal_spec.hpp):
// its backbones, its stepped sines and response-controlled curves by single-nonlinear-mode
// synthesis (several uncoupled modes summed, forced/multi_mode_synthesis.hpp), and the backbone
// points of measured response-controlled curves. Units: SI.
#pragma once
#include <vector>

#include "analysis/nonlinear_modal_spec.hpp"
#include "forced/backbone_extraction.hpp"
#include "results/table.hpp"

namespace bb {

struct NonlinearModalOutcome {
  ResultTables tables;
  std::vector<BackbonePoint> extracted;  // one per spec.extract
};

// Tables: backbone (the model's f(a) and z(a) on a log grid a decade around its knots; of several
// modes, backbone_<k> per mode); frf_<name> per stepped sine (point, frequency_hz, force_n,
// <dof>_amp_m, <dof>_phase_deg, stable, of several modes each one's <dof>_amp_m_mode<k>, and the
// sensitivity columns <column>_dlog_<path> of spec.sensitivities) and per response control
// (point, frequency_hz, force_n, force_phase_deg, held_m, <dof>_amp_m, <dof>_phase_deg, the
// modes' amplitudes, and force_n_dlog_<path>, <dof>_phase_deg_dlog_<path>); response_control (as
// the hbm analysis's: each curve's smallest force refined by golden section, its frequency and
// phase); and backbone_extracted (per measured curve its backbone point beside the model's f and
// z there, of the mode whose backbone passes nearest its frequency).
// Throws InputError for a measured curve without a resonance inside its band (naming its file)
// or a sensitivity path the model does not have.
NonlinearModalOutcome run_nonlinear_modal(const NonlinearModalSpec& spec);

}  // namespace bb
