// The facts of an hbm analysis: its model, the harmonics and AFT samples each level kept, the
// stability of its solutions and its nonlinear modes.
#include "report/describe_hbm.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "report/number_format.hpp"

namespace bb {

namespace {

// The peak with the largest `value` over every level (none when no value is positive), named as
// the report's facts and warnings name it: "OOP peak at Fe = 30 N".
struct WorstPeak {
  double value = 0.0;
  const HbmLevel* level = nullptr;
  const HbmPeak* peak = nullptr;
  std::string name() const {
    return peak ? fmt::format("{} at Fe = {} N", peak->kind == "peak" ? "peak" : peak->kind + " peak",
                              format_setting(level->force))
                : std::string();
  }
};

template <class Value>
WorstPeak worst_peak(const HbmOutcome& hbm, Value value) {
  WorstPeak w;
  for (const HbmLevel& l : hbm.levels)
    for (const HbmPeak& pk : l.peaks)
      if (const double v = value(pk); v > w.value) w = {v, &l, &pk};
  return w;
}

void describe_nonlinear_modes(const HbmSpec& spec, const HbmOutcome& hbm, RunRecord& run) {
  if (!spec.nonlinear_modes) return;
  const NonlinearModesSpec& nm = *spec.nonlinear_modes;
  size_t points = 0;
  for (const hbm::NonlinearModeBranch& b : hbm.nonlinear_modes) points += b.points.size();
  run.facts.emplace_back(
      "nonlinear modes (extended periodic motion concept, Krack 2015)",
      fmt::format("{} branch(es), modal amplitude {} to {} m kg^1/2 in {} log steps, H = {}: {} points in {:.3f} s",
                  hbm.nonlinear_modes.size(), format_setting(nm.amplitude_min), format_setting(nm.amplitude_max),
                  nm.points, spec.harmonics, points, hbm.nonlinear_mode_seconds));
  for (const hbm::NonlinearModeBranch& b : hbm.nonlinear_modes) {
    double lo = b.points.front().omega, hi = lo, dmin = b.points.front().damping_ratio(), dmax = dmin;
    for (const hbm::NonlinearModePoint& p : b.points) {
      lo = std::min(lo, p.omega), hi = std::max(hi, p.omega);
      dmin = std::min(dmin, p.damping_ratio()), dmax = std::max(dmax, p.damping_ratio());
    }
    run.facts.emplace_back(fmt::format("nonlinear mode {} (stuck linear {:.4f} Hz)", b.linear_mode,
                                       b.linear_omega / (2 * std::numbers::pi)),
                           fmt::format("frequency {:.4f} to {:.4f} Hz, damping ratio {:.4g} to {:.4g}",
                                       lo / (2 * std::numbers::pi), hi / (2 * std::numbers::pi), dmin, dmax));
    if (!b.skipped.empty())
      run.warnings.push_back(
          fmt::format("nonlinear mode {}: the branch went past {} requested amplitude(s) without a "
                      "solution ({:.4g} m kg^1/2); the first: {}",
                      b.linear_mode, b.skipped.size(), fmt::join(b.skipped, ", "), b.first_skip));
    if (!b.failure.empty()) run.warnings.push_back(fmt::format("the branch stopped early: {}", b.failure));
  }
}

// Stability by Hill's method: unstable path points per level, and a warning for every peak that
// lies on an unstable solution (a grid sweep can converge onto the middle branch of a fold).
void describe_stability(const HbmSpec& spec, const HbmOutcome& hbm, RunRecord& run) {
  if (spec.stability == HbmSpec::Stability::none) return;
  if (spec.stability == HbmSpec::Stability::path) {
    std::string per_level;
    for (const HbmLevel& l : hbm.levels) {
      int unstable = 0, unknown = 0;
      for (double s : l.stable) unstable += s == 0.0 ? 1 : 0, unknown += std::isnan(s) ? 1 : 0;  // NaN: unresolved
      per_level += fmt::format("{}{} N: {} of {}{}", per_level.empty() ? "" : "; ", format_setting(l.force), unstable,
                               l.stable.size(),
                               unknown ? fmt::format(" ({} unknown: growth beyond the band H resolves)", unknown) : "");
    }
    run.facts.emplace_back("unstable path points (Hill's method; frf_<Fe> columns stable, floquet_max_re)", per_level);
  }
  for (const HbmLevel& l : hbm.levels)
    for (const HbmPeak& pk : l.peaks) {
      if (!pk.stability || !pk.stability->ok)
        run.warnings.push_back(fmt::format("the stability of the {} at Fe = {} N was not computed: {}", pk.kind,
                                           format_setting(l.force),
                                           pk.stability ? pk.stability->failure : "no converged solution"));
      else if (!pk.stability->growing && !pk.stability->unresolved.empty())
        run.warnings.push_back(fmt::format("the stability of the {} at Fe = {} N ({:.4f} Hz) is unknown: {}", pk.kind,
                                           format_setting(l.force), pk.frequency_hz, pk.stability->unresolved));
      else if (pk.stability->growing)
        run.warnings.push_back(fmt::format(
            "the {} at Fe = {} N ({:.4f} Hz) lies on an unstable solution (largest Floquet exponent real part {:.3g} "
            "1/s): the motion would leave it",
            pk.kind, format_setting(l.force), pk.frequency_hz, pk.stability->max_real));
    }
}

// The harmonics each level kept and the truncation they leave at the peaks.
void describe_harmonics(const HbmSpec& spec, const HbmOutcome& hbm, RunRecord& run) {
  const WorstPeak truncated = worst_peak(hbm, [](const HbmPeak& pk) { return pk.truncation.largest(); });
  const double worst = truncated.value;
  const std::string where =
      truncated.peak ? fmt::format("{}, H = {}", truncated.name(), truncated.level->harmonics) : std::string();
  run.facts.emplace_back(
      "Harmonic truncation at the peaks (share of the motion the harmonics above H would add, up to 3 H)",
      worst > 0 ? fmt::format("at most {:.2e} ({})", worst, where) : std::string("0 (nothing above H excited)"));
  const bool by_change = spec.harmonic_criterion == HbmSpec::HarmonicCriterion::change;
  if (spec.harmonic_tolerance > 0.0 && spec.harmonic_scope == HbmSpec::HarmonicScope::point) {
    std::string per_level, unmet;
    for (const HbmLevel& l : hbm.levels) {
      if (l.point_harmonics.empty()) continue;
      const auto [lo, hi] = std::minmax_element(l.point_harmonics.begin(), l.point_harmonics.end());
      double mean = 0.0;
      for (int h : l.point_harmonics) mean += h;
      mean /= static_cast<double>(l.point_harmonics.size());
      std::vector<int> at_peaks;
      for (const HbmPeak& pk : l.peaks) at_peaks.push_back(pk.harmonics);
      per_level += fmt::format("{}{} N: H = {}-{} (mean {:.2f}; peaks at H = {})", per_level.empty() ? "" : "; ",
                               format_setting(l.force), *lo, *hi, mean, fmt::join(at_peaks, ", "));
      const auto points_unmet = std::count_if(l.point_change.begin(), l.point_change.end(),
                                              [&](double c) { return !(c <= spec.harmonic_tolerance); });
      if (points_unmet > 0)
        unmet += fmt::format("{}{} N ({} of {})", unmet.empty() ? "" : ", ", format_setting(l.force), points_unmet,
                             l.point_harmonics.size());
    }
    run.facts.emplace_back(
        fmt::format("Harmonics per frequency, raised by {} until the responses at the frequency change by <= {} from "
                    "the H one step below (at most H = {}; the next frequency starts a step lower; frf_<Fe> columns "
                    "harmonics and harmonic_change, table harmonics_per_point)",
                    spec.harmonic_step, format_setting(spec.harmonic_tolerance), spec.max_harmonics),
        per_level);
    if (!unmet.empty())
      run.warnings.push_back(fmt::format(
          "at some frequencies no two H up to max_harmonics = {} agreed to harmonic_tolerance = {} (or a pair did not "
          "converge and the point was reached by the fallback): {} (frf_<Fe> column harmonic_change is NaN or above "
          "the tolerance there)",
          spec.max_harmonics, format_setting(spec.harmonic_tolerance), unmet));
  } else if (spec.harmonic_tolerance > 0.0) {
    std::string per_level, unmet, beyond, missed;
    bool windowed = false;
    for (const HbmLevel& l : hbm.levels) {
      std::string tried;
      double change = std::numeric_limits<double>::quiet_NaN(), estimate = change;
      for (const HbmLevel::HarmonicTrial& t : l.harmonic_trials) {
        tried += fmt::format("{}{}{}", tried.empty() ? "" : ", ", t.harmonics, t.window_hz > 0.0 ? "w" : "");
        windowed = windowed || t.window_hz > 0.0;
        if (t.chosen) change = t.change, estimate = t.estimated_error;
        if (t.band_change > spec.harmonic_tolerance)
          missed += fmt::format("{}{} N (H = {}: {:.2e})", missed.empty() ? "" : ", ", format_setting(l.force),
                                t.harmonics, t.band_change);
      }
      per_level += fmt::format(
          "{}{} N: H = {} (tried {}{})", per_level.empty() ? "" : "; ", format_setting(l.force), l.harmonics, tried,
          by_change ? fmt::format("; change {:.2e}, estimated error {:.2e}", change, estimate) : std::string());
      if (by_change && !(change <= spec.harmonic_tolerance))
        unmet += fmt::format("{}{} N (H = {})", unmet.empty() ? "" : ", ", format_setting(l.force), l.harmonics);
      else if (by_change && estimate > spec.harmonic_tolerance)
        beyond += fmt::format("{}{} N (H = {}: {:.2e})", beyond.empty() ? "" : ", ", format_setting(l.force),
                              l.harmonics, estimate);
    }
    const std::string scope =
        spec.harmonic_scope == HbmSpec::HarmonicScope::peaks ? "the peaks" : "every point and peak";
    run.facts.emplace_back(
        by_change ? fmt::format("Harmonics per level, raised by {} until the change of the result at {} from the "
                                "previous good H (its sweep at its end, or over the band for the peaks, with trusted "
                                "peaks) is <= {} (at most "
                                "H = {}; table harmonic_selection)",
                                spec.harmonic_step, scope, format_setting(spec.harmonic_tolerance), spec.max_harmonics)
                  : fmt::format("Harmonics per level, raised until the truncation share at {} <= {} and the sweep "
                                "reaches its end with trusted peaks (at most H = {}; table harmonic_selection)",
                                scope, format_setting(spec.harmonic_tolerance), spec.max_harmonics),
        per_level + (windowed ? "; w: swept on windows around the previous H's peaks (column window_hz), the H "
                                "chosen then over the whole band"
                              : ""));
    if (!missed.empty())
      run.warnings.push_back(fmt::format(
          "the whole band's sweep at the H chosen on windows around the peaks moved the peaks by more than "
          "harmonic_tolerance = {} from the windows' at {}: the band holds a maximum the windows did not see "
          "(table harmonic_selection, column band_change)",
          format_setting(spec.harmonic_tolerance), missed));
    if (by_change) {
      if (!unmet.empty())
        run.warnings.push_back(fmt::format(
            "the change with H did not fall to harmonic_tolerance = {} at {}: no two good H up to max_harmonics = {} "
            "agreed (table harmonic_selection)",
            format_setting(spec.harmonic_tolerance), unmet, spec.max_harmonics));
      if (!beyond.empty())
        run.warnings.push_back(fmt::format(
            "the change with H met harmonic_tolerance = {} but the power law through the last three H puts the "
            "error above it at {}: the result converges slowly in H, the change understates its error",
            format_setting(spec.harmonic_tolerance), beyond));
    } else if (worst > spec.harmonic_tolerance)
      run.warnings.push_back(fmt::format(
          "the harmonic truncation share {:.2e} at the {} exceeds harmonic_tolerance = {}: no H up to max_harmonics = "
          "{} met it with a sweep that reached its end and trusted peaks",
          worst, where, format_setting(spec.harmonic_tolerance), spec.max_harmonics));
  } else if (worst > 1e-2) {
    run.warnings.push_back(
        fmt::format("the harmonics above H would add {:.1f} % of the motion at the {}: raise harmonics or set "
                    "harmonic_tolerance (H chosen per level)",
                    100.0 * worst, where));
  }
}

// A stepped curve's frequencies without a solution, said: in its table they are rows of NaN, in a
// fit failed evaluations (issue 68: they used to vanish from the table, the run ending "no checks").
template <class Curve>
void warn_failed_points(const char* what, const std::vector<Curve>& curves, RunRecord& run) {
  for (const Curve& c : curves) {
    if (c.failed_hz.empty()) continue;
    std::string list;
    for (size_t i = 0; i < c.failed_hz.size() && i < 5; ++i)
      list += fmt::format("{}{:.6g}", i ? ", " : "", c.failed_hz[i]);
    if (c.failed_hz.size() > 5) list += ", ...";
    run.warnings.push_back(fmt::format(
        "{} '{}': no solution at {} of {} frequencies ({} Hz; at {:.6g} Hz: {}): rows of NaN in table frf_{}", what,
        c.name, c.failed_hz.size(), c.failed_hz.size() + c.frequency_hz.size(), list, c.failed_hz.front(),
        c.failures.front(), c.name));
  }
}

}  // namespace

std::string describe_modal_ratios(const FrfDamping& d) {
  if (d.mode_zetas.empty()) return format_setting(d.zeta);
  std::string out;
  for (double z : d.mode_zetas) out += (out.empty() ? "" : ", ") + format_setting(z);
  const size_t n = d.mode_zetas.size();
  return fmt::format("{} on the lowest {} (the modes above the last take its ratio)", out,
                     n == 1 ? std::string("mode") : fmt::format("{} modes", n));
}

std::string describe_contacts(const PreparedHbm& p, const HbmSpec& spec) {
  std::string out;
  const auto add = [&](const std::string& name, const friction::PointParameters& point,
                       const friction::FrictionLaw& law, const friction::SliderDistribution* distribution) {
    out += fmt::format("{}{}: kn {} N/m, kt {} N/m, mu {}{}{}", out.empty() ? "" : "; ", name, format_setting(point.kn),
                       format_setting(point.kt), format_setting(point.mu),
                       law.name() == "jenkins" ? "" : ", " + law.describe(),
                       distribution ? ", " + distribution->describe() : "");
  };
  const size_t damper = p.damper ? p.damper->contacts.size() : 0;
  for (size_t c = 0; c < damper; ++c)
    add(p.contact_names[c], p.model.contacts[c].point, *p.model.contacts[c].law, nullptr);
  for (const HbmContactSpec& c : spec.contacts) add(c.name, c.point, *c.law, c.distribution.get());
  return out;
}

void describe_levels(const HbmSpec& spec, RunRecord& run) {
  std::string levels;
  for (double f : spec.force_levels) levels += fmt::format("{}{}", levels.empty() ? "" : ", ", format_setting(f));
  if (!spec.base_motion) {
    run.facts.emplace_back("force levels [N] (amplitude of the first force)", levels);
    return;
  }
  const BaseMotionSpec& b = *spec.base_motion;
  run.facts.emplace_back("base motion levels [m/s^2] (base acceleration of harmonic 1)", levels);
  std::string influence, harmonics;
  for (const auto& [dof, c] : b.influence)
    influence += fmt::format("{}{} {}", influence.empty() ? "" : ", ", format_setting(c), dof.name());
  for (const BaseHarmonic& h : b.harmonics)
    harmonics += fmt::format("{}h = {}: {} at {} deg", harmonics.empty() ? "" : ", ", h.order, format_setting(h.ratio),
                             format_setting(h.phase_deg));
  run.facts.emplace_back(
      "base motion",
      fmt::format(
          "the supports move with acceleration a_b(t); the load is -M r a_b with r = {}; responses and contacts "
          "are relative to the base; harmonics (acceleration relative to harmonic 1's) {}{}",
          influence, harmonics, b.file.empty() ? "" : fmt::format(", from the measured period {}", b.file)));
}

void describe(const HbmSpec& spec, const HbmOutcome& hbm, RunRecord& run) {
  const PreparedHbm& p = hbm.prepared;
  const std::string damping =
      spec.damping_matrix ? "damping matrix given in the case"
      : spec.damping.kind == FrfDamping::Kind::modal
          ? spec.damping.mode_zetas.empty()
                ? fmt::format("modal damping {} on every mode of the linear model", format_setting(spec.damping.zeta))
                : fmt::format("modal damping {}", describe_modal_ratios(spec.damping))
          : fmt::format("Rayleigh damping fitted to zeta = {}, {} at {}, {} Hz",
                        format_setting(spec.damping.rayleigh_zeta[0]), format_setting(spec.damping.rayleigh_zeta[1]),
                        format_setting(spec.damping.rayleigh_hz[0]), format_setting(spec.damping.rayleigh_hz[1]));
  const std::string sweep =
      spec.sweep.method == HbmSweepSpec::Method::grid
          ? fmt::format("a {} Hz grid (Newton from the secant guess)", format_setting(spec.sweep.step_hz))
          : "pseudo-arclength continuation";
  run.facts.emplace_back(
      "analysis", fmt::format("harmonic balance, H = {}, {} time samples per period, {} to {} Hz by {}; {}",
                              spec.harmonics, spec.time_samples > 0 ? format_setting(spec.time_samples) : "automatic",
                              format_setting(spec.sweep.f_min), format_setting(spec.sweep.f_max), sweep, damping));
  describe_levels(spec, run);
  if (spec.cyclic)
    run.facts.emplace_back(
        "cyclic symmetry",
        spec.cyclic->whole
            ? fmt::format(
                  "the whole ring of {} sectors built from the sector (forces of sector j shifted by j x {:.6g} "
                  "deg, engine order {}); the tables are the first sector's",
                  spec.cyclic->sectors, 360.0 * spec.cyclic->engine_order / spec.cyclic->sectors,
                  spec.cyclic->engine_order)
            : fmt::format(
                  "one sector of {} in the travelling wave of engine order {}: the next sector moves as this one "
                  "shifted by {:.6g} deg per harmonic 1",
                  spec.cyclic->sectors, spec.cyclic->engine_order,
                  360.0 * spec.cyclic->engine_order / spec.cyclic->sectors));
  run.facts.emplace_back("contacts", describe_contacts(p, spec));
  run.facts.emplace_back("model DOFs / linear model DOFs", fmt::format("{} / {}", p.model.mass.rows(), p.blade_dofs));
  if (p.damper_static) {
    std::string n0;
    for (size_t c = 0; c < p.damper->contacts.size(); ++c)
      n0 += fmt::format("{}{} {:.4g} N{}", n0.empty() ? "" : ", ", p.damper->contacts[c].name,
                        p.damper_static->normal_preload[static_cast<Eigen::Index>(c)],
                        p.damper_static->open[c] ? " (open)" : "");
    run.facts.emplace_back("damper static pre-solve: normal loads", n0);
  }
  run.facts.emplace_back("setup (reduction + matrices) / all sweeps [s]",
                         fmt::format("{:.2f} / {:.3f}", p.setup_seconds, hbm.sweep_seconds));
  if (spec.model.file.empty() && !spec.model.matrices) describe_cache("Craig-Bampton reduction", p.timing.cache, run);
  int reached = 0, points = 0;
  for (const HbmLevel& l : hbm.levels) {
    reached += l.path.converged ? 1 : 0;
    points += static_cast<int>(l.path.points.size());
    if (!l.path.converged)
      run.facts.emplace_back(fmt::format("sweep at Fe = {} N stopped", format_setting(l.force)), l.path.failure);
  }
  run.facts.emplace_back("sweeps that reached the end / points",
                         fmt::format("{} of {} / {}", reached, hbm.levels.size(), points));
  for (const HbmLevel& l : hbm.levels)
    for (const HbmPeak& pk : l.peaks)
      if (!pk.trusted)
        run.warnings.push_back(fmt::format("{} peak at Fe = {} N ({:.4f} Hz) is doubtful: {}", pk.kind,
                                           format_setting(l.force), pk.frequency_hz, pk.doubt));
  const WorstPeak sampled = worst_peak(hbm, [](const HbmPeak& pk) { return pk.sampling_error; });
  const double worst = sampled.value;
  const std::string where = sampled.name();
  run.facts.emplace_back(
      "AFT sampling error at the peaks (contact-force change with twice the samples, relative to the force scale)",
      worst > 0 ? fmt::format("at most {:.2e} ({})", worst, where) : std::string("0 (every peak stuck)"));
  if (spec.aft_tolerance > 0.0) {
    std::string per_level;
    for (const HbmLevel& l : hbm.levels)
      per_level += fmt::format("{}{} N: {} ({} sweep{})", per_level.empty() ? "" : "; ", format_setting(l.force),
                               l.samples, l.sampling_trials.size(), l.sampling_trials.size() == 1 ? "" : "s");
    run.facts.emplace_back(fmt::format("AFT samples per level, raised until the peaks' sampling error <= {} and the "
                                       "sweep reaches its end with trusted peaks (at most {}; table aft_sampling)",
                                       format_setting(spec.aft_tolerance), spec.max_time_samples),
                           per_level);
  }
  if (spec.aft_tolerance > 0.0 && worst > spec.aft_tolerance)
    run.warnings.push_back(
        fmt::format("the AFT sampling error {:.2e} at the {} exceeds aft_tolerance = {} even at the "
                    "largest samples tried (max_time_samples = {})",
                    worst, where, format_setting(spec.aft_tolerance), spec.max_time_samples));
  else if (!(spec.aft_tolerance > 0.0) && worst > 1e-3)
    run.warnings.push_back(
        fmt::format("the AFT samples leave a contact-force error of {:.2e} at the {}: raise time_samples or set "
                    "aft_tolerance (samples raised automatically)",
                    worst, where));
  const char* const held_unit[] = {"m", "m/s", "m/s^2"};
  for (const ResponseControlSpec& c : spec.response_controls)
    if (!c.file.empty())
      run.facts.emplace_back(
          fmt::format("response control '{}': held level", c.name),
          fmt::format("{:.6g} {}, the median of the amplitude column of {} (its points {:+.2f} % to {:+.2f} % of it)",
                      c.amplitude, held_unit[c.derivative], c.file, 100.0 * c.spread_low, 100.0 * c.spread_high));
  warn_failed_points("stepped sine", hbm.stepped_sines, run);
  warn_failed_points("response control", hbm.response_controls, run);
  describe_harmonics(spec, hbm, run);
  describe_stability(spec, hbm, run);
  describe_nonlinear_modes(spec, hbm, run);
}

}  // namespace bb
