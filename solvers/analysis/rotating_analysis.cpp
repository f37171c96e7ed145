#include "analysis/rotating_analysis.hpp"

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>

#include "analysis/stress_tables.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "ffrf/elastic_basis.hpp"
#include "ffrf/rotating_body.hpp"
#include "ffrf/rotation_profile.hpp"
#include "linalg/spd_factor.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

const char* axis_name(int d) { return d == 0 ? "x" : d == 1 ? "y" : "z"; }

ffrf::RotationProfile profile_of(const RotatingSpec& s) {
  switch (s.profile) {
    case RotatingSpec::Profile::constant:
      return ffrf::RotationProfile::constant_speed(s.speed);
    case RotatingSpec::Profile::spin_up:
      return ffrf::RotationProfile::spin_up(s.speed, s.spin_up_time);
    case RotatingSpec::Profile::torque: {
      const double tau = s.torque;
      return ffrf::RotationProfile::free([tau](double) { return tau; }, s.initial_speed, 0.0,
                                         fmt::format("constant torque {:g} N m", tau));
    }
  }
  throw std::logic_error("unknown rotation profile");
}

// The speed at which the steady state is taken: the constant speed, or the spin-up's final one.
double steady_speed(const RotatingSpec& s) {
  return s.profile == RotatingSpec::Profile::torque ? s.initial_speed : s.speed;
}

// Global DOFs of every node of every history set, set after set, node after node, x y (z).
std::vector<int> history_dofs(const Model& model, const RotatingSpec& spec) {
  std::vector<int> dofs;
  for (const std::string& name : spec.histories) {
    const auto it = model.node_sets.find(name);
    if (it == model.node_sets.end())
      throw InputError(fmt::format("{}: 'analysis.histories': no node set '{}'", spec.at.where(), name));
    for (int n : it->second)
      for (int d = 0; d < model.mesh.dim; ++d) dofs.push_back(n * model.mesh.dim + d);
  }
  return dofs;
}

// Mean over the set's nodes of each direction: samples x (sets * dim).
Eigen::MatrixXd set_means(const Model& model, const RotatingSpec& spec, const Eigen::MatrixXd& per_dof) {
  const int dim = model.mesh.dim;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(per_dof.rows(), static_cast<Index>(spec.histories.size() * dim));
  Index column = 0;
  for (size_t s = 0; s < spec.histories.size(); ++s) {
    const auto& nodes = model.node_sets.at(spec.histories[s]);
    for (size_t n = 0; n < nodes.size(); ++n)
      for (int d = 0; d < dim; ++d)
        out.col(static_cast<Index>(s) * dim + d) += per_dof.col(column++) / static_cast<double>(nodes.size());
  }
  return out;
}

// The same means of a free-DOF static displacement.
Eigen::VectorXd static_means(const Model& model, const RotatingSpec& spec, const ffrf::RotatingBody& body,
                             const Eigen::VectorXd& free_values) {
  const Eigen::VectorXd all = ffrf::expand_to_global(body, free_values);
  const std::vector<int> dofs = history_dofs(model, spec);
  Eigen::MatrixXd row(1, static_cast<Index>(dofs.size()));
  for (size_t i = 0; i < dofs.size(); ++i) row(0, static_cast<Index>(i)) = all[dofs[i]];
  return set_means(model, spec, row).row(0).transpose();
}

void add_history_table(RotatingOutcome& o, const RotatingSpec& spec, const Eigen::MatrixXd& means) {
  std::vector<std::string> cols = {"sample", "time_s", "theta_rad", "omega_rad_s"};
  for (const std::string& s : spec.histories)
    for (int d = 0; d < o.dim; ++d) cols.push_back(fmt::format("{}.u{}_m", s, axis_name(d)));
  const ffrf::FfrfHistory& h = o.history;
  std::vector<std::vector<double>> rows;
  double next = 0.0;
  for (size_t i = 0; i < h.time.size(); ++i) {
    if (h.time[i] + 1e-12 < next && i + 1 < h.time.size()) continue;
    next = h.time[i] + spec.history_interval;
    std::vector<double> row = {static_cast<double>(rows.size() + 1), h.time[i], h.angle[i], h.speed[i]};
    for (Index c = 0; c < means.cols(); ++c) row.push_back(means(static_cast<Index>(i), c));
    rows.push_back(std::move(row));
  }
  o.tables.emplace("histories", table_from_rows("histories", cols, rows));
}

