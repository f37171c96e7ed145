#include "analysis/contact_loop_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "common/constants.hpp"

namespace bb {
namespace {

using friction::ContactState;

bool slipping(ContactState s) { return s == ContactState::slip_positive || s == ContactState::slip_negative; }

// Least-squares slope of T against u with one intercept per stick segment (a maximal run of
// consecutive stuck samples, cyclic). One pooled line would be biased: the two stick branches of a
// stick-slip loop are parallel lines kt (u - w) with different slider positions w.
double stick_slope(const friction::AftResult& a) {
  const Eigen::Index n = a.u.size();
  Eigen::Index start = 0;  // a non-stuck sample to start from, so that no run wraps
  while (start < n && a.state[static_cast<size_t>(start)] == ContactState::stick) ++start;
  double sut = 0, suu = 0;
  std::vector<Eigen::Index> run;
  const auto close_run = [&] {
    if (run.size() >= 2) {
      double mu = 0, mt = 0;
      for (Eigen::Index k : run) mu += a.u[k], mt += a.t[k];
      mu /= static_cast<double>(run.size());
      mt /= static_cast<double>(run.size());
      for (Eigen::Index k : run) sut += (a.u[k] - mu) * (a.t[k] - mt), suu += (a.u[k] - mu) * (a.u[k] - mu);
    }
    run.clear();
  };
  for (Eigen::Index i = 1; i <= n; ++i) {
    const Eigen::Index k = (start + i) % n;  // start == n (stuck throughout): one run of every sample
    if (a.state[static_cast<size_t>(k)] == ContactState::stick)
      run.push_back(k);
    else
      close_run();
  }
  close_run();
  const double scale = a.u.cwiseAbs().maxCoeff();
  return suu > 1e-20 * scale * scale ? sut / suu : kNan;
}

}  // namespace

JenkinsLoopClosedForm jenkins_loop_closed_form(const friction::PointParameters& law, double amplitude) {
  friction::validate(law);
  if (!(amplitude > 0.0) || !std::isfinite(amplitude))
    throw std::invalid_argument(fmt::format("Jenkins loop: amplitude must be finite and > 0 (got {})", amplitude));
  const double fs = law.mu * law.n0, xs = fs / law.kt;
  if (amplitude <= xs) return {.energy = 0.0, .stiffness = law.kt, .damping = 0.0};
  const double beta = std::acos(1.0 - 2.0 * xs / amplitude);
  const double energy = 4.0 * fs * (amplitude - xs);
  return {.energy = energy,
          .stiffness = law.kt / std::numbers::pi * (beta - 0.5 * std::sin(2.0 * beta)),
          .damping = energy / (std::numbers::pi * amplitude * amplitude)};
}

double lift_off_fraction_closed_form(const friction::PointParameters& law, double normal_amplitude) {
  const double reach = law.kn * normal_amplitude;
  if (!(reach > law.n0)) return 0.0;
  return std::acos(law.n0 / reach) / std::numbers::pi;
}

ContactLoopSummary summarise_loop(const friction::PointParameters& law, double tangential_amplitude,
                                  const friction::AftResult& a) {
  ContactLoopSummary s;
  const Eigen::Index n = a.u.size();
  // Loop area by the trapezoid rule in u over the closed sampled loop: what a rig integrates from its
  // samples. At constant N (and for in-phase u, v) T(u) is piecewise linear in u and the samples are
  // exact values of the continuous loop (each step is exact where u is monotone between samples), so
  // the rule errs only in the intervals holding a stick/slip/lift-off corner, by at most
  // (slope jump) du^2 / 8 each: O(1 / n^2), a bound the verification cases use as tolerance.
  // cycle_work on the DFT coefficients equals this sum divided by sin(h) / h, h = 2 pi / n
  // (summation by parts): the same order, plus a bias of h^2 / 6 that has no such bound.
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index next = (k + 1) % n;
    s.dissipated_energy += 0.5 * (a.t[k] + a.t[next]) * (a.u[next] - a.u[k]);
  }
  double stick = 0, slip = 0, open = 0;
  s.min_normal = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < n; ++k) {
    const ContactState st = a.state[static_cast<size_t>(k)];
    s.max_tangential_force = std::max(s.max_tangential_force, std::abs(a.t[k]));
    s.min_normal = std::min(s.min_normal, a.n[k]);
    s.max_normal = std::max(s.max_normal, a.n[k]);
    if (st == ContactState::lift_off) {
      ++open;
      s.max_force_when_open = std::max({s.max_force_when_open, std::abs(a.t[k]), a.n[k]});
      continue;
    }
    (slipping(st) ? slip : stick) += 1;
    if (a.n[k] > 0 && law.mu > 0) s.max_t_over_mu_n = std::max(s.max_t_over_mu_n, std::abs(a.t[k]) / (law.mu * a.n[k]));
  }
  s.stick_fraction = stick / static_cast<double>(n);
  s.slip_fraction = slip / static_cast<double>(n);
  s.lift_off_fraction = open / static_cast<double>(n);
  s.stick_slope = stick_slope(a);
  // First harmonic of T in the AFT layout [c0, a1, b1]: T1 = a1 cos + b1 sin, b1 < 0 when dissipating.
  s.equivalent_stiffness = a.tangential[1] / tangential_amplitude;
  s.equivalent_damping = -a.tangential[2] / tangential_amplitude;
  return s;
}

