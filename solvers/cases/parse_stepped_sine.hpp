// [[analysis.stepped_sine]] and [[analysis.response_control]] of an hbm analysis: stepped sines at
// the force of each point (written in the case or read from a measured FRF file's frequency and
// force columns), and at a held response amplitude (cases/README.md).
#pragma once
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "common/toml_reader.hpp"
#include "forced/hbm_spec.hpp"

namespace bb {

// Reads every [[analysis.stepped_sine]] of `r` (relative files from `folder`). Throws InputError
// with file:line:key for a missing or repeated name, a table name already in `tables` (each new
// one is added), both or neither of `file` and `frequency_hz`, frequencies that are not one
// monotonic sweep, non-positive forces, or a data file without a force column.
std::vector<SteppedSineSpec> parse_stepped_sines(TomlReader& r, const std::filesystem::path& folder,
                                                 std::set<std::string>& tables);

// Reads every [[analysis.response_control]]: name, dof (one of `responses`), exactly one of
// displacement [m], velocity [m/s] or acceleration [m/s^2] (> 0), frequency_hz (a list, or
// [first, last] with step_hz). Same refusals for names and frequencies. Or `file` (relative to
// `folder`), a measured response-controlled curve: its frequencies, and its level the median of
// its amplitude column, refused when a point lies beyond `level_tolerance` (default 0.05) of it
// or a held amplitude also given is another quantity or another level.
std::vector<ResponseControlSpec> parse_response_controls(TomlReader& r, const std::vector<PointDof>& responses,
                                                         const std::filesystem::path& folder,
                                                         std::set<std::string>& tables);

}  // namespace bb
