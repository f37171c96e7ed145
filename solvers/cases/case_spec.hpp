// A case file parsed into plain, validated structs (parse once, at the edge). Every part is the
// spec of the layer that consumes it; this layer only assembles and parses them, and nothing below
// it includes it.
#pragma once
#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/analysis_spec.hpp"
#include "checks/check_spec.hpp"
#include "common/source_location.hpp"
#include "model/model_spec.hpp"
#include "study/fidelity_spec.hpp"
#include "study/study_spec.hpp"

namespace bb {

struct CaseSpec {
  std::filesystem::path file;
  std::string name;
  std::string title;
  std::string description;
  // The plots a report shows under its verdict, by name (the SVG's stem); empty: the first plot.
  std::vector<std::string> key_plots;
  SourceLocation key_plots_at;
  bool vtk = false;                  // ParaView files of the run's fields (report/vtk_files.hpp)
  std::filesystem::path model_from;  // the case whose material, mesh, sets and constraints these are
  ModelSpec model;
  AnalysisSpec analysis;
  std::vector<CheckSpec> checks;
  std::optional<StudySpec> study;
  std::optional<FidelitySpec> fidelity;  // what `run --fidelity` may vary, and the accuracy it must meet
};

// Throws InputError naming file, line and key for every malformed or missing entry.
CaseSpec parse_case_file(const std::filesystem::path& file);

// The same in two steps, so that a caller can keep the table (e.g. to write a calibrated copy);
// `file` locates relative paths and names the source in messages.
toml::table read_case_table(const std::filesystem::path& file);
CaseSpec parse_case_table(const toml::table& root, const std::filesystem::path& file);

}  // namespace bb
