// The [study] section of a case file (see cases/README.md, "Studies").
#pragma once
#include "analysis/analysis_spec.hpp"
#include "common/toml_reader.hpp"
#include "model/model_spec.hpp"
#include "study/study_spec.hpp"

namespace bb {

// Reads [study] of the case's top table; its kind must suit the mesh and the analysis. Throws InputError.
StudySpec parse_study(TomlReader& top, const ModelSpec& model, const AnalysisSpec& analysis);

}  // namespace bb
