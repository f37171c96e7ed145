#include "cases/parse_stepped_sine.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "forced/hbm_level.hpp"
#include "identify/measured_data.hpp"

namespace bb {
namespace {

constexpr size_t kMaxPoints = 100000;

bool valid_name(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') return false;
  return true;
}

SteppedSineSpec parse_one(TomlReader& r, const toml::table& t, const std::filesystem::path& folder) {
  SteppedSineSpec s;
  s.at = r.location();
  s.name = r.string("name");
  if (!valid_name(s.name))
    r.fail("name", fmt::format("'{}': use letters, digits, '_', '.' and '-' (it names the table frf_<name>)", s.name));
  if (r.has("file") == r.has("frequency_hz"))
    r.fail(r.has("file") ? "frequency_hz" : "file",
           "give either file (a measured frf file with a force column) or frequency_hz with force");
  if (r.has("file")) {
    const std::filesystem::path file = r.input_file("file", folder);
    const MeasuredData data = read_measured_data(file, DataKind::frf);
    if (!data.has("force"))
      r.fail("file", fmt::format("{} has no 'force [<unit>]' column: a stepped sine needs the force of each point",
                                 file.string()));
    const Eigen::VectorXd& f = data.column("frequency");
    const Eigen::VectorXd& force = data.column("force");
    s.frequency_hz.assign(f.data(), f.data() + f.size());
    s.force.assign(force.data(), force.data() + force.size());
    s.file = file.string();
    return s;
  }
  s.frequency_hz = r.number_array("frequency_hz");
  if (s.frequency_hz.empty()) r.fail("frequency_hz", "needs at least one frequency [Hz]");
  if (s.frequency_hz.size() > kMaxPoints)
    r.fail("frequency_hz", fmt::format("{} points; at most {}", s.frequency_hz.size(), kMaxPoints));
  if (const toml::node* force = t.get("force"); !force || !force->is_array()) {
    s.force.assign(s.frequency_hz.size(), r.number("force"));
  } else {
    s.force = r.number_array("force");
    if (s.force.size() != s.frequency_hz.size())
      r.fail("force", fmt::format("{} forces for {} frequencies: give one per frequency, or one number for all",
                                  s.force.size(), s.frequency_hz.size()));
  }
  for (double f : s.force)
    if (!(f > 0.0) || !std::isfinite(f)) r.fail("force", fmt::format("every force must be positive [N], found {}", f));
  const std::vector<double>& f = s.frequency_hz;
  const bool down = f.size() > 1 && f[1] < f[0];
  for (size_t i = 0; i < f.size(); ++i) {
    if (!(f[i] > 0.0) || !std::isfinite(f[i]))
      r.fail("frequency_hz", fmt::format("every frequency must be positive [Hz], found {}", f[i]));
    if (i > 0 && (down ? !(f[i] < f[i - 1]) : !(f[i] > f[i - 1])))
      r.fail("frequency_hz", fmt::format("frequency {} Hz (entry {}) is not {} the one before ({} Hz): a stepped sine "
                                         "goes one way, up or down, without repeating a frequency",
                                         f[i], i + 1, down ? "below" : "above", f[i - 1]));
  }
  return s;
}

}  // namespace

std::vector<SteppedSineSpec> parse_stepped_sines(TomlReader& r, const std::filesystem::path& folder,
                                                 const std::vector<double>& force_levels) {
  std::vector<SteppedSineSpec> out;
  if (!r.has("stepped_sine")) return out;
  std::set<std::string> tables;
  for (double f : force_levels) tables.insert(hbm_frf_table_name(f));
  int i = 0;
  for (const toml::node& n : r.array("stepped_sine")) {
    if (!n.is_table()) r.fail("stepped_sine", "write each stepped sine as an [[analysis.stepped_sine]] table");
    TomlReader s(*n.as_table(), fmt::format("{}.stepped_sine[{}]", r.path(), i++), r.file());
    out.push_back(parse_one(s, *n.as_table(), folder));
    s.finish();
    const std::string table = "frf_" + out.back().name;
    if (!tables.insert(table).second)
      s.fail("name", fmt::format("table '{}' is already written by a force level or another stepped sine", table));
  }
  return out;
}

}  // namespace bb
