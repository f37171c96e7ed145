// The keys of [analysis] for type = "contact_loop" (see cases/README.md, "Friction-contact test rig").
#pragma once
#include "analysis/contact_loop_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Reads the contact_loop keys of `r` and its [analysis.contact] table (finished here); the caller
// reads `type` and finishes `r`.
ContactLoopSpec parse_contact_loop(TomlReader& r);

}  // namespace bb
