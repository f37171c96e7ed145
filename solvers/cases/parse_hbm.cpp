#include "cases/parse_hbm.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/hbm_analysis.hpp"
#include "cases/case_parameter.hpp"
#include "cases/parse_base_motion.hpp"
#include "cases/parse_frf.hpp"
#include "cases/parse_friction_law.hpp"
#include "cases/parse_stepped_sine.hpp"
#include "reduction/reduced_model.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// kn, kt, mu (and n0 when `preload`), checked by the contact law itself. kn may be 0 or left out
// (constant normal load) where `kn_optional`.
friction::PointParameters parse_law(TomlReader& r, bool preload, bool kn_optional = false) {
  friction::PointParameters law;
  law.kn = kn_optional ? r.non_negative("kn", 0.0) : r.positive("kn");
  law.kt = r.positive("kt");
  law.mu = r.non_negative("mu", 0.0);
  if (preload) law.n0 = r.non_negative("n0", 0.0);
  try {
    friction::validate(law);
  } catch (const std::invalid_argument& e) {
    r.fail("kn", e.what());
  }
  return law;
}

HbmContactSpec parse_contact(TomlReader r) {
  HbmContactSpec c;
  c.at = r.location();
  c.name = r.name("name");
  // An Iwan joint usually sits at a constant normal load (kn = 0); a Jenkins point needs its kn.
  const bool jenkins = r.optional_string("law").value_or("jenkins") == "jenkins";
  c.point = parse_law(r, true, !jenkins);
  const ContactLaw law = parse_contact_law(r, c.point, true);
  c.law = law.law;
  c.distribution = law.distribution;
  c.tangential = parse_combination(r, "tangential");
  if (c.law->directions() == 2) {
    if (!r.has("tangential_2"))
      r.fail("tangential_2",
             fmt::format("the {} law needs its second tangential direction, e.g. {{ \"A.z\" = 1.0 }}", c.law->name()));
    c.tangential_2 = parse_combination(r, "tangential_2");
  } else if (r.has("tangential_2")) {
    r.fail("tangential_2", fmt::format("only a law of two tangential directions (coupled_slip) takes one; this "
                                       "contact's law is {}",
                                       c.law->name()));
  }
  if (r.has("normal")) c.normal = parse_combination(r, "normal");
  if (r.has("tangential_next")) c.tangential_next = parse_combination(r, "tangential_next");
  if (r.has("normal_next")) c.normal_next = parse_combination(r, "normal_next");
  r.finish();
  return c;
}

std::array<double, 2> parse_xy(TomlReader& r, const std::string& key) {
  const std::vector<double> v = r.number_array(key);
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1])) r.fail(key, "expected [x, y] in metres");
  return {v[0], v[1]};
}

DamperSpec parse_damper(TomlReader r) {
  DamperSpec d;
  d.mass = r.positive("mass");
  d.inertia = r.positive("inertia");
  d.centre = parse_xy(r, "centre");
  d.left_face_deg = r.number("left_face_deg");
  d.right_face_deg = r.number("right_face_deg");
  for (const char* key : {"left_face_deg", "right_face_deg"}) {
    const double a = std::string(key) == "left_face_deg" ? d.left_face_deg : d.right_face_deg;
    if (!(a > 0.0 && a < 90.0)) r.fail(key, "must lie in (0, 90) degrees");
  }
  d.centrifugal_force = r.positive("centrifugal_force");
  d.point = parse_law(r, false);
  if (r.optional_string("law").value_or("") == "iwan")
    r.fail("law", "a damper point is one slider of its own law (jenkins or coupled_slip), not an Iwan distribution");
  d.law = parse_contact_law(r, d.point, true).law;
  int i = 0;
  std::set<std::string> names;
  for (const toml::node& n : r.array("points")) {
    if (!n.is_table()) r.fail("points", "write each point as { name = \"L1\", face = \"left\", point = \"L1\" }");
    TomlReader p(*n.as_table(), fmt::format("{}.points[{}]", r.path(), i++), r.file());
    DamperPointSpec s;
    s.name = p.name("name");
    if (!names.insert(s.name).second) p.fail("name", fmt::format("a damper point named '{}' exists already", s.name));
    s.left_face = p.choice("face", {"left", "right"}) == "left";
    s.point = p.optional_string("point").value_or("");
    if (p.has("position")) s.position = parse_xy(p, "position"), s.position_at = p.location("position");
    if (s.point.empty() && !s.position)
      p.fail("point", "give the blade point it touches ('point'), or a 'position' for a rigid platform");
    p.finish();
    d.points.push_back(s);
  }
  if (d.points.empty()) r.fail("points", "needs at least one contact point");
  r.finish();
  return d;
}

