// [[analysis.stepped_sine]] of an hbm analysis: stepped sines at the force of each point, written
// in the case or read from a measured FRF file's frequency and force columns (cases/README.md).
#pragma once
#include <filesystem>
#include <vector>

#include "common/toml_reader.hpp"
#include "forced/hbm_spec.hpp"

namespace bb {

// Reads every [[analysis.stepped_sine]] of `r` (relative files from `folder`). Throws InputError
// with file:line:key for a missing or repeated name, a table name a force level already writes,
// both or neither of `file` and `frequency_hz`, frequencies that are not one monotonic sweep,
// non-positive forces, or a data file without a force column.
std::vector<SteppedSineSpec> parse_stepped_sines(TomlReader& r, const std::filesystem::path& folder,
                                                 const std::vector<double>& force_levels);

}  // namespace bb
