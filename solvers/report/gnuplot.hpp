// Running gnuplot: each figure's data (.dat) and script (.gp) are kept next to its SVG under
// plots/, so it can be redrawn or restyled by hand.
#pragma once
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>

#include "report/run_record.hpp"

namespace bb {

// '' for every ' so that `s` fits inside a single-quoted gnuplot string.
std::string gnuplot_quote(const std::string& s);

// out_dir/plots/<stem>.dat, opened for writing with 12 significant digits.
std::ofstream open_plot_data(const std::filesystem::path& out_dir, const std::string& stem);

// The colour of the i-th series of a plot, cycling through one palette of 8 shared by every plot.
const char* series_colour(size_t i);

// Writes out_dir/plots/<stem>.gp (SVG terminal + `script`) and runs gnuplot on it; the plot, or
// the reason it was not drawn.
Plot draw(const std::filesystem::path& out_dir, const std::string& stem, const std::string& title,
          const std::string& script);

}  // namespace bb
