// The keys of [analysis] for type = "hbm" (see cases/README.md, "Nonlinear forced response").
#pragma once
#include <filesystem>

#include "common/toml_reader.hpp"
#include "forced/hbm_spec.hpp"

namespace bb {

// Reads the hbm keys of `r` (the caller reads `type` and finishes `r`). Throws InputError.
// `contacts_required`: a harmonic balance needs a nonlinearity; a time integration may run a linear model.
HbmSpec parse_hbm(TomlReader& r, const std::filesystem::path& folder, bool contacts_required = true);

}  // namespace bb
