// The [calibration] section of a case file (see cases/README.md, "Calibration").
#pragma once
#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <string>

#include "cases/case_spec.hpp"
#include "identify/calibration_spec.hpp"

namespace bb {

// Reads [calibration] from a case file's table; std::nullopt when absent. Checks that every path
// names a parameter of the case (cases/case_parameter.hpp) inside its bounds, every fit check
// exists and every data file reads. Throws InputError.
std::optional<CalibrationSpec> parse_calibration(const toml::table& root, const std::filesystem::path& file,
                                                 const CaseSpec& spec);

// Before any solve: every check reference of the case (require_check_references), and of every case
// it reaches through its checks' reference_case and its [calibration] cross_check, each such case
// read as a run of it would read it (its data files included), so that a file missing, a folder, a
// link loop or a device there is bad input now, not after a solve or a fit. Throws InputError naming
// the chain of cases.
void require_linked_cases(const std::filesystem::path& file, const CaseSpec& spec,
                          const std::optional<CalibrationSpec>& calibration);

// The number at a dotted path ("a.b.c"; an integer segment indexes an array), or nullptr: for
// writing the calibrated copy of a case.
toml::node* node_at_path(toml::table& root, const std::string& path);

}  // namespace bb
