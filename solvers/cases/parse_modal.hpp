// The keys of [analysis] for type = "modal" (see cases/README.md, "Modal analysis"), and the
// [analysis.pairs] table that labels modes (modal and frf).
#pragma once
#include "analysis/modal_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Reads the modal keys of `r` (the caller reads `type` and finishes `r`). Throws InputError.
ModalSpec parse_modal(TomlReader& r);

// [analysis.pairs] when `r` has it, finished here.
std::optional<ModePairSpec> parse_mode_pairs(TomlReader& r);

}  // namespace bb