// The parameters hbm/sensitivity.hpp differentiates exactly (cases/case_parameter.hpp says which):
// rayleigh damping and a damping matrix do not scale with one case value.
std::vector<HbmParameter> parse_sensitivities(TomlReader& r, const HbmSpec& s) {
  std::vector<HbmParameter> out;
  const std::vector<std::string> paths = r.string_array("sensitivities");
  for (const std::string& path : paths) {
    const auto fail = [&](const std::string& why) { r.fail("sensitivities", fmt::format("'{}': {}", path, why)); };
    std::optional<HbmParameter> parameter;
    try {
      parameter = hbm_parameter(parse_parameter_path(path));
    } catch (const std::invalid_argument&) {
    }
    if (!parameter)
      fail(
          "not a supported path (analysis.contact.<i>.{kn,kt,mu,n0}, analysis.damper.{kt,mu}, "
          "analysis.modal_damping[.<mode>], analysis.model.{stiffness,mass}.<i>.<j>, "
          "analysis.model.{frequency_hz,modal_mass}.<i>)");
    if (const std::optional<std::string> why = unsupported_sensitivity(s, *parameter)) fail(*why);
    if (std::count(paths.begin(), paths.end(), path) > 1) fail("listed twice");
    out.push_back(*parameter);
  }
  return out;
}

}  // namespace

namespace {

NonlinearModesSpec parse_nonlinear_modes(TomlReader r, const HbmSpec& hbm) {
  NonlinearModesSpec s;
  s.at = r.location();
  for (long m : r.integer_array("linear_modes")) {
    if (m < 1 || m > 10000) r.fail("linear_modes", fmt::format("mode {}: modes count from 1", m));
    s.linear_modes.push_back(static_cast<int>(m));
  }
  if (s.linear_modes.empty()) r.fail("linear_modes", "name at least one mode of the stuck linearization");
  if (r.has("peaks")) {
    s.peaks = r.string_array("peaks");
    if (s.peaks.size() != s.linear_modes.size())
      r.fail("peaks", fmt::format("one peak kind per linear mode ({} modes, {} peak kinds)", s.linear_modes.size(),
                                  s.peaks.size()));
    const std::set<std::string> kinds = hbm.ip_oop ? std::set<std::string>{"ip", "oop"} : std::set<std::string>{"peak"};
    for (const std::string& k : s.peaks)
      if (!kinds.count(k))
        r.fail("peaks", fmt::format("'{}' is not a peak kind of this sweep ({})", k,
                                    hbm.ip_oop ? "\"ip\" or \"oop\" with ip_oop" : "\"peak\" without ip_oop"));
  }
  const std::vector<double> range = r.number_array("modal_amplitude");
  if (range.size() != 2 || !(range[0] > 0.0) || !(range[0] < range[1]) || !std::isfinite(range[1]))
    r.fail("modal_amplitude", "expected [a_min, a_max] with 0 < a_min < a_max [m kg^1/2]");
  s.amplitude_min = range[0];
  s.amplitude_max = range[1];
  if (const auto n = r.optional_integer("points")) {
    if (*n < 2 || *n > 10000) r.fail("points", "must lie in [2, 10000]");
    s.points = static_cast<int>(*n);
  }
  r.finish();
  return s;
}

}  // namespace

