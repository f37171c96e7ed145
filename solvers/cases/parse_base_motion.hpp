// [analysis.base_motion] of a harmonic-balance or time analysis (forced/base_motion_spec.hpp).
#pragma once
#include <filesystem>
#include <vector>

#include "common/toml_reader.hpp"
#include "forced/base_motion_spec.hpp"
#include "forced/hbm_spec.hpp"

namespace bb {

// Reads the table `base_motion` of `analysis` and its `levels` (base accelerations of harmonic 1
// [m/s^2], which the analysis sweeps as it sweeps force levels) into `levels`. Throws InputError.
BaseMotionSpec parse_base_motion(TomlReader& analysis, const std::filesystem::path& folder,
                                 std::vector<double>& levels);

// What a base motion cannot drive (exit 2 naming the key): a cyclic sector or gap damper (an
// engine order's travelling wave is a force pattern), a response control when the base has
// harmonics above the first (the controlled force scales harmonic 1 alone), and in a harmonic
// balance (`harmonic_balance`) a base harmonic above the highest H it may reach.
void refuse_base_motion_misfits(TomlReader& analysis, const HbmSpec& spec, bool harmonic_balance);

}  // namespace bb
