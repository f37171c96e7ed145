// Plot of the friction-contact test rig (analysis type "contact_loop"): the steady hysteresis loop,
// tangential force against relative tangential displacement, its samples marked by contact state.
#pragma once
#include <filesystem>
#include <string>

#include "analysis/contact_loop_analysis.hpp"
#include "report/run_record.hpp"

namespace bb {

Plot plot_contact_loop(const ContactLoopOutcome& loop, const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