// Samples of the steady phase: the whole run at constant speed, after the ramp of a spin-up.
Index steady_start(const ffrf::FfrfHistory& h, const RotatingSpec& spec) {
  if (spec.profile != RotatingSpec::Profile::spin_up) return 0;
  const auto it = std::lower_bound(h.time.begin(), h.time.end(), spec.spin_up_time);
  return static_cast<Index>(it - h.time.begin());
}

// deflection: per set, the mean over the steady phase, half its peak-to-peak range, the static
// solution of the same model (spin softening, and stiffening when on) and the linear one K u = Omega^2 f_c.
void add_deflection_table(RotatingOutcome& o, const Model& model, const RotatingSpec& spec,
                          const ffrf::RotatingBody& body, const Eigen::MatrixXd& means) {
  const double speed = steady_speed(spec);
  const ffrf::StaticDeflection full = ffrf::centrifugal_deflection(body, speed, {.stiffening = spec.stiffening});
  SpdFactorization k;
  if (!k.factorize(body.stiffness).ok)
    throw SolverError("rotating analysis: K could not be factorized for the linear deflection");
  const Eigen::VectorXd linear = k.solve(Eigen::VectorXd(speed * speed * body.centrifugal_load));
  const Eigen::VectorXd s_full = static_means(model, spec, body, full.displacement);
  const Eigen::VectorXd s_linear = static_means(model, spec, body, linear);
  const Index first = std::min<Index>(steady_start(o.history, spec), std::max<Index>(means.rows() - 1, 0));
  const Eigen::MatrixXd steady = means.bottomRows(means.rows() - first);
  std::vector<std::string> cols = {"set_number"};
  for (const char* q : {"mean", "static", "linear", "amplitude"})
    for (int d = 0; d < o.dim; ++d) cols.push_back(fmt::format("{}_u{}_m", q, axis_name(d)));
  std::vector<std::vector<double>> rows;
  for (size_t s = 0; s < spec.histories.size(); ++s) {
    std::vector<double> row = {static_cast<double>(s + 1)};
    const Index c0 = static_cast<Index>(s) * o.dim;
    for (int d = 0; d < o.dim; ++d) row.push_back(steady.rows() > 0 ? steady.col(c0 + d).mean() : kNan);
    for (int d = 0; d < o.dim; ++d) row.push_back(s_full[c0 + d]);
    for (int d = 0; d < o.dim; ++d) row.push_back(s_linear[c0 + d]);
    for (int d = 0; d < o.dim; ++d)
      row.push_back(steady.rows() > 0 ? 0.5 * (steady.col(c0 + d).maxCoeff() - steady.col(c0 + d).minCoeff()) : kNan);
    rows.push_back(std::move(row));
  }
  ResultTable t = table_from_rows("deflection", cols, rows);
  t.add_text_column("set", spec.histories);
  o.tables.emplace("deflection", std::move(t));
  // The stresses of the steady deflection (the centrifugal stresses in the rotating frame, those
  // that stiffen the blade): the same recovery as a static analysis's.
  const Eigen::VectorXd all = ffrf::expand_to_global(body, full.displacement);
  const Eigen::MatrixXd nodal = Eigen::Map<const Eigen::MatrixXd>(all.data(), o.dim, model.mesh.n_nodes()).transpose();
  o.steady_stresses = recover_stresses(model.mesh, model.section, nodal);
  o.tables.emplace("steady_stresses", nodal_stress_table("steady_stresses", model.mesh, o.steady_stresses));
}

