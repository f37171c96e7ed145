// The keys of [analysis] for type = "rotating" (see cases/README.md, "Rotating blade").
#pragma once
#include "analysis/rotating_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Reads the rotating keys of `r` and its [analysis.axis] and [analysis.campbell] tables (the caller
// reads `type` and finishes `r`). Throws InputError naming the key.
RotatingSpec parse_rotating(TomlReader& r);

}  // namespace bb
