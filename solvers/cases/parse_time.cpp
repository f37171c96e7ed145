#include "cases/parse_time.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cases/parse_hbm.hpp"
#include "common/errors.hpp"
#include "reduction/reduced_model.hpp"

namespace bb {
namespace {

// The exact flow tells stick from slip by comparing the contact force with mu N in the rounding of
// the forces that drive it: a slip force below 1e-12 of the load is lost in it (a level of 1e90 N
// against mu N0 = 3 N gave a "converged" motion of 0 after minutes), so such a level is refused.
constexpr double kLargestLoadPerSlipForce = 1e12;

// The largest force per unit level: per newton of the first force, or per m/s^2 of a base motion
// (|M r|, known here when the matrices are written in the case; 0 when unknown).
double load_per_level(const HbmSpec& s) {
  double pattern = 0.0;
  if (s.base_motion) {
    const std::optional<ReducedModel>& m = s.model.matrices;
    if (!m) return 0.0;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(m->size());
    for (const auto& [dof, c] : s.base_motion->influence)
      if (const std::optional<int> i = m->index_of(dof.point, static_cast<int>(dof.direction))) r[*i] += c;
    return (m->mass * r).cwiseAbs().maxCoeff();
  }
  if (s.forces.empty() || s.forces.front().amplitude == 0.0) return 0.0;
  for (const FrfForce& f : s.forces) pattern = std::max(pattern, std::abs(f.amplitude / s.forces.front().amplitude));
  return pattern;
}

void refuse_unresolvable_levels(const TomlReader& r, const HbmSpec& s) {
  const double pattern = load_per_level(s);
  if (s.force_levels.empty() || !(pattern > 0.0)) return;
  double slip = INFINITY;
  const HbmContactSpec* smallest = nullptr;
  for (const HbmContactSpec& c : s.contacts)
    if (c.point.mu * c.point.n0 > 0.0 && c.point.mu * c.point.n0 < slip) slip = c.point.mu * c.point.n0, smallest = &c;
  if (!smallest) return;  // no constant slip force: the load sets N (a damper, contacts without n0)
  const double level = *std::max_element(s.force_levels.begin(), s.force_levels.end());
  if (level * pattern > kLargestLoadPerSlipForce * slip)
    r.fail(s.base_motion ? "base_motion" : "force_levels",
           fmt::format("a load of {:g} N is {:.3g} times the slip force mu n0 = {:g} N of contact '{}': above {:g}, "
                       "the exact flow cannot tell its stick from its slip in the rounding of the forces; lower the "
                       "level (or raise mu n0)",
                       level * pattern, level * pattern / slip, slip, smallest->name, kLargestLoadPerSlipForce));
}

}  // namespace

namespace {

// Coulomb's law (law = "coulomb") asks the exact flow to hold stuck contacts rigidly; the flow holds
// every one or none, and only shooting on the exact flow has that flow.
bool rigid_stick(const TimeSpec& t) {
  size_t rigid = 0;
  const HbmContactSpec* first = nullptr;
  for (const HbmContactSpec& c : t.system.contacts)
    if (c.law->rigid_stick()) {
      ++rigid;
      if (!first) first = &c;
    }
  if (rigid == 0) return false;
  const auto fail = [&](const std::string& what) {
    throw InputError(fmt::format("{}: 'law': {}", first->at.where(), what));
  };
  if (rigid != t.system.contacts.size() || t.system.damper)
    fail("the exact flow holds every stuck contact rigidly or none: give every contact law = \"coulomb\"");
  if (t.method != TimeSpec::Method::shooting || t.period_map != TimeSpec::PeriodMap::exact)
    fail(
        "\"coulomb\" (Coulomb's stick) applies to method = \"shooting\" on the exact flow (period_map = \"exact\"); "
        "elsewhere write law = \"jenkins\" with a stiff kt");
  return true;
}

}  // namespace

TimeSpec parse_time(TomlReader& r, const std::filesystem::path& folder) {
  TimeSpec t;
  if (r.has("method"))
    t.method = r.choice("method", {"newmark", "shooting"}) == "shooting" ? TimeSpec::Method::shooting
                                                                         : TimeSpec::Method::newmark;
  if (r.has("period_map")) {
    if (t.method != TimeSpec::Method::shooting) r.fail("period_map", "applies to method = \"shooting\"");
    t.period_map = r.choice("period_map", {"exact", "newmark"}) == "newmark" ? TimeSpec::PeriodMap::newmark
                                                                             : TimeSpec::PeriodMap::exact;
  }
  if (r.has("stick"))
    r.fail("stick",
           "Coulomb's stick is a friction law now: write law = \"coulomb\" in each [[analysis.contact]] and leave "
           "out stick");
  if (r.has("floquet")) {
    t.floquet = r.boolean("floquet", false);
    if (t.floquet && t.method != TimeSpec::Method::shooting)
      r.fail("floquet",
             "Floquet multipliers need a periodic solution: method = \"shooting\" (Newmark marches a transient)");
  }
  if (const auto n = r.optional_integer("steps_per_period")) {
    if (*n < 8 || *n > 100000) r.fail("steps_per_period", "must lie in [8, 100000]");
    t.steps_per_period = static_cast<int>(*n);
  }
  if (const auto n = r.optional_integer("max_cycles")) {
    if (*n < 2 || *n > 1000000) r.fail("max_cycles", "must lie in [2, 1000000]");
    t.max_cycles = static_cast<int>(*n);
  }
  if (r.has("steady_tolerance")) {
    t.steady_tolerance = r.positive("steady_tolerance");
    if (t.steady_tolerance >= 0.1) r.fail("steady_tolerance", "must be below 0.1 (relative cycle-to-cycle change)");
  }
  if (r.has("envelope_tolerance")) {
    t.envelope_tolerance = r.positive("envelope_tolerance");
    if (t.envelope_tolerance >= 0.1)
      r.fail("envelope_tolerance", "must be below 0.1 (relative span of the first-harmonic amplitude)");
  }
  if (r.has("alpha")) {
    t.alpha = r.number("alpha");
    if (!(t.alpha >= -1.0 / 3.0 && t.alpha <= 0.0)) r.fail("alpha", "HHT-alpha must lie in [-1/3, 0]");
  }
  if (r.has("history_hz")) t.history_hz = r.positive("history_hz");
  if (const auto n = r.optional_integer("history_cycles")) {
    if (*n < 1 || *n > 10000) r.fail("history_cycles", "must lie in [1, 10000]");
    t.history_cycles = static_cast<int>(*n);
  }
  if (const auto n = r.optional_integer("compare_harmonics")) {
    if (*n < 0 || *n > 50) r.fail("compare_harmonics", "must lie in [0, 50] (0: no harmonic-balance comparison)");
    t.compare_harmonics = static_cast<int>(*n);
  }
  if (t.method == TimeSpec::Method::shooting && t.period_map != TimeSpec::PeriodMap::newmark) {
    for (const char* key : {"max_cycles", "steady_tolerance", "envelope_tolerance"})
      if (r.has(key))
        r.fail(key,
               "applies to method = \"newmark\" (or to shooting with period_map = \"newmark\", which marches where "
               "Newton finds no periodic solution); shooting converges on tolerance and max_iterations");
    if (r.has("alpha"))
      r.fail("alpha", "applies to method = \"newmark\" (or to shooting with period_map = \"newmark\")");
  }
  t.system = parse_hbm(r, folder, false);
  t.rigid_stick = rigid_stick(t);
  if (t.system.harmonic_tolerance > 0.0)
    r.fail("harmonic_tolerance", "applies to an hbm analysis (a time integration carries every harmonic)");
  if (t.system.sweep.method != HbmSweepSpec::Method::grid)
    r.fail("sweep", "a time-domain analysis steps through a grid: sweep = \"grid\"");
  if (2 * (t.system.harmonics + 1) > t.steps_per_period)
    r.fail("steps_per_period", fmt::format("must be at least 2 (H + 1) = {} for the DFT of {} harmonics",
                                           2 * (t.system.harmonics + 1), t.system.harmonics));
  if (t.method == TimeSpec::Method::shooting && t.period_map == TimeSpec::PeriodMap::exact) {
    for (const HbmContactSpec& c : t.system.contacts)
      if (!c.law->piecewise_linear())
        throw InputError(
            fmt::format("{}: 'law': the exact flow of shooting integrates piecewise-linear laws only, "
                        "and the {} law is not one here; write period_map = \"newmark\" to shoot on "
                        "the Newmark step",
                        c.at.where(), c.law->name()));
    if (t.system.damper && !t.system.damper->law->piecewise_linear())
      r.fail("damper", fmt::format("the exact flow of shooting integrates piecewise-linear laws only, and the "
                                   "damper's {} law is not one; write period_map = \"newmark\"",
                                   t.system.damper->law->name()));
    if (t.system.base_motion && t.system.base_motion->harmonics.size() > 1)
      r.fail("base_motion", fmt::format("the exact flow carries the excitation's harmonic 1 alone; the base moves at "
                                        "harmonic {} too: write period_map = \"newmark\"",
                                        t.system.base_motion->harmonics[1].order));
    refuse_unresolvable_levels(r, t.system);
  }
  if (t.system.base_motion && 2 * (t.system.base_motion->highest_order() + 1) > t.steps_per_period)
    r.fail("steps_per_period",
           fmt::format("must be at least 2 (h + 1) = {} for the base's harmonic {}",
                       2 * (t.system.base_motion->highest_order() + 1), t.system.base_motion->highest_order()));
  return t;
}

}  // namespace bb