// oscillation: for each mode at the run's speed, the spectral peak of the history component that
// carries it most within +-3 % of the mode's frequency (the free vibration a sudden start leaves).
void add_oscillation_table(RotatingOutcome& o, const RotatingSpec& spec, const Eigen::MatrixXd& means) {
  const Index first = steady_start(o.history, spec);
  const Index n = means.rows() - first;
  if (n < 64 || o.history.time.size() < 2 || means.cols() == 0) return;  // no history recorded: nothing to measure
  const double dt = (o.history.time.back() - o.history.time[static_cast<size_t>(first)]) / static_cast<double>(n - 1);
  std::vector<AmplitudeSpectrum> spectra;
  for (Index c = 0; c < means.cols(); ++c) spectra.emplace_back(means.col(c).tail(n), dt);
  // A mode counts as excited when its peak stands above a millionth of the largest motion recorded.
  double largest = 0.0;
  for (Index c = 0; c < means.cols(); ++c) largest = std::max(largest, means.col(c).tail(n).array().abs().maxCoeff());
  std::vector<std::vector<double>> rows;
  std::vector<std::string> where, component;
  const Eigen::VectorXd& modes = o.modes_at_speed.frequencies_hz;
  for (Index m = 0; m < modes.size(); ++m) {
    const double f = modes[m];
    if (!(f > 0.0)) continue;
    // Search within +-3 %, and never past halfway to a neighbouring mode (each peak is one mode's).
    const double lo = m > 0 ? std::max(0.97 * f, 0.5 * (f + modes[m - 1])) : 0.97 * f;
    const double hi = m + 1 < modes.size() ? std::min(1.03 * f, 0.5 * (f + modes[m + 1])) : 1.03 * f;
    SpectralPeak best{kNan, 0.0};
    Index best_column = 0;
    for (Index c = 0; c < means.cols(); ++c) {
      const SpectralPeak p = spectra[static_cast<size_t>(c)].peak(lo, hi);
      if (std::isfinite(p.frequency_hz) && p.amplitude > best.amplitude) best = p, best_column = c;
    }
    if (!(best.amplitude > 1e-6 * largest)) best = {kNan, best.amplitude};
    rows.push_back({static_cast<double>(m + 1), f, best.frequency_hz, best.amplitude});
    where.push_back(spec.histories[static_cast<size_t>(best_column / o.dim)]);
    component.push_back(fmt::format("u{}", axis_name(static_cast<int>(best_column % o.dim))));
  }
  ResultTable t = table_from_rows("oscillation", {"mode", "modal_hz", "measured_hz", "amplitude_m"}, rows);
  t.add_text_column("set", where);
  t.add_text_column("component", component);
  o.tables.emplace("oscillation", std::move(t));
}

// energy: the work-energy balance of the run, relative to the largest strain energy (the elastic
// energy scale; the rotor's 1/2 J Omega^2 would hide any error in the elastic motion).
void add_energy_table(RotatingOutcome& o) {
  const ffrf::FfrfHistory& h = o.history;
  if (h.time.empty()) return;
  const double kinetic = *std::max_element(h.kinetic_energy.begin(), h.kinetic_energy.end());
  const double strain = std::max(*std::max_element(h.strain_energy.begin(), h.strain_energy.end()), 1e-300);
  const double error = h.energy_balance_error();
  o.tables.emplace("energy",
                   table_from_rows("energy",
                                   {"run", "max_kinetic_j", "max_strain_j", "driving_work_j", "gravity_work_j",
                                    "balance_error_j", "relative_error", "final_angular_momentum"},
                                   {{1.0, kinetic, strain, h.driving_work.back(), h.gravity_work.back(), error,
                                     error / strain, h.angular_momentum.back()}}));
}

