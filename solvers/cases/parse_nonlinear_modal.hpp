// [analysis] of type "nonlinear_modal" (cases/README.md, "Nonlinear modal model").
#pragma once
#include <filesystem>

#include "analysis/nonlinear_modal_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Throws InputError with file:line:key for: a backbone whose amplitudes are not positive and
// strictly increasing, a frequency or damping list of another length, a frequency that is not
// positive or a damping ratio that is not positive anywhere between the knots (the spline may dip
// between positive knots), a non-positive mass, the stepped sines' refusals
// (cases/parse_stepped_sine.hpp), an extract file that is not frf data with a force column; and
// for [[analysis.mode]]: the single-mode keys (mass, backbone) beside it, more than 8 modes, a
// mode without mass or backbone, modes not in ascending order of their linear frequency.
NonlinearModalSpec parse_nonlinear_modal(TomlReader& r, const std::filesystem::path& folder);

}  // namespace bb
