// The [fidelity] section of a case file (see cases/README.md, "Fidelity") and how one level of one
// of its axes is applied to the parsed case.
#pragma once
#include "common/toml_reader.hpp"
#include "study/fidelity_spec.hpp"

namespace bb {

struct CaseSpec;

// Reads [fidelity] of the case's top table; every axis must suit the case's analysis and mesh.
// Throws InputError naming file, line and key.
FidelitySpec parse_fidelity(TomlReader& top, const CaseSpec& spec);

// Sets `axis` to `level` in `spec` (mesh.refinement multiplies the case's own divisions).
void apply_fidelity_level(CaseSpec& spec, const FidelityAxisSpec& axis, double level);

}  // namespace bb
