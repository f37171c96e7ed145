// The keys of [analysis] for type = "cyclic_modal" (see cases/README.md, "Bladed disks").
#pragma once
#include "analysis/cyclic_modal_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Throws InputError naming the key (the caller reads `type` and finishes `r`).
CyclicModalSpec parse_cyclic_modal(TomlReader& r);

}  // namespace bb
