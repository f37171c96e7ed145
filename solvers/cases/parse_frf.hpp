// The keys of [analysis] for type = "frf" (see cases/README.md, "Linear forced response").
#pragma once
#include <filesystem>

#include "analysis/frf_spec.hpp"
#include "cases/toml_reader.hpp"

namespace bb {

// Reads the frf keys of `r` (the caller reads `type` and finishes `r`). Throws InputError.
FrfSpec parse_frf(TomlReader& r, const std::filesystem::path& folder);

}  // namespace bb
