#include "cases/parse_stepped_sine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "cases/parse_frf.hpp"
#include "cases/read_measured_file.hpp"
#include "common/constants.hpp"
#include "common/stepped_order.hpp"
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

// frequency_hz: the list as stepped, or with step_hz [first, last] on a grid (down when first > last).
std::vector<double> stepped_frequencies(TomlReader& r) {
  std::vector<double> f = r.number_array("frequency_hz");
  if (r.has("step_hz")) {
    const double step = r.positive("step_hz");
    if (f.size() != 2) r.fail("frequency_hz", "with step_hz give [first, last] (last < first steps down)");
    if (!(f[0] > 0.0) || !(f[1] > 0.0) || f[0] == f[1])
      r.fail("frequency_hz", "needs two different positive frequencies [Hz]");
    const double span = std::abs(f[1] - f[0]);
    if (span / step > static_cast<double>(kMaxPoints)) r.fail("step_hz", fmt::format("more than {} steps", kMaxPoints));
    const auto n = static_cast<size_t>(std::floor(span / step + 1e-9));
    const double dir = f[1] > f[0] ? 1.0 : -1.0, first = f[0], last = f[1];
    f.clear();
    for (size_t i = 0; i <= n; ++i) f.push_back(first + dir * static_cast<double>(i) * step);
    if (std::abs(f.back() - last) > 1e-9 * last) f.push_back(last);
    return f;
  }
  if (f.empty()) r.fail("frequency_hz", "needs at least one frequency [Hz]");
  if (f.size() > kMaxPoints) r.fail("frequency_hz", fmt::format("{} points; at most {}", f.size(), kMaxPoints));
  const std::optional<SteppedBreak> order = first_unstepped(f);
  for (size_t i = 0; i < f.size(); ++i) {
    if (!(f[i] > 0.0) || !std::isfinite(f[i]))
      r.fail("frequency_hz", fmt::format("every frequency must be positive [Hz], found {}", f[i]));
    if (order && i == order->index)
      r.fail("frequency_hz", fmt::format("frequency {} Hz (entry {}) is not {} the one before ({} Hz): a stepped sine "
                                         "goes one way, up or down, without repeating a frequency",
                                         f[i], i + 1, order->down ? "below" : "above", f[i - 1]));
  }
  return f;
}

SteppedSineSpec parse_one(TomlReader& r, const toml::table& t, const std::filesystem::path& folder) {
  SteppedSineSpec s;
  s.at = r.location();
  s.name = r.string("name");
  if (!valid_name(s.name))
    r.fail("name", fmt::format("'{}': use letters, digits, '_', '.' and '-' (it names the table frf_<name>)", s.name));
  if (r.has("file") == r.has("frequency_hz"))
    r.fail(r.has("file") ? "frequency_hz" : "file",
           "give either file (a measured frf file, with a force column or force) or frequency_hz with force");
  if (r.has("file")) {
    const std::filesystem::path file = r.input_file("file", folder);
    const MeasuredData data = read_measured_file(r, file, DataKind::frf, false).data;
    const Eigen::VectorXd& f = data.column("frequency");
    s.frequency_hz.assign(f.data(), f.data() + f.size());
    s.file = file.string();
    // A rig that held one force writes none per point: the case states it.
    if (data.has("force")) {
      if (r.has("force"))
        r.fail("force",
               fmt::format("{} gives the force of each point: leave out force (or the file's column)", file.string()));
      const Eigen::VectorXd& force = data.column("force");
      s.force.assign(force.data(), force.data() + force.size());
      return s;
    }
    if (!r.has("force"))
      r.fail("file", fmt::format("{} has no 'force [<unit>]' column: give the force the rig held, force = <N>, or "
                                 "a force per point in the file",
                                 file.string()));
    s.force.assign(s.frequency_hz.size(), r.positive("force"));
    return s;
  }
  s.frequency_hz = stepped_frequencies(r);
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
  return s;
}

const char* const kHeld[] = {"displacement", "velocity", "acceleration"};
const char* const kHeldUnit[] = {"m", "m/s", "m/s^2"};

