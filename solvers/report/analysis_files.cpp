#include "report/analysis_files.hpp"

#include "reduction/reduced_model_io.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

void write_sidecar(const ReducedModel& model, const std::string& name, const fs::path& out, RunRecord& run) {
  const fs::path sidecar = out / "reduced_models" / (name + ".toml");
  fs::create_directories(sidecar.parent_path());
  write_reduced_model(model, sidecar);
  run.tables.push_back("reduced_models/" + name + ".toml");
}

void files(const HbmSpec& spec, const HbmOutcome& hbm, const fs::path& out, RunRecord& run) {
  if (!spec.model.masters.empty() && !spec.cyclic) write_sidecar(hbm.prepared.linear, spec.model.name, out, run);
}

void files(const FrfSpec&, const FrfOutcome& frf, const fs::path& out, RunRecord& run) {
  for (const RomOutcome& r : frf.roms)
    if (r.model.recovery.size() != 0) write_sidecar(r.model, r.name, out, run);  // read from a file: nothing new
}

// The other analyses build no reduced model.
void files(const StaticSpec&, const StaticOutcome&, const fs::path&, RunRecord&) {}
void files(const ModalSpec&, const ModalOutcome&, const fs::path&, RunRecord&) {}
void files(const TimeSpec&, const TimeOutcome&, const fs::path&, RunRecord&) {}
void files(const ContactLoopSpec&, const ContactLoopOutcome&, const fs::path&, RunRecord&) {}
void files(const RotatingSpec&, const RotatingOutcome&, const fs::path&, RunRecord&) {}
void files(const ContactModalSpec&, const ContactModalOutcome&, const fs::path&, RunRecord&) {}
void files(const CyclicModalSpec&, const CyclicModalOutcome&, const fs::path&, RunRecord&) {}
void files(const NonlinearModalSpec&, const NonlinearModalOutcome&, const fs::path&, RunRecord&) {}

}  // namespace

void write_analysis_files(const AnalysisSpec& spec, const AnalysisResults& results, const fs::path& out,
                          RunRecord& run) {
  visit_analysis(spec, results, [&](const auto& s, const auto& outcome) { files(s, outcome, out, run); });
}

}  // namespace bb