// [analysis.cyclic], and the next-sector terms of the contacts that need it.
void parse_cyclic(TomlReader& r, HbmSpec& s, bool harmonic_balance) {
  const toml::table* t = r.optional_table("cyclic");
  if (!t) {
    if (r.has("gap_damper")) r.fail("gap_damper", "a damper between two sectors needs [analysis.cyclic]");
    for (size_t i = 0; i < s.contacts.size(); ++i)
      if (!s.contacts[i].tangential_next.empty() || !s.contacts[i].normal_next.empty())
        r.fail("contact",
               fmt::format("contact '{}' names next-sector terms: they need [analysis.cyclic]", s.contacts[i].name));
    return;
  }
  TomlReader c(*t, r.path() + ".cyclic", r.file());
  if (!harmonic_balance)
    r.fail("cyclic", "a travelling wave of one sector is solved by the harmonic balance (type = \"hbm\") only");
  HbmCyclicSpec cyclic;
  cyclic.at = c.location();
  cyclic.sectors = static_cast<int>(c.integer("sectors", 2, 10000));
  cyclic.engine_order = static_cast<int>(c.integer("engine_order", 0, 1000000));
  cyclic.whole = c.boolean("whole", false);
  if (s.model.masters.empty()) {
    for (const char* key : {"left", "right", "face_tolerance"})
      if (c.has(key))
        c.fail(key, "names the cyclic faces of a mesh: it needs a Craig-Bampton model ('masters' in [analysis.model])");
  } else {
    cyclic.left = c.optional_string("left").value_or(cyclic.left);
    cyclic.right = c.optional_string("right").value_or(cyclic.right);
    cyclic.face_tolerance = c.optional_number("face_tolerance").value_or(cyclic.face_tolerance);
    if (!(cyclic.face_tolerance > 0.0)) c.fail("face_tolerance", "must be > 0 [m]");
  }
  c.finish();
  const char* refused = s.damper                                  ? "damper"
                        : !s.sensitivities.empty()                ? "sensitivities"
                        : s.nonlinear_modes                       ? "nonlinear_modes"
                        : s.stability != HbmSpec::Stability::none ? "stability"
                                                                  : nullptr;
  if (refused)
    r.fail(refused,
           "is not built for one sector of a cyclic structure (the travelling wave of [analysis.cyclic]); "
           "leave it out or model the whole structure");
  s.cyclic = cyclic;
  if (const toml::table* g = r.optional_table("gap_damper")) {
    TomlReader d(*g, r.path() + ".gap_damper", r.file());
    if (s.model.masters.empty())
      d.fail("mass",
             "a gap damper sits between the platforms of a meshed sector: it needs 'masters' in [analysis.model]");
    GapDamperSpec damper;
    damper.at = d.location();
    damper.mass = d.positive("mass");
    damper.own = d.string("own");
    damper.next = d.string("next");
    for (const std::string* point : {&damper.own, &damper.next})
      if (std::find(s.model.masters.begin(), s.model.masters.end(), *point) == s.model.masters.end())
        d.fail(point == &damper.own ? "own" : "next",
               fmt::format("'{}' is not one of the model's master points", *point));
    damper.centrifugal_force = d.positive("centrifugal_force");
    damper.face_angle_deg = d.number("face_angle_deg");
    if (!(damper.face_angle_deg > 0.0 && damper.face_angle_deg < 90.0))
      d.fail("face_angle_deg", "must lie in (0, 90) degrees: a flat face (0) leaves the damper's mean position free");
    damper.point = parse_law(d, false);
    damper.distribution = parse_slider_distribution(d, damper.point);
    d.finish();
    s.gap_damper = damper;
  }
}

