// Plots of a contact-modal analysis: each mode's frequency against the penalty factor, one line
// per interference (as the thesis's Figs 3.12-3.19), and the contact pressure of the state point.
#pragma once
#include <filesystem>
#include <string>

#include "analysis/contact_modal_analysis.hpp"
#include "analysis/contact_modal_spec.hpp"
#include "report/run_record.hpp"
#include "results/table.hpp"

namespace bb {

Plot plot_contact_mode(const ContactModalOutcome& o, const ContactModalSpec& spec, int mode,
                       const std::filesystem::path& out_dir, const std::string& stem);

// Pressure along x at every contact point of the state point (the run's contact_state table), one
// colour per pair.
Plot plot_contact_pressure(const ContactModalOutcome& o, const ResultTable& contact_state,
                           const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
