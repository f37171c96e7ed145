// The keys of [analysis] for type = "hbm" (see cases/README.md, "Nonlinear forced response").
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "common/toml_reader.hpp"
#include "forced/hbm_spec.hpp"

namespace bb {

// Reads the hbm keys of `r` (the caller reads `type` and finishes `r`). Throws InputError.
// `contacts_required`: a harmonic balance needs a nonlinearity; a time integration may run a linear model.
HbmSpec parse_hbm(TomlReader& r, const std::filesystem::path& folder, bool contacts_required = true);

// The levels of a sweep, each of which names its table (hbm_frf_table_name): positive, finite, not
// repeated, and distinct in those names. Exit 2 naming `key` of `r`; `quantity` and `unit` for the
// message ("force", "N").
void check_levels(TomlReader& r, const std::string& key, const std::vector<double>& levels, const char* quantity,
                  const char* unit);

}  // namespace bb