ContactLoopOutcome run_contact_loop(const ContactLoopSpec& spec) {
  if (!(spec.tangential_amplitude > 0.0) || !(spec.normal_amplitude >= 0.0) || !std::isfinite(spec.normal_phase_deg) ||
      spec.samples < 16)
    throw std::invalid_argument("contact_loop: need U > 0, V >= 0, a finite phase and at least 16 samples");
  const double phi = spec.normal_phase_deg * std::numbers::pi / 180.0;
  // H = 1 coefficients [c0, a1, b1]: V cos(theta + phi) = V cos(phi) cos(theta) - V sin(phi) sin(theta).
  const Eigen::Vector3d u(0.0, spec.tangential_amplitude, 0.0);
  const Eigen::Vector3d v(0.0, spec.normal_amplitude * std::cos(phi), -spec.normal_amplitude * std::sin(phi));
  friction::AftOptions options;
  options.samples = spec.samples;
  ContactLoopOutcome o;
  o.aft = friction::aft_parallel(spec.point, spec.distribution.get(), u, v, options);
  o.summary = summarise_loop(spec.point, spec.tangential_amplitude, o.aft);
  const friction::AftResult& a = o.aft;
  const ContactLoopSummary& s = o.summary;

  std::vector<std::vector<double>> rows;
  std::vector<std::string> states;
  for (Eigen::Index k = 0; k < a.u.size(); ++k) {
    rows.push_back({static_cast<double>(k + 1), 360.0 * static_cast<double>(k) / spec.samples, a.u[k], a.v[k], a.t[k],
                    a.n[k], a.w[k]});
    states.emplace_back(friction::state_name(a.state[static_cast<size_t>(k)]));
  }
  ResultTable h = table_from_rows("hysteresis",
                                  {"instant", "phase_deg", "relative_tangential_m", "relative_normal_m",
                                   "tangential_force_n", "normal_force_n", "slider_m"},
                                  rows);
  h.add_text_column("state", std::move(states));
  o.tables.emplace("hysteresis", std::move(h));

  // The closed forms hold at constant normal load only.
  const bool constant_normal = spec.normal_amplitude == 0.0 || spec.point.kn == 0.0;
  JenkinsLoopClosedForm cf{kNan, kNan, kNan};
  if (constant_normal && !spec.distribution) {
    cf = jenkins_loop_closed_form(spec.point, spec.tangential_amplitude);
  } else if (constant_normal) {
    // Another law gives its loop energy (and so the loss stiffness energy / (pi U^2)), when it has one.
    if (const auto energy = spec.distribution->closed_form_energy(spec.point, spec.tangential_amplitude)) {
      cf.energy = *energy;
      cf.damping = *energy / (std::numbers::pi * spec.tangential_amplitude * spec.tangential_amplitude);
    }
  }
  o.tables.emplace(
      "loop_summary",
      table_from_rows(
          "loop_summary",
          {"loop", "dissipated_energy_j", "closed_form_energy_j", "max_tangential_force_n", "stick_slope_n_per_m",
           "stick_fraction", "slip_fraction", "lift_off_fraction", "closed_form_lift_off_fraction",
           "equivalent_stiffness_n_per_m", "equivalent_damping_n_per_m", "closed_form_stiffness_n_per_m",
           "closed_form_damping_n_per_m", "max_t_over_mu_n", "max_force_when_open_n", "min_normal_n", "max_normal_n",
           "periods", "closed"},
          {{1.0, s.dissipated_energy, cf.energy, s.max_tangential_force, s.stick_slope, s.stick_fraction,
            s.slip_fraction, s.lift_off_fraction, lift_off_fraction_closed_form(spec.point, spec.normal_amplitude),
            s.equivalent_stiffness, s.equivalent_damping, cf.stiffness, cf.damping, s.max_t_over_mu_n,
            s.max_force_when_open, s.min_normal, s.max_normal, static_cast<double>(a.periods), a.closed ? 1.0 : 0.0}}));
  return o;
}

}  // namespace bb
