// A measured phase that cannot be the model's convention: 180 degrees off (a displacement phase
// given for an acceleration, a force's sign) or of the opposite lag sign. A fit would "converge"
// on such data with its parameters on their bounds; this looks at the points of the start.
#pragma once
#include <string>
#include <vector>

#include "identify/calibration_spec.hpp"
#include "identify/fit_points.hpp"

namespace bb {

// The phase points of each data block of `cal` at the start values (`points`, data_points' sets
// named as the blocks). Throws InputError naming the block and its file's phase column when the
// measured phase passes through a resonance (changes by 90 degrees or more over the curve) and
// the start's misfit is 45 degrees or more (rms) but a third of it or less once the phase is
// moved by 180 degrees or its sign reversed. Returns warnings where the data may be right: the
// misfit near 180 degrees at every point while the data pass through no resonance (a start far
// from the data looks the same), or the measured phase's trend through the curve opposite to the
// model's by 90 degrees or more each.
std::vector<std::string> check_measured_phases(const CalibrationSpec& cal, const std::vector<FitPoint>& points);

}  // namespace bb
