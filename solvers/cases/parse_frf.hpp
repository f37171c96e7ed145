// The keys of [analysis] for type = "frf" (see cases/README.md, "Linear forced response").
#pragma once
#include <filesystem>

#include "analysis/frf_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Pieces shared with the nonlinear forced response (cases/parse_hbm.hpp). Each throws InputError.
PointDof parse_point_dof(TomlReader& r, const std::string& key, const std::string& text);  // "T2.x"
std::vector<PointDof> parse_responses(TomlReader& r);                                      // key "responses"
std::vector<FrfForce> parse_forces(TomlReader& r);                                         // key "forces"
FrfDamping parse_damping(TomlReader& r);                                               // "modal_damping" or "rayleigh"
Eigen::MatrixXd parse_square_matrix(TomlReader& r, const std::string& key, size_t n);  // n rows of n finite numbers
RomSpec parse_rom(TomlReader& r, const std::filesystem::path& folder);  // one [[analysis.rom]] table, finished

// Reads the frf keys of `r` (the caller reads `type` and finishes `r`). Throws InputError.
FrfSpec parse_frf(TomlReader& r, const std::filesystem::path& folder);

}  // namespace bb