// A law of two tangential directions runs in the harmonic balance's sweeps only: the time
// integration keeps one slider coordinate per contact, the sensitivities and the nonlinear modes
// are built for one direction, a cyclic contact for one.
void refuse_two_directions_beyond_sweeps(TomlReader& r, const HbmSpec& s, bool harmonic_balance) {
  bool two = s.damper && s.damper->law->directions() == 2;
  for (const HbmContactSpec& c : s.contacts) two = two || c.law->directions() == 2;
  if (!two) return;
  const char* refused = !harmonic_balance          ? "type"
                        : !s.sensitivities.empty() ? "sensitivities"
                        : s.nonlinear_modes        ? "nonlinear_modes"
                        : s.cyclic                 ? "cyclic"
                                                   : nullptr;
  if (refused)
    r.fail(refused,
           "a contact of two tangential directions (law = \"coupled_slip\") is solved by the harmonic balance's "
           "sweeps only (no time integration, sensitivities, nonlinear modes or cyclic sector)");
}

void check_levels(TomlReader& r, const std::string& key, const std::vector<double>& levels, const char* quantity,
                  const char* unit) {
  std::set<double> unique;
  std::map<std::string, double> tables;  // each level writes its own table: no two may share a name
  for (double f : levels) {
    if (!(f > 0) || !std::isfinite(f))
      r.fail(key, fmt::format("every level must be a positive {} [{}]", quantity, unit));
    if (!unique.insert(f).second) r.fail(key, fmt::format("level {} {} is listed twice", f, unit));
    if (const auto [it, fresh] = tables.emplace(hbm_frf_table_name(f), f); !fresh)
      r.fail(key, fmt::format("levels {} {} and {} {} would both write table '{}' (a level is named by its first 6 "
                              "significant digits): make them differ there",
                              it->second, unit, f, unit, it->first));
  }
}

