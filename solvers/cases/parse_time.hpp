// The keys of [analysis] for type = "time" (see cases/README.md, "Time-domain forced response").
#pragma once
#include <filesystem>

#include "forced/time_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Reads the time keys of `r`, then the hbm keys (cases/parse_hbm.hpp) for the model and the
// sweep; contacts are optional (a linear model). The caller reads `type` and finishes `r`.
TimeSpec parse_time(TomlReader& r, const std::filesystem::path& folder);

}  // namespace bb
