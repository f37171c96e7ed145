// The keys of [analysis] for type = "contact_modal" (see cases/README.md, "Contact and modes").
#pragma once
#include "analysis/contact_modal_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Throws InputError naming the key (the caller reads `type` and finishes `r`).
ContactModalSpec parse_contact_modal(TomlReader& r);

}  // namespace bb
