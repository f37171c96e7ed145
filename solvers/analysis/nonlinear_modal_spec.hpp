// What a nonlinear_modal analysis computes: the driven point of one nonlinear mode, or a few
// uncoupled ones, whose natural frequency and damping ratio depend on the amplitude there
// (forced/single_mode_synthesis.hpp, forced/multi_mode_synthesis.hpp),
// under the stepped sines a rig runs (force-controlled, read from measured files or written in the
// case; response-controlled at a held amplitude), with exact sensitivities to its backbone's
// knots and mass for calibration; and, from measured response-controlled curves, the backbone
// points each curve implies (forced/backbone_extraction.hpp). Units: SI, frequencies in Hz.
#pragma once
#include <string>
#include <vector>

#include "common/source_location.hpp"
#include "forced/hbm_spec.hpp"
#include "forced/single_mode_synthesis.hpp"

namespace bb {

// A measured response-controlled curve read for its backbone point.
struct BackboneCurve {
  std::string name;  // the file's stem
  std::string file;
  std::vector<double> frequency_hz, amplitude_m, force_n;  // displacement amplitude, as read
  SourceLocation at;
};

struct NonlinearModalSpec {
  std::vector<NonlinearMode> modes;  // ascending linear frequency; one in the single-mode form
  bool mode_array = false;           // given as [[analysis.mode]]: names the paths and backbone tables
  std::string dof;                   // the driven and measured point, e.g. "A.x": names the table columns
  std::vector<SteppedSineSpec> stepped_sines;
  std::vector<ResponseControlSpec> response_controls;
  std::vector<BackboneCurve> extract;  // [analysis] extract = [files]
  // Parameter paths whose log-sensitivities the tables carry (<column>_dlog_<path>): set by
  // calibration, each one of parameter_paths() below.
  std::vector<std::string> sensitivities;
  SourceLocation at;
};

// The paths of the model's parameters, mode after mode, each in NonlinearMode order:
// analysis.backbone.frequency_hz.<i>, analysis.backbone.damping_ratio.<i>, analysis.mass (one
// mode, the single-mode form), or analysis.mode.<k>.backbone.{frequency_hz,damping_ratio}.<i>,
// analysis.mode.<k>.mass ([[analysis.mode]]).
std::vector<std::string> nonlinear_modal_parameter_paths(const NonlinearModalSpec& spec);
// Their values, in the same order.
std::vector<double> nonlinear_modal_parameter_values(const NonlinearModalSpec& spec);

}  // namespace bb
