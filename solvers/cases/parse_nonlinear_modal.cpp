#include "cases/parse_nonlinear_modal.hpp"

#include <fmt/format.h>

#include <set>

#include "cases/parse_frf.hpp"
#include "cases/parse_stepped_sine.hpp"
#include "cases/read_measured_file.hpp"

namespace bb {
namespace {

constexpr size_t kMaxKnots = 64;

// Knot amplitudes [m]: positive, strictly increasing, at most kMaxKnots.
std::vector<double> knot_amplitudes(TomlReader& b, const std::string& key) {
  const std::vector<double> amplitudes = b.number_array(key);
  if (amplitudes.empty() || amplitudes.size() > kMaxKnots)
    b.fail(key, fmt::format("give 1 to {} knot amplitudes [m], found {}", kMaxKnots, amplitudes.size()));
  for (size_t i = 0; i < amplitudes.size(); ++i) {
    if (!(amplitudes[i] > 0.0))
      b.fail(key, fmt::format("knot amplitudes must be positive [m], entry {} is {}", i + 1, amplitudes[i]));
    if (i > 0 && !(amplitudes[i] > amplitudes[i - 1]))
      b.fail(key, fmt::format("knot amplitudes must increase strictly: entry {} ({}) follows {}", i + 1, amplitudes[i],
                              amplitudes[i - 1]));
  }
  return amplitudes;
}

// One curve: its values at its own knots (<curve>_amplitude_m) or at the shared amplitude_m.
ModalBackbone backbone(TomlReader& b, const std::string& key) {
  const std::string own = key == "frequency_hz" ? "frequency_amplitude_m" : "damping_amplitude_m";
  if (b.has(own) == b.has("amplitude_m"))
    b.fail(b.has(own) ? own : "amplitude_m",
           fmt::format("give the knots of {} either in amplitude_m (shared) or in {}, not both", key, own));
  const std::string knots = b.has(own) ? own : "amplitude_m";
  const std::vector<double> amplitudes = knot_amplitudes(b, knots);
  const std::vector<double> values = b.number_array(key);
  if (values.size() != amplitudes.size())
    b.fail(key, fmt::format("{} values for {} amplitudes: give one per entry of {}", values.size(), amplitudes.size(),
                            knots));
  return ModalBackbone(amplitudes, values);
}

// The smallest value of the curve over its knots' span and a decade beyond (the constant ends):
// a spline through positive knots may still dip below zero between them.
void require_positive(TomlReader& b, const ModalBackbone& curve, const std::string& key, const char* what) {
  const auto& a = curve.amplitudes();
  const auto [lo, hi] = curve.range(a.front(), a.back(), 2000);
  (void)hi;
  if (!(lo > 0.0))
    b.fail(key, fmt::format("the {} must be positive at every amplitude; the spline through these knots reaches {:.6g} "
                            "between them (add a knot or move one)",
                            what, lo));
}

NonlinearMode parse_mode(TomlReader& r) {
  NonlinearMode mode;
  mode.mass = r.positive("mass");
  TomlReader b(r.table("backbone"), r.path() + ".backbone", r.file());
  mode.frequency_hz = backbone(b, "frequency_hz");
  mode.damping_ratio = backbone(b, "damping_ratio");
  require_positive(b, mode.frequency_hz, "frequency_hz", "natural frequency");
  require_positive(b, mode.damping_ratio, "damping_ratio", "damping ratio");
  b.finish();
  return mode;
}

constexpr size_t kMaxModes = 8;

// [[analysis.mode]]: a few uncoupled modes, each with its mass and backbone, in ascending order of
// their linear frequency (f at the smallest knot) so that mode k is the k-th resonance.
std::vector<NonlinearMode> parse_modes(TomlReader& r) {
  for (const char* single : {"mass", "backbone"})
    if (r.has(single))
      r.fail(single,
             "give the modes either as [[analysis.mode]] (each with its mass and backbone) or as one mode "
             "(mass and [analysis.backbone]), not both");
  const toml::array& list = r.array("mode");
  if (list.empty() || list.size() > kMaxModes || !list.is_array_of_tables())
    r.fail("mode",
           fmt::format("give 1 to {} modes as [[analysis.mode]] tables, each with mass and backbone", kMaxModes));
  std::vector<NonlinearMode> modes;
  for (size_t k = 0; k < list.size(); ++k) {
    TomlReader m(*list.get(k)->as_table(), fmt::format("{}.mode[{}]", r.path(), k), r.file());
    modes.push_back(parse_mode(m));
    m.finish();
    if (k > 0 && !(modes[k].frequency_hz.values().front() > modes[k - 1].frequency_hz.values().front()))
      m.fail("backbone",
             fmt::format("list the modes in ascending order of their linear frequency (f at the smallest knot): mode "
                         "{} has {} Hz, mode {} has {} Hz",
                         k, modes[k].frequency_hz.values().front(), k - 1, modes[k - 1].frequency_hz.values().front()));
  }
  return modes;
}

std::vector<BackboneCurve> parse_extract(TomlReader& r, const std::filesystem::path& folder) {
  std::vector<BackboneCurve> out;
  if (!r.has("extract")) return out;
  int i = 0;
  for (const toml::node& n : r.array("extract")) {
    if (!n.is_table()) r.fail("extract", "write each curve as an [[analysis.extract]] table with its file");
    TomlReader e(*n.as_table(), fmt::format("{}.extract[{}]", r.path(), i++), r.file());
    BackboneCurve c;
    c.at = e.location();
    const std::filesystem::path file = e.input_file("file", folder);
    const MeasuredData data = read_measured_file(e, file, DataKind::frf).data;
    if (!data.has("amplitude"))
      e.fail("file", fmt::format("{} has no amplitude column: a backbone point is read from the amplitudes a "
                                 "response-controlled curve held",
                                 file.string()));
    if (!data.has("force"))
      e.fail("file", fmt::format("{} has no 'force [<unit>]' column: a response-controlled curve gives the force that "
                                 "held the amplitude",
                                 file.string()));
    if (data.rows() < 5)
      e.fail("file", fmt::format("{} has {} points; a backbone point needs 5", file.string(), data.rows()));
    c.file = file.string();
    c.name = e.optional_label("name").value_or(file.stem().string());
    const auto copy = [&](const char* column) {
      const Eigen::VectorXd& v = data.column(column);
      return std::vector<double>(v.data(), v.data() + v.size());
    };
    c.frequency_hz = copy("frequency"), c.amplitude_m = copy("amplitude"), c.force_n = copy("force");
    e.finish();
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

NonlinearModalSpec parse_nonlinear_modal(TomlReader& r, const std::filesystem::path& folder) {
  NonlinearModalSpec s;
  s.at = r.location();
  const PointDof dof = parse_point_dof(r, "dof", r.string("dof"));
  s.dof = dof.name();
  s.mode_array = r.has("mode");
  s.modes = s.mode_array ? parse_modes(r) : std::vector<NonlinearMode>{parse_mode(r)};
  std::set<std::string> tables;
  s.stepped_sines = parse_stepped_sines(r, folder, tables);
  s.response_controls = parse_response_controls(r, {dof}, folder, tables);
  s.extract = parse_extract(r, folder);
  return s;
}

}  // namespace bb