void add_campbell_tables(RotatingOutcome& o, const ffrf::ProjectedBody& projected, const RotatingSpec& spec,
                         const ffrf::RotatingModesOptions& options) {
  std::vector<double> speeds = spec.campbell_speeds;
  if (speeds.empty())
    for (int i = 0; i <= 10; ++i) speeds.push_back(steady_speed(spec) * i / 10.0);
  o.campbell = ffrf::campbell_diagram(projected, speeds, options);
  o.crossings = ffrf::engine_order_crossings(projected, o.campbell, spec.engine_orders, options);
  std::vector<std::vector<double>> rows;
  for (Index i = 0; i < o.campbell.frequencies_hz.rows(); ++i)
    for (Index m = 0; m < o.campbell.frequencies_hz.cols(); ++m)
      rows.push_back({static_cast<double>(rows.size() + 1), o.campbell.speeds[static_cast<size_t>(i)],
                      static_cast<double>(m + 1), o.campbell.frequencies_hz(i, m)});
  o.tables.emplace("campbell", table_from_rows("campbell", {"point", "omega_rad_s", "mode", "frequency_hz"}, rows));
  std::vector<std::vector<double>> crossing_rows;
  for (const ffrf::EngineOrderCrossing& c : o.crossings)
    crossing_rows.push_back({static_cast<double>(crossing_rows.size() + 1), static_cast<double>(c.engine_order),
                             static_cast<double>(c.mode), c.speed, c.speed * 60.0 / kTwoPi, c.frequency_hz});
  o.tables.emplace(
      "crossings",
      table_from_rows("crossings", {"crossing", "engine_order", "mode", "speed_rad_s", "speed_rpm", "frequency_hz"},
                      crossing_rows));
  const ffrf::RotatingModes rest = ffrf::rotating_modes(projected, 0.0, options);
  std::vector<std::vector<double>> mode_rows;
  for (Index m = 0; m < o.modes_at_speed.frequencies_hz.size(); ++m)
    mode_rows.push_back({static_cast<double>(m + 1), m < rest.frequencies_hz.size() ? rest.frequencies_hz[m] : kNan,
                         o.modes_at_speed.frequencies_hz[m], o.modes_at_speed.growth_rates[m]});
  o.tables.emplace(
      "rotating_modes",
      table_from_rows("rotating_modes", {"mode", "rest_hz", "frequency_hz", "growth_rate_1_s"}, mode_rows));
}

// stiffening: the run as specified and with the stiffening switched, each to its end or to the
// time its divergence stops it; per variant the largest |u| of every history component, and the
// speed at which its static operator turns singular (the spin-softening divergence).
void add_stiffening_table(RotatingOutcome& o, const Model& model, const RotatingSpec& spec,
                          const ffrf::ProjectedBody& projected, const ffrf::RotationProfile& profile,
                          const ffrf::FfrfOptions& options) {
  std::vector<std::string> cols = {"variant", "stiffening", "diverged", "end_time_s", "divergence_speed_rad_s"};
  for (const std::string& s : spec.histories)
    for (int d = 0; d < o.dim; ++d) cols.push_back(fmt::format("max_abs_{}.u{}_m", s, axis_name(d)));
  std::vector<std::vector<double>> rows;
  std::vector<std::string> notes;
  for (const bool stiffening : {spec.stiffening, !spec.stiffening}) {
    const double divergence = ffrf::divergence_speed(projected, stiffening);
    std::vector<double> row = {static_cast<double>(rows.size() + 1), stiffening ? 1.0 : 0.0};
    Eigen::MatrixXd means;
    if (stiffening == spec.stiffening) {
      means = o.set_histories;
      row.insert(row.end(), {0.0, o.history.time.back()});
      notes.emplace_back("reached the end");
    } else {
      ffrf::FfrfOptions other = options;
      other.stiffening = stiffening;
      try {
        const ffrf::FfrfHistory h = ffrf::integrate(projected, profile, other);
        means = set_means(model, spec, h.displacement);
        row.insert(row.end(), {0.0, h.time.back()});
        notes.emplace_back("reached the end");
      } catch (const ffrf::DivergenceError& e) {
        // The divergence is the finding: when it stopped the run.
        row.insert(row.end(), {1.0, e.time()});
        notes.emplace_back(e.what());
      }
    }
    row.push_back(std::isfinite(divergence) ? divergence : kNan);
    for (Index c = 0; c < static_cast<Index>(spec.histories.size()) * o.dim; ++c)
      row.push_back(means.rows() > 0 ? means.col(c).cwiseAbs().maxCoeff() : kNan);
    rows.push_back(std::move(row));
  }
  ResultTable t = table_from_rows("stiffening", cols, rows);
  t.add_text_column("outcome", notes);
  o.tables.emplace("stiffening", std::move(t));
}

