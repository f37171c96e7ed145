#include "report/gnuplot.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace bb {
namespace {

namespace fs = std::filesystem;

const char* kTerminal = "set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'\n";

// A word for sh -c: single-quoted, a quote inside written '\''. The report folder comes from
// --out, which may hold any character.
std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

const char* series_colour(size_t i) {
  static constexpr const char* kPalette[] = {"#1f5fbf", "#bf1f1f", "#2f9f2f", "#9f2fbf",
                                             "#bf8f1f", "#1f9fbf", "#7f7f7f", "#000000"};
  return kPalette[i % 8];
}

std::string gnuplot_quote(const std::string& s) {
  std::string out;
  // Doubled quotes inside '...'; a line break would end the string and start a gnuplot command.
  for (char c : s)
    out += c == '\''                                           ? std::string("''")
           : static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? std::string(" ")
                                                               : std::string(1, c);
  return out;
}

// Runs gnuplot on `script`; returns the plot or the reason it was not drawn.
Plot draw(const fs::path& out_dir, const std::string& stem, const std::string& title, const std::string& script) {
  const fs::path dir = out_dir / "plots";
  fs::create_directories(dir);
  const fs::path gp = dir / (stem + ".gp");
  {
    std::ofstream out(gp);
    out << kTerminal << fmt::format("set output '{}.svg'\n", gnuplot_quote(stem)) << script;
  }
  const std::string cmd = fmt::format("cd {} && gnuplot {} > {} 2>&1", shell_quote(dir.string()),
                                      shell_quote(stem + ".gp"), shell_quote(stem + ".log"));
  const int rc = std::system(cmd.c_str());
  if (rc != 0 || !fs::exists(dir / (stem + ".svg"))) {
    return {title, "", fmt::format("gnuplot failed or is not installed; see plots/{}.log", stem), stem};
  }
  fs::remove(dir / (stem + ".log"));
  return {title, fmt::format("plots/{}.svg", stem), "", stem};
}

std::ofstream open_plot_data(const fs::path& out_dir, const std::string& stem) {
  fs::create_directories(out_dir / "plots");
  std::ofstream out(out_dir / "plots" / (stem + ".dat"));
  out.precision(12);
  return out;
}

}  // namespace bb
