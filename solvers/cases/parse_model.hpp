// The model sections of a case file (see cases/README.md, "Model"): material, mesh, section,
// node sets, constraints and loads.
#pragma once
#include <filesystem>

#include "common/toml_reader.hpp"
#include "model/model_spec.hpp"

namespace bb {

// Reads [material], [mesh], [section], [sets], [[bc]] and [[load]] from the case's top table.
// `needs_mass`: rho must be > 0 (every analysis but a static one). Throws InputError.
ModelSpec parse_model(TomlReader& top, const std::filesystem::path& folder, bool needs_mass);

}  // namespace bb