// The integration's steps, known once the time step is: each step a few dense solves of the basis
// size, and a row of every recorded history (the statistics use every step).
WorkEstimate step_work(const RotatingSpec& spec, double time_step, Index basis_size, size_t recorded_dofs) {
  const double steps = std::ceil(spec.end_time / time_step);
  const double n = static_cast<double>(basis_size) + 1.0;
  WorkEstimate e;
  e.operations = steps * 30.0 * n * n;
  e.bytes = steps * (static_cast<double>(recorded_dofs) + 12.0) * 8.0;
  e.basis =
      fmt::format("{:.3g} steps of {:.3g} s{} over {} s, {} elastic coordinates", steps, time_step,
                  spec.time_step > 0 ? "" : " (40 per period of the lowest rotating mode)", spec.end_time, basis_size);
  e.at = spec.at;
  e.key = spec.time_step > 0 ? "analysis.end_time_s, time_step_s" : "analysis.end_time_s";
  if (steps > kMaxRotatingSteps)  // the limit the parser holds a given step to, for the automatic one
    throw InputError(
        fmt::format("{}: '{}': {} exceed the limit of {:.0e} steps: shorten end_time_s or give a larger "
                    "time_step_s",
                    e.at.where(), e.key, e.basis, kMaxRotatingSteps));
  return e;
}

}  // namespace

AmplitudeSpectrum::AmplitudeSpectrum(const Eigen::VectorXd& signal, double dt) {
  const Index n = signal.size();
  Index padded = 1;
  while (padded < 4 * n) padded *= 2;  // 4x zero padding: bins a quarter of the record's resolution
  std::vector<double> x(static_cast<size_t>(padded), 0.0);
  const double mean = signal.mean();
  for (Index i = 0; i < n; ++i)
    x[static_cast<size_t>(i)] =
        (signal[i] - mean) * (0.5 - 0.5 * std::cos(kTwoPi * static_cast<double>(i) / static_cast<double>(n - 1)));
  std::vector<std::complex<double>> spectrum;
  Eigen::FFT<double> fft;
  fft.fwd(spectrum, x);
  amplitude_.resize(padded / 2);
  // A sinusoid of amplitude A gives |X| = A n / 4 under the Hann window.
  for (Index k = 0; k < padded / 2; ++k)
    amplitude_[k] = 4.0 * std::abs(spectrum[static_cast<size_t>(k)]) / static_cast<double>(n);
  df_ = 1.0 / (static_cast<double>(padded) * dt);
}

SpectralPeak AmplitudeSpectrum::peak(double f_lo, double f_hi) const {
  const Index lo = std::max<Index>(static_cast<Index>(std::ceil(f_lo / df_)), 1);
  const Index hi = std::min<Index>(static_cast<Index>(std::floor(f_hi / df_)), amplitude_.size() - 2);
  if (hi - lo < 2) return {kNan, 0.0};
  Index k = 0;
  amplitude_.segment(lo, hi - lo + 1).maxCoeff(&k);
  k += lo;
  if (k == lo || k == hi) return {kNan, 0.0};
  const double y0 = amplitude_[k - 1], y1 = amplitude_[k], y2 = amplitude_[k + 1];
  const double shift = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2);
  return {(static_cast<double>(k) + shift) * df_, y1 - 0.25 * (y0 - y2) * shift};
}

