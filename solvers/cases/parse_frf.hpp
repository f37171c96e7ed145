// The keys of [analysis] for type = "frf" (see cases/README.md, "Linear forced response").
#pragma once
#include <filesystem>

#include "analysis/frf_spec.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// Pieces shared with the nonlinear forced response (cases/parse_hbm.hpp). Each throws InputError.
PointDof parse_point_dof(TomlReader& r, const std::string& key, const std::string& text);  // "T2.x"
std::vector<PointDof> parse_responses(TomlReader& r);                                      // key "responses"
std::vector<FrfForce> parse_forces(TomlReader& r);
// { "A.x" = 1.0, "B.x" = -1.0 }: DOFs and finite nonzero coefficients, at least one.
std::vector<std::pair<PointDof, double>> parse_combination(TomlReader& r, const std::string& key);  // key "forces"
FrfDamping parse_damping(TomlReader& r);                                               // "modal_damping" or "rayleigh"
Eigen::MatrixXd parse_square_matrix(TomlReader& r, const std::string& key, size_t n);  // n rows of n finite numbers
RomSpec parse_rom(TomlReader& r, const std::filesystem::path& folder);  // one [[analysis.rom]] table, finished

// Reads the frf keys of `r` (the caller reads `type` and finishes `r`). Throws InputError.
FrfSpec parse_frf(TomlReader& r, const std::filesystem::path& folder);

}  // namespace bb