// The curve of a response control read from a measured frf file: its frequencies as stepped, its
// level the median of its amplitude column in the column's own quantity (displacement, velocity
// or acceleration: the file's unit says which), every point within level_tolerance of it (a rig
// holds one level per curve); a held amplitude also given in the case must be that level.
void control_from_file(TomlReader& r, const std::filesystem::path& folder, ResponseControlSpec& s) {
  if (r.has("frequency_hz"))
    r.fail("frequency_hz", "give either file (a measured response-controlled curve) or frequency_hz");
  const std::filesystem::path file = r.input_file("file", folder);
  const MeasuredData data = read_measured_file(r, file, DataKind::frf).data;
  if (!data.has("amplitude"))
    r.fail("file", fmt::format("{} has no amplitude column: a response-controlled curve's level is the median of its "
                               "amplitudes",
                               file.string()));
  const double tolerance = r.has("level_tolerance") ? r.positive("level_tolerance") : 0.05;
  if (!(tolerance < 1.0)) r.fail("level_tolerance", fmt::format("must lie in (0, 1), found {}", tolerance));
  const int k = data.derivative;
  const Eigen::VectorXd& f = data.column("frequency");
  std::vector<double> level(static_cast<size_t>(f.size()));
  for (Eigen::Index i = 0; i < f.size(); ++i)  // back to the quantity the rig held (the reader made it a displacement)
    level[static_cast<size_t>(i)] = data.column("amplitude")[i] * std::pow(kTwoPi * f[i], k);
  std::vector<double> sorted = level;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  size_t worst = 0;
  for (size_t i = 0; i < level.size(); ++i)
    if (std::abs(level[i] / median - 1.0) > std::abs(level[worst] / median - 1.0)) worst = i;
  if (std::abs(level[worst] / median - 1.0) > tolerance)
    r.fail("file", fmt::format("{}: amplitude {:.6g} {} lies {:+.1f} % from the curve's level {:.6g} {} (the median "
                               "of its amplitude column), beyond level_tolerance = {:g}: a response-controlled curve "
                               "holds one level",
                               data.where(static_cast<Eigen::Index>(worst)), level[worst], kHeldUnit[k],
                               100.0 * (level[worst] / median - 1.0), median, kHeldUnit[k], tolerance));
  for (int q = 0; q < 3; ++q) {
    if (!r.has(kHeld[q])) continue;
    if (q != k)
      r.fail(kHeld[q], fmt::format("{} holds its amplitude as a {} ({}): give that, or no held amplitude (the "
                                   "file's median is the level)",
                                   file.string(), kHeld[k], data.units.at("amplitude").symbol));
    const double given = r.positive(kHeld[q]);
    if (std::abs(given / median - 1.0) > tolerance)
      r.fail(kHeld[q], fmt::format("{:g} {} but {} holds its amplitude at {:.6g} {} (the median of its amplitude "
                                   "column), beyond level_tolerance = {:g}",
                                   given, kHeldUnit[k], file.string(), median, kHeldUnit[k], tolerance));
  }
  s.derivative = k;
  s.amplitude = median;
  s.frequency_hz.assign(f.data(), f.data() + f.size());
  s.file = file.string();
  const auto [lo, hi] = std::minmax_element(level.begin(), level.end());
  s.spread_low = *lo / median - 1.0;
  s.spread_high = *hi / median - 1.0;
}

ResponseControlSpec parse_control(TomlReader& r, const std::vector<PointDof>& responses,
                                  const std::filesystem::path& folder) {
  ResponseControlSpec s;
  s.at = r.location();
  s.name = r.string("name");
  if (!valid_name(s.name))
    r.fail("name", fmt::format("'{}': use letters, digits, '_', '.' and '-' (it names the table frf_<name>)", s.name));
  const PointDof dof = parse_point_dof(r, "dof", r.string("dof"));
  const auto held =
      std::find_if(responses.begin(), responses.end(), [&](const PointDof& p) { return p.name() == dof.name(); });
  if (held == responses.end())
    r.fail("dof",
           fmt::format("'{}' must be one of analysis.responses (the held response is written with them)", dof.name()));
  s.response = static_cast<size_t>(held - responses.begin());
  if (r.has("file")) {
    control_from_file(r, folder, s);
    return s;
  }
  if (r.has("level_tolerance")) r.fail("level_tolerance", "applies only with file (the level read from the data)");
  const char* const* kinds = kHeld;
  int given = 0;
  for (int k = 0; k < 3; ++k)
    if (r.has(kinds[k])) ++given, s.derivative = k;
  if (given != 1)
    r.fail("displacement", "give exactly one held amplitude: displacement [m], velocity [m/s] or acceleration [m/s^2]");
  s.amplitude = r.number(kinds[s.derivative]);
  if (!(s.amplitude > 0.0) || !std::isfinite(s.amplitude))
    r.fail(kinds[s.derivative], fmt::format("the held amplitude must be positive, found {}", s.amplitude));
  s.frequency_hz = stepped_frequencies(r);
  return s;
}

// Every [[analysis.<key>]] table read by `parse`; each writes the table frf_<name>, which a force
// level or another stepped sine must not write already (`tables`, updated).
template <class Spec, class Parse>
std::vector<Spec> parse_blocks(TomlReader& r, const std::string& key, const char* what, std::set<std::string>& tables,
                               const Parse& parse) {
  std::vector<Spec> out;
  if (!r.has(key)) return out;
  int i = 0;
  for (const toml::node& n : r.array(key)) {
    if (!n.is_table()) r.fail(key, fmt::format("write each {} as an [[analysis.{}]] table", what, key));
    TomlReader s(*n.as_table(), fmt::format("{}.{}[{}]", r.path(), key, i++), r.file());
    out.push_back(parse(s, *n.as_table()));
    s.finish();
    const std::string table = "frf_" + out.back().name;
    if (!tables.insert(table).second)
      s.fail("name", fmt::format("table '{}' is already written by a force level or another stepped sine", table));
  }
  return out;
}

}  // namespace

std::vector<ResponseControlSpec> parse_response_controls(TomlReader& r, const std::vector<PointDof>& responses,
                                                         const std::filesystem::path& folder,
                                                         std::set<std::string>& tables) {
  return parse_blocks<ResponseControlSpec>(
      r, "response_control", "response control", tables,
      [&](TomlReader& s, const toml::table&) { return parse_control(s, responses, folder); });
}

std::vector<SteppedSineSpec> parse_stepped_sines(TomlReader& r, const std::filesystem::path& folder,
                                                 std::set<std::string>& tables) {
  return parse_blocks<SteppedSineSpec>(r, "stepped_sine", "stepped sine", tables,
                                       [&](TomlReader& s, const toml::table& t) { return parse_one(s, t, folder); });
}

}  // namespace bb
