// Figures of a cyclic modal analysis: the nodal-diameter map (frequency of each family against
// the nodal diameter) with the engine-order excitations at the top speed, and a family's wave on
// the sector.
#pragma once
#include <filesystem>
#include <string>

#include "analysis/cyclic_modal_analysis.hpp"
#include "report/run_record.hpp"

namespace bb {

Plot plot_nodal_diameter_map(const CyclicModalOutcome& o, const CyclicModalSpec& spec,
                             const std::filesystem::path& out_dir, const std::string& stem);

// Frequency against speed of the families of the nodal diameters the engine orders excite (all
// nodal diameters without engine orders), the engine-order lines and their crossings.
Plot plot_cyclic_campbell(const CyclicModalOutcome& o, const CyclicModalSpec& spec,
                          const std::filesystem::path& out_dir, const std::string& stem);

// The cosine part of family `family` (1-based) of the outcome's diameters[index] on the sector.
Plot plot_sector_wave(const CyclicModalOutcome& o, const Mesh& mesh, size_t index, int family,
                      const std::filesystem::path& out_dir, const std::string& stem);

}  // namespace bb