HbmSpec parse_hbm(TomlReader& r, const fs::path& folder, bool contacts_required) {
  HbmSpec s;
  s.at = r.location();
  const std::vector<double> range = r.number_array("frequency_hz");
  if (range.size() != 2 || !(range[0] > 0.0) || !(range[0] < range[1]) || !std::isfinite(range[1]))
    r.fail("frequency_hz", "expected [f_min, f_max] with 0 < f_min < f_max");
  s.sweep.f_min = range[0];
  s.sweep.f_max = range[1];
  const toml::table& model = r.table("model");
  if (!model.contains("damping")) s.damping = parse_damping(r);
  const long h = r.optional_integer("harmonics").value_or(1);
  if (h < 1 || h > 50) r.fail("harmonics", "must lie in [1, 50]");
  s.harmonics = static_cast<int>(h);
  const long samples = r.optional_integer("time_samples").value_or(0);
  if (samples != 0 && (samples < 2 * h + 1 || samples > 100000))
    r.fail("time_samples", fmt::format("must be 0 (automatic) or lie in [{}, 100000] (at least 2H + 1)", 2 * h + 1));
  s.time_samples = static_cast<int>(samples);
  if (r.has("aft")) s.aft_events = r.choice("aft", {"samples", "events"}) == "events";
  if (r.has("aft_tolerance")) {
    s.aft_tolerance = r.positive("aft_tolerance");
    if (s.aft_tolerance >= 1.0) r.fail("aft_tolerance", "must be below 1 (a relative contact-force error)");
  }
  if (const auto most = r.optional_integer("max_time_samples")) {
    if (!r.has("aft_tolerance")) r.fail("max_time_samples", "applies only with aft_tolerance (samples raised)");
    const long start = samples > 0 ? samples : 2 * h + 1;
    if (*most < start || *most > 100000)
      r.fail("max_time_samples", fmt::format("must lie in [{}, 100000] (at least time_samples and 2H + 1)", start));
    s.max_time_samples = static_cast<int>(*most);
  }
  if (r.has("harmonic_tolerance")) {
    s.harmonic_tolerance = r.positive("harmonic_tolerance");
    if (s.harmonic_tolerance >= 1.0)
      r.fail("harmonic_tolerance", "must be below 1 (a share of the motion relative to the solution's)");
  }
  if (const auto most = r.optional_integer("max_harmonics")) {
    if (!r.has("harmonic_tolerance")) r.fail("max_harmonics", "applies only with harmonic_tolerance (H raised)");
    if (*most < h || *most > 50)
      r.fail("max_harmonics", fmt::format("must lie in [{}, 50] (at least harmonics = {})", h, h));
    s.max_harmonics = static_cast<int>(*most);
  } else if (s.harmonic_tolerance > 0.0) {
    s.max_harmonics = std::max(s.max_harmonics, s.harmonics);
  }
  if (r.has("harmonic_scope")) {
    if (!r.has("harmonic_tolerance")) r.fail("harmonic_scope", "applies only with harmonic_tolerance (H raised)");
    const std::string scope = r.choice("harmonic_scope", {"path", "peaks", "point"});
    s.harmonic_scope = scope == "peaks"   ? HbmSpec::HarmonicScope::peaks
                       : scope == "point" ? HbmSpec::HarmonicScope::point
                                          : HbmSpec::HarmonicScope::path;
  }
  if (r.has("harmonic_criterion")) {
    if (!r.has("harmonic_tolerance")) r.fail("harmonic_criterion", "applies only with harmonic_tolerance (H raised)");
    s.harmonic_criterion = r.choice("harmonic_criterion", {"share", "change"}) == "change"
                               ? HbmSpec::HarmonicCriterion::change
                               : HbmSpec::HarmonicCriterion::share;
  }
  if (const auto step = r.optional_integer("harmonic_step")) {
    if (!r.has("harmonic_tolerance")) r.fail("harmonic_step", "applies only with harmonic_tolerance (H raised)");
    if (*step < 1 || *step > 10) r.fail("harmonic_step", "must lie in [1, 10]");
    s.harmonic_step = static_cast<int>(*step);
  }
  if (s.harmonic_scope == HbmSpec::HarmonicScope::point && s.harmonic_criterion != HbmSpec::HarmonicCriterion::change)
    r.fail("harmonic_scope",
           "harmonic_scope = \"point\" compares two H at each frequency: it needs harmonic_criterion = \"change\"");
  if (s.harmonic_criterion == HbmSpec::HarmonicCriterion::change && s.max_harmonics < s.harmonics + s.harmonic_step)
    r.fail(
        r.has("max_harmonics") ? "max_harmonics" : "harmonic_criterion",
        fmt::format("harmonic_criterion = \"change\" compares two H: max_harmonics = {} must be at least harmonics + "
                    "harmonic_step = {}",
                    s.max_harmonics, s.harmonics + s.harmonic_step));
  if (s.harmonic_tolerance > 0.0 && samples != 0 && samples < 2 * s.max_harmonics + 1)
    r.fail(r.has("max_harmonics") ? "max_harmonics" : "time_samples",
           fmt::format("time_samples = {} resolve at most H = {}; max_harmonics = {} needs at least {} (or "
                       "time_samples = 0: automatic)",
                       samples, (samples - 1) / 2, s.max_harmonics, 2 * s.max_harmonics + 1));
  if (r.has("tolerance")) {
    s.tolerance = r.positive("tolerance");
    if (s.tolerance >= 1e-2) r.fail("tolerance", "must be below 1e-2 (relative force balance)");
  }
  if (const auto it = r.optional_integer("max_iterations")) {
    if (*it < 1 || *it > 1000) r.fail("max_iterations", "must lie in [1, 1000]");
    s.max_iterations = static_cast<int>(*it);
  }
  if (const auto n = r.optional_integer("threads")) {
    if (!contacts_required) r.fail("threads", "only a harmonic balance analysis sweeps its levels in parallel");
    if (*n < 1 || *n > 256)
      r.fail("threads", fmt::format("must lie in [1, 256] (force levels swept at once), found {}", *n));
    s.threads = static_cast<int>(*n);
  }
  if (r.has("base_motion")) {
    for (const char* key : {"forces", "force_levels"})
      if (r.has(key))
        r.fail(key,
               "a base motion is the excitation: leave out forces and force_levels ([analysis.base_motion] "
               "levels are its accelerations)");
    s.base_motion = parse_base_motion(r, folder, s.force_levels);
  } else {
    s.forces = parse_forces(r);
  }
  s.responses = parse_responses(r);
  for (const char* key : {"stepped_sine", "response_control"})
    if (r.has(key) && !contacts_required)
      r.fail(key,
             "only a harmonic balance analysis solves stepped sines point by point (a time analysis "
             "has stepped_sine = true)");
  // A case of stepped sines alone sweeps no band.
  if (!s.base_motion && (r.has("force_levels") || !(r.has("stepped_sine") || r.has("response_control")))) {
    s.force_levels = r.number_array("force_levels");
    if (s.force_levels.empty()) r.fail("force_levels", "needs at least one level [N]");
  }
  if (!s.base_motion) check_levels(r, "force_levels", s.force_levels, "force", "N");
  if (const toml::table* t = r.optional_table("ip_oop")) {
    TomlReader p(*t, r.path() + ".ip_oop", r.file());
    s.ip_oop.emplace(parse_point_dof(p, "left", p.string("left")), parse_point_dof(p, "right", p.string("right")));
    p.finish();
  }
  if (r.has("static_loads")) {
    int i = 0;
    for (const toml::node& n : r.array("static_loads")) {
      if (!n.is_table()) r.fail("static_loads", "write each load as { dof = \"A.y\", force = 40.0 }");
      TomlReader l(*n.as_table(), fmt::format("{}.static_loads[{}]", r.path(), i++), r.file());
      const PointDof dof = parse_point_dof(l, "dof", l.string("dof"));
      const double f = l.number("force");
      if (!std::isfinite(f)) l.fail("force", "must be finite");
      l.finish();
      s.static_loads.emplace_back(dof, f);
    }
  }
  {
    TomlReader m(model, r.path() + ".model", r.file());
    if (m.has("damping")) {
      if (!m.has("stiffness") && !m.has("frequency_hz"))
        m.fail("damping",
               "a damping matrix goes with matrices written in the case ('dofs', 'stiffness', 'mass') or a modal "
               "model ('dofs', 'frequency_hz', 'modal_mass')");
      if (r.has("modal_damping") || r.has("rayleigh"))
        r.fail("modal_damping", "the model gives its damping matrix: leave out modal_damping and rayleigh");
      s.damping_matrix = parse_square_matrix(m, "damping", m.string_array("dofs").size());
      if (const std::string problem = damping_matrix_problem(*s.damping_matrix); !problem.empty())
        m.fail("damping", problem);
    }
    s.model = parse_rom(m, folder);
    if (!s.model.forces.empty() || !s.model.responses.empty())
      m.fail("forces", "the forces and responses of an hbm analysis are given in [analysis]");
  }
  if (r.has("contact")) {
    int i = 0;
    for (const toml::node& n : r.array("contact")) {
      if (!n.is_table()) r.fail("contact", "write each contact as a [[analysis.contact]] table");
      const TomlReader c(*n.as_table(), fmt::format("{}.contact[{}]", r.path(), i++), r.file());
      s.contacts.push_back(parse_contact(c));
      // Its name heads its result columns: two of one name would share them.
      for (size_t k = 0; k + 1 < s.contacts.size(); ++k)
        if (s.contacts[k].name == s.contacts.back().name)
          c.fail("name", fmt::format("'{}' is also the name of contact[{}]", s.contacts.back().name, k));
    }
  }
  if (const toml::table* d = r.optional_table("damper"))
    s.damper = parse_damper(TomlReader(*d, r.path() + ".damper", r.file()));
  if (contacts_required && s.contacts.empty() && !s.damper && !r.has("gap_damper"))
    r.fail("contact",
           "an hbm analysis needs at least one [[analysis.contact]], an [analysis.damper] or an [analysis.gap_damper]");
  s.sweep.method = r.choice("sweep", {"grid", "arclength"}, "grid") == "grid" ? HbmSweepSpec::Method::grid
                                                                              : HbmSweepSpec::Method::arclength;
  if (s.harmonic_scope == HbmSpec::HarmonicScope::point && s.sweep.method != HbmSweepSpec::Method::grid)
    r.fail("sweep", "harmonic_scope = \"point\" chooses H at each frequency of a grid: it needs sweep = \"grid\"");
  if (s.sweep.method == HbmSweepSpec::Method::grid) {
    s.sweep.step_hz = r.positive("step_hz");
    if ((s.sweep.f_max - s.sweep.f_min) / s.sweep.step_hz > 1e6)
      r.fail("step_hz", "more than a million frequencies: choose a larger step");
  }
  if (const toml::table* c = r.optional_table("continuation")) {
    if (s.sweep.method == HbmSweepSpec::Method::grid)
      r.fail("continuation", "[analysis.continuation] needs sweep = \"arclength\"");
    TomlReader p(*c, r.path() + ".continuation", r.file());
    s.sweep.initial_step = p.optional_number("initial_step").value_or(s.sweep.initial_step);
    s.sweep.max_step = p.optional_number("max_step").value_or(s.sweep.max_step);
    s.sweep.min_step = p.optional_number("min_step").value_or(s.sweep.min_step);
    if (!(s.sweep.min_step > 0) || !(s.sweep.initial_step >= s.sweep.min_step) ||
        !(s.sweep.max_step >= s.sweep.initial_step))
      p.fail("max_step", "need 0 < min_step <= initial_step <= max_step");
    p.finish();
  }
  if (r.has("sensitivities")) {
    if (!contacts_required) r.fail("sensitivities", "only a harmonic balance analysis computes sensitivities");
    s.sensitivities = parse_sensitivities(r, s);
  }
  if (r.has("stability")) {
    if (!contacts_required)
      r.fail("stability", "only a harmonic balance analysis computes the stability of its solutions");
    const std::string st = r.choice("stability", {"none", "peaks", "path"});
    s.stability = st == "path"    ? HbmSpec::Stability::path
                  : st == "peaks" ? HbmSpec::Stability::peaks
                                  : HbmSpec::Stability::none;
  }
  if (const toml::table* t = r.optional_table("nonlinear_modes")) {
    if (!contacts_required) r.fail("nonlinear_modes", "only a harmonic balance analysis computes nonlinear modes");
    s.nonlinear_modes = parse_nonlinear_modes(TomlReader(*t, r.path() + ".nonlinear_modes", r.file()), s);
  }
  parse_cyclic(r, s, contacts_required);
  refuse_two_directions_beyond_sweeps(r, s, contacts_required);
  std::set<std::string> table_names;  // the levels' tables, then each stepped sine's
  for (double f : s.force_levels) table_names.insert(hbm_frf_table_name(f));
  s.stepped_sines = parse_stepped_sines(r, folder, table_names);
  s.response_controls = parse_response_controls(r, s.responses, folder, table_names);
  for (const char* key : {"stepped_sine", "response_control"})
    if (r.has(key) && (s.cyclic || s.gap_damper))
      r.fail(key, "a stepped sine runs on a lumped or reduced model without [analysis.cyclic]");
  if (s.base_motion) refuse_base_motion_misfits(r, s, contacts_required);
  return s;
}

}  // namespace bb