RotatingOutcome run_rotating(const Model& model, const RotatingSpec& spec, const WorkLimits& limits) {
  RotatingOutcome o;
  o.dim = model.mesh.dim;
  o.history_sets = spec.histories;
  const auto t0 = Clock::now();
  const std::vector<int> dofs = history_dofs(model, spec);
  const ffrf::RotatingBody body = ffrf::build_rotating_body(model, {spec.axis_direction, spec.axis_point});
  const ffrf::ElasticBasis basis = [&] {
    try {
      return ffrf::make_elastic_basis(
          body, spec.modal_basis ? ffrf::ElasticBasisOptions{ffrf::BasisKind::modal, spec.basis_modes, {}, true}
                                 : ffrf::ElasticBasisOptions{});
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: 'analysis.basis_modes': {}", spec.at.where(), e.what()));
    }
  }();
  const ffrf::ProjectedBody projected = ffrf::project(body, basis);
  // The rotating modes always come from a modal basis (dense eigenproblem), large enough that the
  // reported ones are converged.
  const int modal_size = std::min(std::max(spec.basis_modes, 2 * spec.campbell_modes + 4), body.n_free() - 1);
  const ffrf::ElasticBasis modal = ffrf::make_elastic_basis(body, {ffrf::BasisKind::modal, modal_size, {}, true});
  const ffrf::ProjectedBody modal_body = ffrf::project(body, modal);
  const ffrf::RotatingModesOptions mode_options{
      .n_modes = spec.campbell_modes, .stiffening = spec.stiffening, .coriolis = spec.coriolis};
  o.free_dofs = body.n_free();
  o.basis_size = basis.size();
  o.modes_at_speed = ffrf::rotating_modes(modal_body, steady_speed(spec), mode_options);
  o.time_step = spec.time_step > 0 ? spec.time_step
                                   : ffrf::time_step_resolving(modal_body, steady_speed(spec), 1, 40, mode_options);
  o.setup_seconds = seconds_since(t0);
  require_within(step_work(spec, o.time_step, basis.size(), dofs.size()), limits);

  const ffrf::RotationProfile profile = profile_of(spec);
  o.profile = profile.describe();
  ffrf::FfrfOptions options;
  options.time_step = o.time_step;
  options.end_time = spec.end_time;
  options.rho_infinity = spec.rho_infinity;
  options.stiffening = spec.stiffening;
  options.coriolis = spec.coriolis;
  options.rotor_inertia = spec.rotor_inertia;
  options.gravity = spec.gravity;
  options.output_dofs = dofs;
  const auto t1 = Clock::now();
  o.history = ffrf::integrate(projected, profile, options);
  o.run_seconds = seconds_since(t1);

  o.set_histories = set_means(model, spec, o.history.displacement);
  const Eigen::MatrixXd& means = o.set_histories;
  add_history_table(o, spec, means);
  add_deflection_table(o, model, spec, body, means);
  add_energy_table(o);
  const auto t2 = Clock::now();
  add_campbell_tables(o, modal_body, spec, mode_options);
  o.campbell_seconds = seconds_since(t2);
  add_oscillation_table(o, spec, means);
  if (spec.compare_stiffening) add_stiffening_table(o, model, spec, projected, profile, options);
  const double steps = std::max(1.0, static_cast<double>(o.history.steps));
  o.tables.emplace(
      "rotating_cost",
      table_from_rows("rotating_cost",
                      {"run", "free_dofs", "basis_size", "time_step_s", "steps", "factorizations", "setup_s",
                       "integration_s", "campbell_s", "us_per_step"},
                      {{1.0, static_cast<double>(o.free_dofs), static_cast<double>(o.basis_size), o.time_step,
                        static_cast<double>(o.history.steps), static_cast<double>(o.history.factorizations),
                        o.setup_seconds, o.run_seconds, o.campbell_seconds, 1e6 * o.run_seconds / steps}}));
  return o;
}

}  // namespace bb
