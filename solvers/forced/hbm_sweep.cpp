// One force level of an hbm analysis: the sweep in frequency (a grid of Newton solves, or
// pseudo-arclength continuation), the peaks refined by golden-section search, the sensitivities.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

#include "common/constants.hpp"
#include "common/seconds_since.hpp"
#include "forced/hbm_level.hpp"
#include "forced/hbm_level_system.hpp"
#include "forced/hbm_peak_sensitivity.hpp"
#include "forced/hbm_response.hpp"
#include "forced/linear_model.hpp"
#include "frf/sweep.hpp"
#include "hbm/sensitivity.hpp"

namespace bb {

std::string hbm_frf_table_name(double force) { return fmt::format("frf_{:g}", force); }

hbm::HarmonicBalance level_system(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics, int samples) {
  friction::FrictionModel m = p.model;
  friction::scale_excitation(m, force);
  hbm::HbmOptions options;
  options.harmonics = harmonics;
  options.aft.samples = samples;
  options.aft.resolve_events = spec.aft_events;
  options.tolerance = spec.tolerance;
  options.max_iterations = spec.max_iterations;
  return hbm::HarmonicBalance(std::move(m), options);
}

hbm::HarmonicBalance patient_level_system(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                                          int samples) {
  HbmSpec patient = spec;
  patient.max_iterations = 10 * spec.max_iterations;
  return level_system(p, patient, force, harmonics, samples);
}

std::optional<Eigen::VectorXd> damper_seated_start(const PreparedHbm& p, const hbm::HarmonicBalance& system,
                                                   double omega) {
  if (!p.damper_static) return std::nullopt;
  std::optional<Eigen::VectorXd> initial = system.linearized(omega, true);
  if (initial) {
    const auto& dofs = system.contact_dofs();
    for (size_t i = 0; i < dofs.size(); ++i) (*initial)[static_cast<Eigen::Index>(i)] = p.damper_static->q[dofs[i]];
  }
  return initial;
}

// dC/d(log p) on the blade DOFs by central differences 1e-6 apart in log p of the damping
// `build(factor)` gives with p scaled by `factor` (exact but for rounding where C is linear in p).
template <class Build>
Eigen::MatrixXd damping_log_derivative(const PreparedHbm& p, Build build) {
  const double h = 1e-6;
  const Eigen::Index n = p.model.mass.rows();
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  d.topLeftCorner(p.blade_dofs, p.blade_dofs) = (build(std::exp(h)) - build(std::exp(-h))) / (2.0 * h);
  return d;
}

// p d(model)/dp for an entry p of the lumped K or M (and its mirror). The damping built from the
// matrices (modal, Rayleigh) moves with them: its derivative by central differences of that
// construction, 1e-6 apart in log p (an eigenproblem of the model's size; C given as a matrix stays).
hbm::ModelDerivative lumped_entry_derivative(const PreparedHbm& p, const HbmSpec& spec, const HbmParameter& parameter) {
  const auto i = static_cast<Eigen::Index>(parameter.row), j = static_cast<Eigen::Index>(parameter.col);
  const Eigen::Index n = p.model.mass.rows();
  const auto scaled = [&](double factor) {
    ReducedModel m = p.linear;
    Eigen::MatrixXd& a = parameter.mass ? m.mass : m.stiffness;
    a(i, j) *= factor;
    if (i != j) a(j, i) *= factor;
    return m;
  };
  hbm::ModelDerivative d;
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(n, n);
  e(i, j) = (parameter.mass ? p.linear.mass : p.linear.stiffness)(i, j);
  e(j, i) = e(i, j);
  (parameter.mass ? d.mass : d.stiffness) = e;
  (parameter.mass ? d.stiffness : d.mass) = Eigen::MatrixXd::Zero(n, n);
  d.damping = spec.damping_matrix ? Eigen::MatrixXd::Zero(n, n) : damping_log_derivative(p, [&](double factor) {
    return damping_matrix(spec.damping, scaled(factor));
  });
  return d;
}

// A modal model's frequency (K_ii = M_ii w^2: d/d log f = 2 d/d log K_ii) or modal mass (M_ii and
// K_ii together: the sum of their log-derivatives).
hbm::ModelDerivative modal_coordinate_derivative(const PreparedHbm& p, const HbmSpec& spec,
                                                 const HbmParameter& parameter) {
  HbmParameter entry = parameter;
  entry.kind = HbmParameter::Kind::lumped_matrix;
  entry.col = entry.row;
  entry.mass = false;
  hbm::ModelDerivative d = lumped_entry_derivative(p, spec, entry);
  if (!parameter.mass) {
    d.stiffness *= 2.0;
    d.damping *= 2.0;
    return d;
  }
  entry.mass = true;
  const hbm::ModelDerivative m = lumped_entry_derivative(p, spec, entry);
  d.mass += m.mass;
  d.damping += m.damping;
  return d;
}

// d(model)/d(log zeta_i) of a ratio given per mode (C is linear in it).
hbm::ModelDerivative mode_damping_derivative(const PreparedHbm& p, const HbmSpec& spec, size_t mode) {
  hbm::ModelDerivative d;
  d.damping = damping_log_derivative(p, [&](double factor) {
    FrfDamping scaled = spec.damping;
    scaled.mode_zetas.at(mode) *= factor;
    return damping_matrix(scaled, p.linear);
  });
  return d;
}

// d(model)/d(log p) for each of spec.sensitivities: scaling a unit derivative by the parameter's
// value turns d/dp into d/d(log p). The damper's contacts come first in the model.
std::vector<hbm::ModelDerivative> log_derivatives(const PreparedHbm& p, const HbmSpec& spec,
                                                  const friction::FrictionModel& m) {
  const size_t damper_contacts = p.damper ? p.damper->contacts.size() : 0;
  std::vector<hbm::ModelDerivative> out;
  for (const HbmParameter& parameter : spec.sensitivities) {
    if (parameter.kind == HbmParameter::Kind::modal_damping) {  // C = zeta C1: dC/d(log zeta) = C
      out.push_back(hbm::damping_scale_derivative(m));
      continue;
    }
    if (parameter.kind == HbmParameter::Kind::lumped_matrix) {
      out.push_back(lumped_entry_derivative(p, spec, parameter));
      continue;
    }
    if (parameter.kind == HbmParameter::Kind::modal_coordinate) {
      out.push_back(modal_coordinate_derivative(p, spec, parameter));
      continue;
    }
    if (parameter.kind == HbmParameter::Kind::mode_damping) {
      out.push_back(mode_damping_derivative(p, spec, parameter.row));
      continue;
    }
    const bool damper = parameter.kind == HbmParameter::Kind::damper_law;
    // Each slider's kn, kt, n0 is a fixed share of the point's and its mu the point's, so the
    // point's log-derivative is the sum over its sliders of theirs.
    const auto [first, last] =
        damper ? std::pair<size_t, size_t>{0, damper_contacts} : p.contact_sliders.at(parameter.contact);
    hbm::ModelDerivative d;
    d.laws.assign(m.contacts.size(), {});
    for (size_t k = first; k < last; ++k) {
      const friction::PointParameters& law = m.contacts[k].point;
      friction::PointParameters& dl = d.laws[k];
      switch (parameter.law) {
        case friction::law_kn:
          dl.kn = law.kn;
          break;
        case friction::law_kt:
          dl.kt = law.kt;
          break;
        case friction::law_mu:
          dl.mu = law.mu;
          break;
        case friction::law_n0:
          dl.n0 = law.n0;
          break;
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

// With z the first-harmonic amplitude (Z = a1 - i b1): d|z| = Re(conj z dz) / |z| and
// d arg z = Im(conj z dz) / |z|^2.
ResponseDlog response_dlog(const PreparedHbm& p, const hbm::HarmonicBalance& system, const Eigen::VectorXd& x,
                           double omega, const std::vector<hbm::ModelDerivative>& derivatives) {
  const auto n_d = static_cast<Eigen::Index>(derivatives.size()),
             n_resp = static_cast<Eigen::Index>(p.responses.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ResponseDlog out{Eigen::MatrixXd::Constant(n_d, n_resp, nan), Eigen::MatrixXd::Constant(n_d, n_resp, nan)};
  hbm::HbmSolution s;
  s.x = x;
  s.omega = omega;
  s.converged = true;  // the caller's point is a converged solve
  std::vector<Eigen::MatrixXd> dq;
  try {
    dq = hbm::response_sensitivity(system, s, derivatives);
  } catch (const std::exception&) {
    return out;  // a singular Jacobian (e.g. a free static position): no derivative, NaN
  }
  const Eigen::VectorXcd z = first_harmonic(system, x, omega);
  for (Eigen::Index j = 0; j < n_d; ++j)
    for (Eigen::Index r = 0; r < n_resp; ++r) {
      const Eigen::Index dof = p.responses[static_cast<size_t>(r)];
      const std::complex<double> zr = z[dof],
                                 dz(dq[static_cast<size_t>(j)](dof, 1), -dq[static_cast<size_t>(j)](dof, 2));
      const double a2 = std::norm(zr);
      if (!(a2 > 0.0)) continue;
      out.amplitude(j, r) = (std::conj(zr) * dz).real() / std::sqrt(a2);
      out.phase_deg(j, r) = (std::conj(zr) * dz).imag() / a2 * 180.0 / std::numbers::pi;
    }
  return out;
}

namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

// The peak of `kind` (0 in-phase, 1 out-of-phase, or the first response) along the path, refined
// by golden-section search between the path's neighbours of the largest point (where the path does
// not fold there), each trial a Newton solve from the nearest path point.
// With the point scope the peak is solved at the largest H of the maximum and its neighbours.
// With `derivatives`, how the peak moves with them (forced/hbm_peak_sensitivity.hpp).
HbmPeak find_peak(const PreparedHbm& p, const LevelSystems& systems, const HbmLevel& level, int kind,
                  const std::vector<hbm::ModelDerivative>& derivatives) {
  const auto& pts = level.path.points;
  const Eigen::VectorXd values = p.ip_oop ? level.components.col(kind) : level.amplitude.col(0);
  Index k = 0;
  values.maxCoeff(&k);
  HbmPeak peak;
  peak.kind = p.ip_oop ? (kind == 0 ? "IP" : "OOP") : "peak";
  peak.harmonics = level.harmonics;
  if (!level.point_harmonics.empty()) {
    peak.harmonics = 0;
    for (Index j = std::max<Index>(k - 1, 0); j <= std::min<Index>(k + 1, static_cast<Index>(pts.size()) - 1); ++j)
      peak.harmonics = std::max(peak.harmonics, level.point_harmonics[static_cast<size_t>(j)]);
  }
  const hbm::HarmonicBalance& system = systems.at(peak.harmonics);
  const Index nc = static_cast<Index>(system.contact_dofs().size());
  // The sweep's iteration cap keeps its rare failed steps cheap; a polish solve starts up to half
  // a step away and must not fail for want of iterations (a smooth residual converges
  // quadratically, not in the few steps a piecewise-linear one takes once its states are right).
  hbm::HbmOptions patient = system.options();
  patient.max_iterations = std::max(patient.max_iterations, hbm::HbmOptions{}.max_iterations);
  const hbm::HarmonicBalance polish(system.model(), patient);
  auto solve = [&](double omega) {
    return hbm::solve_at_frequency(polish, omega,
                                   with_harmonics(nearest_point(level.path, omega).x, nc, peak.harmonics));
  };
  auto value = [&](const hbm::HbmSolution& s) { return peak_values(p, first_harmonic(system, s.x, s.omega), kind); };
  hbm::HbmSolution best = solve(pts[static_cast<size_t>(k)].omega);
  const bool interior = k > 0 && k + 1 < static_cast<Index>(pts.size());
  if (interior) {
    const double a = pts[static_cast<size_t>(k - 1)].omega, b = pts[static_cast<size_t>(k + 1)].omega;
    if ((pts[static_cast<size_t>(k)].omega - a) * (b - pts[static_cast<size_t>(k)].omega) > 0) {  // no fold here
      std::map<double, hbm::HbmSolution> solved;
      const auto component = [&](double omega) -> std::optional<double> {
        const hbm::HbmSolution& s = solved.emplace(omega, solve(omega)).first->second;
        return s.converged ? std::optional<double>(value(s).component) : std::nullopt;
      };
      // To 1e-7 of the frequency: a coarse grid's neighbours bracket tens of hertz.
      const GoldenSearch search = golden_section_maximum(component, a, b, 40, 1e-7);
      double best_value = best.converged ? value(best).component : -1.0;
      for (double omega : search.compared) {
        const hbm::HbmSolution& s = solved.at(omega);
        if (const double v = value(s).component; v > best_value) best = s, best_value = v;
      }
    }
  }
  peak.solution = best;
  peak.frequency_hz = best.omega / kTwoPi;
  const double below = pts[static_cast<size_t>(std::max<Index>(k - 1, 0))].omega / kTwoPi;
  const double above =
      pts[static_cast<size_t>(std::min<Index>(k + 1, static_cast<Index>(pts.size()) - 1))].omega / kTwoPi;
  for (double f : level.failed_hz)
    if (f > std::min(below, above) && f < std::max(below, above)) {
      peak.trusted = false;
      peak.doubt = fmt::format("the sweep did not converge at {:.4f} Hz, next to the maximum at {:.4f} Hz", f,
                               peak.frequency_hz);
    }
  if (!level.path.converged && k + 1 == static_cast<Index>(pts.size())) {
    peak.trusted = false;
    peak.doubt = fmt::format("the maximum is the last point before the sweep stopped ({})", level.path.failure);
  }
  if (best.converged) {
    const PeakValues v = value(best);
    peak.component = v.component;
    peak.amplitude = v.amplitude;
    peak.energy = hbm::cycle_energy(system, best);
    // The AFT's sampling error at the peak: the contact forces of the same motion sampled twice as
    // finely (exact for a stuck contact; a kink between samples of a stick-slip loop is not), as the
    // residual it leaves in the balance, relative to the balance's force scale (the solve's own measure).
    hbm::HbmOptions finer = system.options();
    finer.aft.samples = 2 * system.aft_options().samples;
    const hbm::HarmonicBalance twice(system.model(), finer);
    const Eigen::VectorXd g = system.contact_forces(best.x).force;
    peak.sampling_error = (twice.contact_forces(best.x).force - g).norm() / std::max(system.force_scale(), 1e-300);
    peak.truncation = systems.probe(peak.harmonics).at(best.x, best.omega, p.responses);
  }
  if (!derivatives.empty()) add_peak_sensitivities(p, polish, kind, derivatives, !interior, peak);
  return peak;
}

// Fills level.amplitude_dlog and phase_dlog_deg from the converged path points.
void add_sensitivities(const PreparedHbm& p, const LevelSystems& systems,
                       const std::vector<hbm::ModelDerivative>& derivatives, HbmLevel& level) {
  const Index n_points = static_cast<Index>(level.path.points.size()), n_resp = static_cast<Index>(p.responses.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  level.amplitude_dlog.assign(derivatives.size(), Eigen::MatrixXd::Constant(n_points, n_resp, nan));
  level.phase_dlog_deg.assign(derivatives.size(), Eigen::MatrixXd::Constant(n_points, n_resp, nan));
  for (Index i = 0; i < n_points; ++i) {
    const hbm::ContinuationPoint& pt = level.path.points[static_cast<size_t>(i)];
    const ResponseDlog d =
        response_dlog(p, systems.at(point_h(level, static_cast<size_t>(i))), pt.x, pt.omega, derivatives);
    for (size_t j = 0; j < derivatives.size(); ++j) {
      level.amplitude_dlog[j].row(i) = d.amplitude.row(static_cast<Index>(j));
      level.phase_dlog_deg[j].row(i) = d.phase_deg.row(static_cast<Index>(j));
    }
  }
}

HbmLevel sweep_at_samples(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics, int samples,
                          const HbmProgress& progress, const LevelLink* link, const PeakWindows* windows) {
  const auto t0 = Clock::now();
  HbmLevel level;
  level.force = force;
  const LevelSystems systems(p, spec, force, samples);
  level.samples = systems.at(harmonics).aft_options().samples;
  level.harmonics = harmonics;
  const double omega_start = kTwoPi * spec.sweep.f_min, omega_end = kTwoPi * spec.sweep.f_max;
  std::optional<LevelStart> neighbour;
  if (link) neighbour = link->relay.from_neighbour(link->level);
  const FirstSolution first = [&](int h) {
    const hbm::HarmonicBalance& system = systems.at(h);
    std::optional<Eigen::VectorXd> initial;
    if (neighbour)
      initial = with_harmonics(neighbour->x, static_cast<Index>(system.contact_dofs().size()), h);
    else
      initial = damper_seated_start(p, system, omega_start);
    hbm::HbmSolution s = first_solution(p, spec, force, h, samples, omega_start, initial,
                                        neighbour ? std::optional<double>(neighbour->force) : std::nullopt);
    if (link && s.converged) link->relay.publish(link->level, LevelStart{s.x, h, force});
    return s;
  };
  hbm::ContinuationResult& path = level.path;
  const SweepReport report = [&](double omega, int point, int iterations) {
    if (progress && point % 25 == 0)
      progress(
          fmt::format("Fe = {:g} N, H = {}, {} samples: {:.3f} Hz, point {}, {} iterations", force,
                      spec.harmonic_scope == HbmSpec::HarmonicScope::point ? "per point" : fmt::to_string(harmonics),
                      level.samples, omega / kTwoPi, point, iterations));
  };
  if (windows) {
    sweep_grid_windows(p, spec, systems, *windows, level, report);
  } else if (spec.sweep.method == HbmSweepSpec::Method::grid) {
    sweep_grid(p, spec, systems, first, level, report);
    level.samples = systems.at(level.harmonics).aft_options().samples;
  } else if (const hbm::HbmSolution start = first(harmonics); !start.converged) {
    path.failure = "first point: " + start.failure;
  } else {
    hbm::ContinuationOptions c;
    c.omega_start = omega_start;
    c.omega_end = omega_end;
    c.initial_step = spec.sweep.initial_step;
    c.max_step = spec.sweep.max_step;
    c.min_step = spec.sweep.min_step;
    c.max_points = 20000;
    c.initial = start.x;
    c.progress = [&](const hbm::ContinuationProgress& s) { report(s.omega, s.point, s.iterations); };
    path = hbm::continue_in_frequency(systems.at(harmonics), c);
  }
  const size_t n_points = path.points.size();
  level.amplitude.resize(static_cast<Index>(n_points), static_cast<Index>(p.responses.size()));
  level.phase_deg.resize(static_cast<Index>(n_points), static_cast<Index>(p.responses.size()));
  level.excursion.resize(static_cast<Index>(n_points), static_cast<Index>(p.responses.size()));
  if (p.ip_oop) level.components.resize(static_cast<Index>(n_points), 2);
  for (size_t i = 0; i < n_points; ++i) {
    const hbm::ContinuationPoint& pt = path.points[i];
    level.frequency_hz.push_back(pt.omega / kTwoPi);
    const Eigen::MatrixXd q = systems.at(point_h(level, i)).recover(pt.x, pt.omega);
    write_response_row(p, q, 1.0, static_cast<Index>(i), level.amplitude, level.phase_deg, level.excursion);
    if (p.ip_oop) {
      const Eigen::VectorXcd z = first_harmonic(q);
      for (int k = 0; k < 2; ++k) level.components(static_cast<Index>(i), k) = peak_values(p, z, k).component;
    }
  }
  if (spec.harmonic_tolerance > 0.0 && spec.harmonic_criterion == HbmSpec::HarmonicCriterion::share &&
      spec.harmonic_scope == HbmSpec::HarmonicScope::path && n_points > 0) {
    // Each point on the scale of the curve (the response's largest first-harmonic amplitude over
    // the path): far from resonance the motion is small and its harmonics large beside it, but
    // small on the curve a check or a plot reads.
    std::vector<double> scales;
    for (Index r = 0; r < level.amplitude.cols(); ++r) scales.push_back(level.amplitude.col(r).maxCoeff());
    const hbm::TruncationProbe& truncation = systems.probe(harmonics);
    for (const hbm::ContinuationPoint& pt : path.points) {
      const hbm::HarmonicTruncation t = truncation.at(pt.x, pt.omega, p.responses, scales);
      level.harmonic_share.push_back(t.ok ? t.largest() : 1.0);  // not evaluated: as if nothing were resolved
      level.harmonics_needed = std::max(level.harmonics_needed, t.needed(spec.harmonic_tolerance));
    }
  }
  std::vector<hbm::ModelDerivative> derivatives;
  if (!spec.sensitivities.empty()) derivatives = log_derivatives(p, spec, systems.at(level.harmonics).model());
  if (!derivatives.empty() && spec.path_sensitivities) add_sensitivities(p, systems, derivatives, level);
  if (n_points > 0)
    for (int k = 0; k < (p.ip_oop ? 2 : 1); ++k) level.peaks.push_back(find_peak(p, systems, level, k, derivatives));
  level.seconds = seconds_since(t0);
  return level;
}

// The Floquet exponents spec.stability asks for, on the sweep a level keeps (not on the sampling
// trials it discards).
// `samples` as the level's sweep asked for them (0: automatic per H).
void add_stability(const PreparedHbm& p, const HbmSpec& spec, double force, int samples, HbmLevel& level) {
  if (spec.stability == HbmSpec::Stability::none) return;
  const auto t0 = Clock::now();
  const LevelSystems systems(p, spec, force, samples);
  if (spec.stability == HbmSpec::Stability::path)
    for (size_t i = 0; i < level.path.points.size(); ++i) {
      const hbm::ContinuationPoint& pt = level.path.points[i];
      const hbm::HillStability st = hbm::hill_stability(systems.at(point_h(level, i)), pt.x, pt.omega);
      level.stable.push_back(st.verdict());
      level.floquet_max_real.push_back(st.ok ? st.max_real : std::numeric_limits<double>::quiet_NaN());
    }
  for (HbmPeak& pk : level.peaks)
    if (pk.solution.converged)
      pk.stability = hbm::hill_stability(systems.at(pk.harmonics), pk.solution.x, pk.solution.omega);
  level.seconds += seconds_since(t0);
}

// sweep_hbm_level, on the whole band or on windows of it.
HbmLevel sweep_level(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                     const HbmProgress& progress, bool retry_failures, const LevelLink* link,
                     const PeakWindows* windows) {
  int samples = spec.time_samples;
  HbmLevel level = sweep_at_samples(p, spec, force, harmonics, samples, progress, link, windows);
  if (!(spec.aft_tolerance > 0.0)) {
    add_stability(p, spec, force, samples, level);
    return level;
  }
  std::vector<HbmLevel::SamplingTrial> trials;
  double seconds = 0.0;
  for (;;) {
    HbmLevel::SamplingTrial t;
    t.samples = level.samples;
    t.reached_end = level.path.converged;
    t.trusted = peaks_trusted(level);
    for (const HbmPeak& pk : level.peaks) t.aft_error = std::max(t.aft_error, pk.sampling_error);
    t.seconds = level.seconds;
    seconds += level.seconds;
    trials.push_back(t);
    const bool met = t.aft_error <= spec.aft_tolerance && t.reached_end && t.trusted;
    // The event-resolved AFT's residual does not roughen with fewer samples (they only bracket the
    // transitions): once its error meets the tolerance, one doubling tries transitions two samples
    // may have hidden; more would sweep the same failure again (Table XI at H = 5, 60 N from 172 Hz:
    // 8 sweeps to 4096 samples, each stopping at 172.45 Hz, 72 s instead of 2).
    const bool samples_cannot_help = spec.aft_events && t.aft_error <= spec.aft_tolerance && trials.size() >= 2;
    if (met || samples_cannot_help || level.samples >= spec.max_time_samples ||
        (!retry_failures && !(t.reached_end && t.trusted)))
      break;
    // The error falls as 1 / n (a stick-slip kink lies between two samples), so when it alone is
    // the reason, jump to the power-of-two multiple that should meet the tolerance; else double.
    int factor = 2;
    if (t.reached_end && t.trusted)
      while (factor < 64 && t.aft_error / factor > spec.aft_tolerance) factor *= 2;
    samples = std::min(factor * level.samples, spec.max_time_samples);
    level = sweep_at_samples(p, spec, force, harmonics, samples, progress, link, windows);
  }
  level.sampling_trials = std::move(trials);
  level.seconds = seconds;  // the cost of reaching the tolerance, every trial included
  add_stability(p, spec, force, samples, level);
  return level;
}

}  // namespace

bool peaks_trusted(const HbmLevel& level) {
  return !level.peaks.empty() && std::all_of(level.peaks.begin(), level.peaks.end(),
                                             [](const HbmPeak& pk) { return pk.trusted && pk.solution.converged; });
}

HbmLevel sweep_hbm_level(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                         const HbmProgress& progress, bool retry_failures, const LevelLink* link) {
  return sweep_level(p, spec, force, harmonics, progress, retry_failures, link, nullptr);
}

HbmLevel sweep_hbm_level_windows(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics,
                                 const HbmProgress& progress, const PeakWindows& windows) {
  return sweep_level(p, spec, force, harmonics, progress, false, nullptr, &windows);
}

}  // namespace bb
