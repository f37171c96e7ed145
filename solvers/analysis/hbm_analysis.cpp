#include "analysis/hbm_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "analysis/frf_analysis.hpp"
#include "analysis/modal_analysis.hpp"
#include "common/errors.hpp"
#include "frf/receptance.hpp"
#include "frf/sweep.hpp"
#include "hbm/sensitivity.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;
constexpr double kTwoPi = 2 * std::numbers::pi;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Coordinates of a one-node set.
std::array<double, 2> point_position(const Model& model, const std::string& point) {
  const auto it = model.node_sets.find(point);
  if (it == model.node_sets.end() || it->second.size() != 1)
    throw InputError(fmt::format("'analysis.damper': '{}' is not a one-node set of the mesh; give the point's 'position'", point));
  const auto x = model.mesh.coords.row(it->second.front());
  return {x[0], x[1]};
}

damper::RigidDamper build_damper(const Model& model, const DamperSpec& spec, const ReducedModel& blades) {
  damper::RigidDamper d;
  d.mass = spec.mass;
  d.inertia = spec.inertia;
  for (const DamperPointSpec& p : spec.points) {
    damper::DamperContact c;
    c.name = p.name;
    const std::array<double, 2> at = p.position ? *p.position : point_position(model, p.point);
    c.position = Eigen::Vector2d(at[0] - spec.centre[0], at[1] - spec.centre[1]);
    c.normal = p.left_face ? damper::left_face_normal(spec.left_face_deg) : damper::right_face_normal(spec.right_face_deg);
    if (!p.point.empty()) std::tie(c.blade_x, c.blade_y) = damper::platform_dofs(blades, p.point);
    d.contacts.push_back(c);
  }
  try {
    damper::validate(d, blades.size());
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("'analysis.damper': {}", e.what()));
  }
  return d;
}

// Model DOF of a named DOF: the linear model's, or "damper.x" / "damper.y" after them.
Index dof_index(const PreparedHbm& p, const ReducedModel& blades, const PointDof& dof, const std::string& where) {
  if (p.damper && dof.point == "damper" && dof.direction < 2) return p.blade_dofs + dof.direction;
  const auto i = blades.index_of(dof.point, dof.direction);
  if (!i) throw InputError(fmt::format("{}: the model has no DOF {}", where, dof.name()));
  return *i;
}

Eigen::RowVectorXd combination_row(const PreparedHbm& p, const ReducedModel& blades, const std::vector<std::pair<PointDof, double>>& terms,
                                   Index n, const std::string& where) {
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
  for (const auto& [dof, c] : terms) row[dof_index(p, blades, dof, where)] += c;
  return row;
}

// First-harmonic complex amplitude of each model DOF (Re(Z e^{i theta}) = a cos + b sin).
Eigen::VectorXcd first_harmonic(const hbm::HarmonicBalance& system, const Eigen::VectorXd& x, double omega) {
  const Eigen::MatrixXd q = system.recover(x, omega);
  return q.col(1).cast<std::complex<double>>() - std::complex<double>(0.0, 1.0) * q.col(2).cast<std::complex<double>>();
}

struct PeakValues {
  double component = 0.0, amplitude = 0.0;
};

PeakValues peak_values(const PreparedHbm& p, const Eigen::VectorXcd& z, int kind) {
  if (!p.ip_oop) return {std::abs(z[p.responses.front()]), std::abs(z[p.responses.front()])};
  const auto [l, r] = *p.ip_oop;
  const double c = kind == 0 ? std::abs(z[l] + z[r]) / 2 : std::abs(z[r] - z[l]) / 2;
  return {c, std::abs(z[r])};
}

// The peak of `kind` (0 in-phase, 1 out-of-phase, or the first response) along the path, refined
// by golden-section search between the path's neighbours of the largest point (where the path does
// not fold there), each trial a Newton solve from the nearest path point.
HbmPeak find_peak(const PreparedHbm& p, const hbm::HarmonicBalance& system, const HbmLevel& level, int kind) {
  const auto& pts = level.path.points;
  const Eigen::VectorXd values = p.ip_oop ? level.components.col(kind) : level.amplitude.col(0);
  Index k = 0;
  values.maxCoeff(&k);
  HbmPeak peak;
  peak.kind = p.ip_oop ? (kind == 0 ? "IP" : "OOP") : "peak";
  auto solve = [&](double omega) {
    size_t nearest = 0;
    for (size_t i = 1; i < pts.size(); ++i)
      if (std::abs(pts[i].omega - omega) < std::abs(pts[nearest].omega - omega)) nearest = i;
    return hbm::solve_at_frequency(system, omega, pts[nearest].x);
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
      const GoldenSearch search = golden_section_maximum(component, a, b, 14);
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
  const double above = pts[static_cast<size_t>(std::min<Index>(k + 1, static_cast<Index>(pts.size()) - 1))].omega / kTwoPi;
  for (double f : level.failed_hz)
    if (f > std::min(below, above) && f < std::max(below, above)) {
      peak.trusted = false;
      peak.doubt = fmt::format("the sweep did not converge at {:.4f} Hz, next to the maximum at {:.4f} Hz", f, peak.frequency_hz);
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
  }
  return peak;
}

}  // namespace

std::string hbm_frf_table_name(double force) { return fmt::format("frf_{:g}", force); }


Eigen::MatrixXd stuck_stiffness(const hbm::HbmModel& model) {
  Eigen::MatrixXd k = model.stiffness;
  for (const hbm::ContactElement& c : model.contacts)
    k += c.law.kn * c.normal.transpose() * c.normal + c.law.kt * c.tangential.transpose() * c.tangential;
  return k;
}

PreparedHbm prepare_hbm(const Model& model, const HbmSpec& spec) {
  const auto t0 = Clock::now();
  PreparedHbm p;
  FreeSystem system;
  if (!spec.model.masters.empty()) system = assemble_free_system(model);
  p.linear = build_reduced_model(model, system, spec.model, &p.timing);
  const ReducedModel& blades = p.linear;
  p.blade_dofs = blades.size();
  for (const ReducedDof& d : blades.dofs) p.dof_names.push_back(d.name());
  {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(blades.stiffness, blades.mass, Eigen::EigenvaluesOnly);
    p.linear_frequencies_hz = eig.eigenvalues().array().max(0.0).sqrt() / kTwoPi;
  }
  const Eigen::MatrixXd blade_damping = spec.damping_matrix ? *spec.damping_matrix : damping_matrix(spec.damping, blades);
  hbm::HbmModel& m = p.model;
  if (spec.damper) {
    p.damper = build_damper(model, *spec.damper, blades);
    p.centrifugal_force = spec.damper->centrifugal_force;
    const damper::CoupledSystem coupled = damper::assemble_coupled_system(blades.mass, blades.stiffness, *p.damper);
    m.mass = coupled.mass;
    m.stiffness = coupled.stiffness;
    for (const char* n : {"damper.x", "damper.y", "damper.theta"}) p.dof_names.push_back(n);
  } else {
    m.mass = blades.mass;
    m.stiffness = blades.stiffness;
  }
  const Index n = m.mass.rows();
  m.damping = Eigen::MatrixXd::Zero(n, n);
  m.damping.topLeftCorner(p.blade_dofs, p.blade_dofs) = blade_damping;  // the rigid damper has none of its own
  m.static_load = Eigen::VectorXd::Zero(n);
  const std::string in_analysis = spec.at.where() + ": 'analysis'";
  for (const auto& [dof, f] : spec.static_loads) m.static_load[dof_index(p, blades, dof, in_analysis + " static_loads")] += f;
  if (spec.damper) {
    const damper::ContactKinematics kin = damper::contact_kinematics(*p.damper, p.blade_dofs);
    contact::JenkinsParameters law = spec.damper->law;
    law.n0 = 0.0;  // contacts just touch at q = 0; CF loads them through the static balance
    for (size_t c = 0; c < p.damper->contacts.size(); ++c) {
      m.contacts.push_back({law, kin.tangential.row(static_cast<Index>(c)), kin.normal.row(static_cast<Index>(c))});
      p.contact_names.push_back(p.damper->contacts[c].name);
    }
    m.static_load += damper::centrifugal_load(p.blade_dofs, spec.damper->centrifugal_force);
    damper::DamperStaticOptions options;
    options.kn = law.kn;
    p.damper_static = damper::solve_damper_static(blades.stiffness, *p.damper, m.static_load, options);
    if (!p.damper_static->converged)
      throw InputError(fmt::format("'analysis.damper': the static pre-solve (CF = {} N) has no equilibrium: {}",
                                   spec.damper->centrifugal_force, p.damper_static->failure));
    // The damper seats without friction (eq 3.49): each slider rests where its contact came to rest.
    for (hbm::ContactElement& c : m.contacts) c.tangential_offset = c.tangential.dot(p.damper_static->q);
  }
  for (const HbmContactSpec& c : spec.contacts) {
    const std::string where = fmt::format("{}: contact '{}'", c.at.where(), c.name);
    m.contacts.push_back({c.law, combination_row(p, blades, c.tangential, n, where),
                          c.normal.empty() ? Eigen::RowVectorXd::Zero(n) : combination_row(p, blades, c.normal, n, where)});
    p.contact_names.push_back(c.name);
  }
  m.harmonic_load = Eigen::VectorXcd::Zero(n);
  for (const FrfForce& f : spec.forces) m.harmonic_load[dof_index(p, blades, f.dof, in_analysis + " forces")] += f.amplitude / spec.forces.front().amplitude;
  for (const PointDof& r : spec.responses) {
    p.responses.push_back(dof_index(p, blades, r, in_analysis + " responses"));
    p.response_names.push_back(r.name());
  }
  if (spec.ip_oop)
    p.ip_oop.emplace(dof_index(p, blades, spec.ip_oop->first, in_analysis + " ip_oop"), dof_index(p, blades, spec.ip_oop->second, in_analysis + " ip_oop"));
  if (!m.contacts.empty()) {  // a time integration may run the linear model alone
    try {
      const hbm::HarmonicBalance check(m, {});  // sizes, contact laws and a nonsingular non-contact part
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("'analysis': {}", e.what()));
    }
  }
  p.setup_seconds = seconds_since(t0);
  return p;
}

namespace {

hbm::HarmonicBalance level_system(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics) {
  hbm::HbmModel m = p.model;
  m.harmonic_load *= force;
  hbm::HbmOptions options;
  options.harmonics = harmonics;
  options.aft.samples = spec.time_samples;
  options.tolerance = spec.tolerance;
  options.max_iterations = spec.max_iterations;
  return hbm::HarmonicBalance(std::move(m), options);
}

// The first frequency's solution. Direct Newton from the static pre-solve (or the linear limits)
// first; when that fails, a homotopy in the force: from 1/64 of it, each converged fraction the
// start of the next, the increment halved on failure.
hbm::HbmSolution first_solution(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics, double omega,
                                const std::optional<Eigen::VectorXd>& initial) {
  const hbm::HarmonicBalance system = level_system(p, spec, force, harmonics);
  hbm::HbmSolution direct = hbm::solve_at_frequency(system, omega, initial);
  if (direct.converged) return direct;
  double done = 1.0 / 64, step = 1.0 / 64;
  hbm::HbmSolution at = hbm::solve_at_frequency(level_system(p, spec, force * done, harmonics), omega, initial);
  int total = direct.iterations + at.iterations;
  while (at.converged && done < 1.0 && step >= 1.0 / 4096) {
    const double next = std::min(1.0, done + step);
    hbm::HbmSolution trial = hbm::solve_at_frequency(level_system(p, spec, force * next, harmonics), omega, at.x);
    total += trial.iterations;
    if (trial.converged) {
      at = std::move(trial), done = next, step *= 2;
    } else {
      step /= 2;
    }
  }
  if (at.converged && done == 1.0) {
    at.iterations = total;
    return at;
  }
  direct.failure += fmt::format("; force homotopy reached {:.4g} of the force", at.converged ? done : 0.0);
  return direct;
}

// d(model)/d(log p) for each of spec.sensitivities: scaling a unit derivative by the parameter's
// value turns d/dp into d/d(log p). The damper's contacts come first in the model.
std::vector<hbm::ModelDerivative> log_derivatives(const PreparedHbm& p, const HbmSpec& spec, const hbm::HbmModel& m) {
  const size_t damper_contacts = p.damper ? p.damper->contacts.size() : 0;
  std::vector<hbm::ModelDerivative> out;
  for (const HbmParameter& parameter : spec.sensitivities) {
    if (parameter.kind == HbmParameter::Kind::modal_damping) {  // C = zeta C1: dC/d(log zeta) = C
      out.push_back(hbm::damping_scale_derivative(m));
      continue;
    }
    const bool damper = parameter.kind == HbmParameter::Kind::damper_law;
    const size_t first = damper ? 0 : damper_contacts + parameter.contact;
    const size_t last = damper ? damper_contacts : first + 1;
    hbm::ModelDerivative d;
    d.laws.assign(m.contacts.size(), {});
    for (size_t k = first; k < last; ++k) {
      const contact::JenkinsParameters& law = m.contacts[k].law;
      contact::JenkinsParameters& dl = d.laws[k];
      switch (parameter.law) {
        case contact::law_kn: dl.kn = law.kn; break;
        case contact::law_kt: dl.kt = law.kt; break;
        case contact::law_mu: dl.mu = law.mu; break;
        case contact::law_n0: dl.n0 = law.n0; break;
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

// Fills level.amplitude_dlog and phase_dlog_deg from the converged path points: with z the
// first-harmonic amplitude (Z = a1 - i b1), d|z| = Re(conj z dz) / |z| and d arg z = Im(conj z dz) / |z|^2.
void add_sensitivities(const PreparedHbm& p, const HbmSpec& spec, const hbm::HarmonicBalance& system, HbmLevel& level) {
  const std::vector<hbm::ModelDerivative> derivatives = log_derivatives(p, spec, system.model());
  const Index n_points = static_cast<Index>(level.path.points.size()), n_resp = static_cast<Index>(p.responses.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  level.amplitude_dlog.assign(derivatives.size(), Eigen::MatrixXd::Constant(n_points, n_resp, nan));
  level.phase_dlog_deg.assign(derivatives.size(), Eigen::MatrixXd::Constant(n_points, n_resp, nan));
  for (Index i = 0; i < n_points; ++i) {
    const hbm::ContinuationPoint& pt = level.path.points[static_cast<size_t>(i)];
    hbm::HbmSolution s;
    s.x = pt.x;
    s.omega = pt.omega;
    s.converged = true;  // every point of the path is a converged solve
    std::vector<Eigen::MatrixXd> dq;
    try {
      dq = hbm::response_sensitivity(system, s, derivatives);
    } catch (const std::exception&) {
      continue;  // a singular Jacobian (e.g. a free static position): no derivative, NaN
    }
    const Eigen::VectorXcd z = first_harmonic(system, pt.x, pt.omega);
    for (size_t j = 0; j < dq.size(); ++j)
      for (Index r = 0; r < n_resp; ++r) {
        const Index dof = p.responses[static_cast<size_t>(r)];
        const std::complex<double> zr = z[dof], dz(dq[j](dof, 1), -dq[j](dof, 2));
        const double a2 = std::norm(zr);
        if (!(a2 > 0.0)) continue;
        level.amplitude_dlog[j](i, r) = (std::conj(zr) * dz).real() / std::sqrt(a2);
        level.phase_dlog_deg[j](i, r) = (std::conj(zr) * dz).imag() / a2 * 180.0 / std::numbers::pi;
      }
  }
}

}  // namespace

HbmLevel sweep_hbm_level(const PreparedHbm& p, const HbmSpec& spec, double force, int harmonics, const HbmProgress& progress) {
  const auto t0 = Clock::now();
  HbmLevel level;
  level.force = force;
  const hbm::HarmonicBalance system = level_system(p, spec, force, harmonics);
  const double omega_start = kTwoPi * spec.sweep.f_min, omega_end = kTwoPi * spec.sweep.f_max;
  std::optional<Eigen::VectorXd> initial;
  if (p.damper_static) {
    // Start from the static pre-solve: the damper seated by CF, the vibration of the stuck limit.
    initial = system.linearized(omega_start, true);
    if (initial) {
      const auto& dofs = system.contact_dofs();
      for (size_t i = 0; i < dofs.size(); ++i) (*initial)[static_cast<Index>(i)] = p.damper_static->q[dofs[i]];
    }
  }
  const hbm::HbmSolution first = first_solution(p, spec, force, harmonics, omega_start, initial);
  hbm::ContinuationResult& path = level.path;
  auto report = [&](double omega, int point, int iterations) {
    if (progress && point % 25 == 0)
      progress(fmt::format("Fe = {:g} N, H = {}: {:.3f} Hz, point {}, {} iterations", force, harmonics, omega / kTwoPi, point, iterations));
  };
  if (!first.converged) {
    path.failure = "first point: " + first.failure;
  } else if (spec.sweep.method == HbmSweepSpec::Method::arclength) {
    hbm::ContinuationOptions c;
    c.omega_start = omega_start;
    c.omega_end = omega_end;
    c.initial_step = spec.sweep.initial_step;
    c.max_step = spec.sweep.max_step;
    c.min_step = spec.sweep.min_step;
    c.max_points = 20000;
    c.initial = first.x;
    c.progress = [&](const hbm::ContinuationProgress& s) { report(s.omega, s.point, s.iterations); };
    path = hbm::continue_in_frequency(system, c);
  } else {
    // Grid: every frequency solved from the secant extrapolation of the last two converged points.
    const std::vector<double> grid = fixed_grid(spec.sweep.f_min, spec.sweep.f_max, spec.sweep.step_hz);
    const int n = static_cast<int>(grid.size());
    path.points.push_back({first.omega, first.x, first.residual, first.iterations, 0.0, 1.0});
    path.corrector_iterations = first.iterations;
    std::vector<double> failed;
    std::string last_failure;
    for (int i = 1; i < n; ++i) {
      const double omega = kTwoPi * grid[static_cast<size_t>(i)];
      const auto& pts = path.points;
      Eigen::VectorXd guess = pts.back().x;
      if (pts.size() >= 2) {
        const auto& a = pts[pts.size() - 2];
        const auto& b = pts.back();
        guess += (b.x - a.x) * ((omega - b.omega) / (b.omega - a.omega));
      }
      hbm::HbmSolution s = hbm::solve_at_frequency(system, omega, guess);
      path.corrector_iterations += s.iterations;
      if (!s.converged) {
        // Approach it in smaller steps from the last converged point (a kink between the two).
        Eigen::VectorXd x = pts.back().x;
        const double w0 = pts.back().omega;
        for (int k = 1; k <= 8; ++k) {
          s = hbm::solve_at_frequency(system, w0 + (omega - w0) * k / 8.0, x);
          path.corrector_iterations += s.iterations;
          if (!s.converged) break;
          x = s.x;
        }
      }
      report(omega, i, s.iterations);
      if (!s.converged) {
        failed.push_back(omega / kTwoPi);
        level.failed_hz.push_back(omega / kTwoPi);
        last_failure = s.failure;
        ++path.rejected_steps;
        continue;
      }
      path.points.push_back({omega, std::move(s.x), s.residual, s.iterations, 0.0, 1.0});
    }
    path.converged = failed.empty();
    if (!failed.empty())
      path.failure = fmt::format("{} of {} frequencies did not converge (first at {:.4f} Hz, last at {:.4f} Hz; last: {})", failed.size(), n,
                                 failed.front(), failed.back(), last_failure);
  }
  const size_t n_points = path.points.size();
  level.amplitude.resize(static_cast<Index>(n_points), static_cast<Index>(p.responses.size()));
  level.phase_deg.resize(static_cast<Index>(n_points), static_cast<Index>(p.responses.size()));
  if (p.ip_oop) level.components.resize(static_cast<Index>(n_points), 2);
  for (size_t i = 0; i < n_points; ++i) {
    const hbm::ContinuationPoint& pt = path.points[i];
    level.frequency_hz.push_back(pt.omega / kTwoPi);
    const Eigen::VectorXcd z = first_harmonic(system, pt.x, pt.omega);
    for (size_t r = 0; r < p.responses.size(); ++r) {
      level.amplitude(static_cast<Index>(i), static_cast<Index>(r)) = std::abs(z[p.responses[r]]);
      level.phase_deg(static_cast<Index>(i), static_cast<Index>(r)) = std::arg(z[p.responses[r]]) * 180.0 / std::numbers::pi;
    }
    if (p.ip_oop)
      for (int k = 0; k < 2; ++k) level.components(static_cast<Index>(i), k) = peak_values(p, z, k).component;
  }
  if (!spec.sensitivities.empty()) add_sensitivities(p, spec, system, level);
  if (n_points > 0)
    for (int k = 0; k < (p.ip_oop ? 2 : 1); ++k) level.peaks.push_back(find_peak(p, system, level, k));
  level.seconds = seconds_since(t0);
  return level;
}

namespace {


// Energy the contact dissipates per cycle: T against u, u's coefficients from its samples (exact:
// u holds H harmonics and the AFT takes at least 2H + 1 samples).
double friction_work(const contact::AftResult& a) {
  const int h = contact::harmonics_of(a.tangential.size());
  return contact::cycle_work(a.tangential, contact::analysis_matrix(h, static_cast<int>(a.u.size())) * a.u);
}

}  // namespace

HbmOutcome run_hbm(const Model& model, const HbmSpec& spec, const HbmProgress& progress) {
  HbmOutcome o;
  o.prepared = prepare_hbm(model, spec);
  const PreparedHbm& p = o.prepared;
  const auto t0 = Clock::now();
  for (double f : spec.force_levels) o.levels.push_back(sweep_hbm_level(p, spec, f, spec.harmonics, progress));
  o.sweep_seconds = seconds_since(t0);
  for (const HbmLevel& level : o.levels) {
    if (level.path.points.empty())
      throw SolverError(fmt::format("harmonic balance at Fe = {:g} N found no solution: {}", level.force, level.path.failure));
    for (const HbmPeak& pk : level.peaks)
      if (!pk.solution.converged)
        throw SolverError(fmt::format("harmonic balance at Fe = {:g} N: the {} peak's solve did not converge ({}); no peak is reported",
                                      level.force, pk.kind, pk.solution.failure));
  }

  const double cf = spec.damper ? spec.damper->centrifugal_force : 0.0;
  // peaks, energy balance, contact states, cost
  std::vector<std::vector<double>> peak_rows, energy_rows, state_rows, cost_rows;
  std::vector<std::string> state_contacts, state_peaks;
  for (size_t l = 0; l < o.levels.size(); ++l) {
    const HbmLevel& level = o.levels[l];
    const double key = static_cast<double>(l + 1);
    std::vector<double> row = {key, level.force};
    if (spec.damper) row.push_back(cf / level.force);
    if (level.peaks.empty()) row.insert(row.end(), p.ip_oop ? 6 : 3, std::numeric_limits<double>::quiet_NaN());
    for (const HbmPeak& pk : level.peaks) {
      const bool ok = pk.solution.converged;
      const double nan = std::numeric_limits<double>::quiet_NaN();
      row.insert(row.end(), {ok ? pk.frequency_hz : nan, ok ? pk.amplitude : nan, ok ? pk.amplitude / level.force : nan});
      if (!ok) continue;
      const hbm::CycleEnergy& e = pk.energy;
      const size_t k = static_cast<size_t>(&pk - level.peaks.data());
      energy_rows.push_back({key * 10 + static_cast<double>(k + 1), level.force, pk.frequency_hz, e.excitation, e.viscous, e.friction,
                             e.normal, std::abs(e.excitation - e.viscous - e.friction - e.normal) / std::max(std::abs(e.excitation), 1e-300)});
      for (size_t c = 0; c < pk.solution.contacts.size(); ++c) {
        const contact::AftResult& a = pk.solution.contacts[c];
        double stick = 0, slip = 0, lift = 0;
        for (const contact::ContactState s : a.state) {
          if (s == contact::ContactState::stick) ++stick;
          else if (s == contact::ContactState::lift_off) ++lift;
          else ++slip;
        }
        const double nt = static_cast<double>(a.state.size());
        state_rows.push_back({key * 1000 + static_cast<double>(k + 1) * 100 + static_cast<double>(c + 1), level.force, pk.frequency_hz,
                              stick / nt, slip / nt, lift / nt, a.normal[0], a.n.minCoeff(), a.n.maxCoeff(),
                              friction_work(a)});
        state_contacts.push_back(p.contact_names[c]);
        state_peaks.push_back(pk.kind);
      }
    }
    row.push_back(level.path.converged ? 1.0 : 0.0);
    for (const HbmPeak& pk : level.peaks) row.push_back(pk.trusted ? 1.0 : 0.0);
    peak_rows.push_back(row);
    cost_rows.push_back({key, level.force, static_cast<double>(level.path.points.size()), static_cast<double>(level.path.corrector_iterations),
                         static_cast<double>(level.path.rejected_steps), static_cast<double>(level.path.turning_points),
                         static_cast<double>(level.path.jumps), level.path.converged ? 1.0 : 0.0, level.seconds});
  }
  std::vector<std::string> peak_columns = {"level", "fe_n"};
  if (spec.damper) peak_columns.push_back("cf_over_fe");
  const std::vector<std::string> kinds = p.ip_oop ? std::vector<std::string>{"ip", "oop"} : std::vector<std::string>{"peak"};
  for (const std::string& k : kinds)
    for (const char* s : {"_hz", "_amp_m", "_amp_per_n"}) peak_columns.push_back(k + s);
  peak_columns.push_back("reached_end");
  for (const std::string& k : kinds) peak_columns.push_back(k + "_trusted");
  o.tables.emplace("peaks", table_from_rows("peaks", peak_columns, peak_rows));
  o.tables.emplace("energy_balance", table_from_rows("energy_balance", {"peak", "fe_n", "frequency_hz", "excitation_j", "viscous_j", "friction_j",
                                                                   "normal_j", "relative_error"}, energy_rows));
  ResultTable states = table_from_rows("contact_states", {"key", "fe_n", "frequency_hz", "stick", "slip", "lift_off", "mean_normal_n",
                                                     "min_normal_n", "max_normal_n", "friction_work_j"}, state_rows);
  states.add_text_column("peak", state_peaks);
  states.add_text_column("contact", state_contacts);
  o.tables.emplace("contact_states", std::move(states));
  o.tables.emplace("sweep_cost", table_from_rows("sweep_cost", {"level", "fe_n", "points", "corrector_iterations", "rejected_steps",
                                                           "turning_points", "jumps", "reached_end", "seconds"}, cost_rows));
  // One FRF table per level: the path points in order.
  for (const HbmLevel& level : o.levels) {
    std::vector<std::string> cols = {"point", "frequency_hz"};
    for (const std::string& r : p.response_names) cols.push_back(r + "_amp_m");
    for (const std::string& r : p.response_names) cols.push_back(r + "_phase_deg");
    if (p.ip_oop) cols.insert(cols.end(), {"ip_component_m", "oop_component_m"});
    cols.insert(cols.end(), {"residual_n", "iterations"});
    for (const HbmParameter& parameter : spec.sensitivities)
      for (const char* q : {"_amp_m_dlog_", "_phase_deg_dlog_"})
        for (const std::string& r : p.response_names) cols.push_back(r + q + parameter.label);
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < level.path.points.size(); ++i) {
      std::vector<double> row = {static_cast<double>(i + 1), level.frequency_hz[i]};
      for (Index r = 0; r < level.amplitude.cols(); ++r) row.push_back(level.amplitude(static_cast<Index>(i), r));
      for (Index r = 0; r < level.phase_deg.cols(); ++r) row.push_back(level.phase_deg(static_cast<Index>(i), r));
      if (p.ip_oop) row.insert(row.end(), {level.components(static_cast<Index>(i), 0), level.components(static_cast<Index>(i), 1)});
      row.insert(row.end(), {level.path.points[i].residual, static_cast<double>(level.path.points[i].iterations)});
      for (size_t j = 0; j < level.amplitude_dlog.size(); ++j)
        for (const Eigen::MatrixXd* d : {&level.amplitude_dlog[j], &level.phase_dlog_deg[j]})
          for (Index r = 0; r < d->cols(); ++r) row.push_back((*d)(static_cast<Index>(i), r));
      rows.push_back(row);
    }
    const std::string name = hbm_frf_table_name(level.force);
    o.tables.emplace(name, table_from_rows(name, cols, rows));
  }
  // Linear limits per newton of the first force: the linear model alone (no damper or contacts)
  // and every contact stuck (kn on the normal, kt on the tangential direction, eq 3.51).
  {
    const hbm::HbmModel& m = p.model;
    const Index nb = p.blade_dofs;
    const Eigen::MatrixXd stuck = stuck_stiffness(m);
    // Limit 0: the linear model alone (the damper's DOFs left out); 1: every contact stuck.
    const auto limit_solve = [&](int l, double w) {
      return l == 0 ? direct_response(m.stiffness.topLeftCorner(nb, nb), m.damping.topLeftCorner(nb, nb), m.mass.topLeftCorner(nb, nb), w,
                                      m.harmonic_load.head(nb))
                    : direct_response(stuck, m.damping, m.mass, w, m.harmonic_load);
    };
    const int n_grid = 2001;
    o.limit_frequency_hz = Eigen::VectorXd::LinSpaced(n_grid, spec.sweep.f_min, spec.sweep.f_max);
    const Index nr = static_cast<Index>(p.responses.size()) + (p.ip_oop ? 2 : 0);
    o.free_response.resize(n_grid, nr);
    o.stuck_response.resize(n_grid, nr);
    auto outputs = [&](const Eigen::VectorXcd& z, Eigen::MatrixXd& into, Index i) {
      for (size_t r = 0; r < p.responses.size(); ++r) into(i, static_cast<Index>(r)) = p.responses[r] < z.size() ? std::abs(z[p.responses[r]]) : 0.0;
      if (p.ip_oop)
        for (int k = 0; k < 2; ++k) into(i, static_cast<Index>(p.responses.size()) + k) = peak_values(p, z, k).component;
    };
    for (Index i = 0; i < n_grid; ++i) {
      const double w = kTwoPi * o.limit_frequency_hz[i];
      outputs(limit_solve(0, w), o.free_response, i);
      outputs(limit_solve(1, w), o.stuck_response, i);
    }
    std::vector<std::string> cols = {"point", "frequency_hz"};
    for (const char* limit : {"free", "stuck"}) {
      for (const std::string& r : p.response_names) cols.push_back(fmt::format("{}_{}_amp_per_n", limit, r));
      if (p.ip_oop) cols.insert(cols.end(), {fmt::format("{}_ip_per_n", limit), fmt::format("{}_oop_per_n", limit)});
    }
    std::vector<std::vector<double>> rows;
    for (Index i = 0; i < n_grid; ++i) {
      std::vector<double> row = {static_cast<double>(i + 1), o.limit_frequency_hz[i]};
      for (const Eigen::MatrixXd* lim : {&o.free_response, &o.stuck_response})
        for (Index r = 0; r < nr; ++r) row.push_back((*lim)(i, r));
      rows.push_back(row);
    }
    o.tables.emplace("limits", table_from_rows("limits", cols, rows));
    // Peaks of the limits, in the columns of `peaks`: the grid's largest point, then golden-section
    // search on the linear solve between its neighbours.
    std::vector<std::vector<double>> peak_limit_rows;
    for (int l = 0; l < 2; ++l) {
      const Eigen::MatrixXd& lim = l == 0 ? o.free_response : o.stuck_response;
      std::vector<double> row = {static_cast<double>(l + 1)};
      for (int k = 0; k < (p.ip_oop ? 2 : 1); ++k) {
        const Index col = p.ip_oop ? static_cast<Index>(p.responses.size()) + k : 0;
        const auto value = [&](double f) {
          const Eigen::VectorXcd z = limit_solve(l, kTwoPi * f);
          if (p.ip_oop && std::max(p.ip_oop->first, p.ip_oop->second) >= z.size()) return PeakValues{};
          if (!p.ip_oop && p.responses.front() >= z.size()) return PeakValues{};
          return peak_values(p, z, k);
        };
        Index i = 0;
        lim.col(col).maxCoeff(&i);
        const double lo = o.limit_frequency_hz[std::max<Index>(i - 1, 0)], hi = o.limit_frequency_hz[std::min<Index>(i + 1, n_grid - 1)];
        const GoldenSearch search = golden_section_maximum([&](double f) { return std::optional<double>(value(f).component); }, lo, hi, 60, 1e-12);
        const double a = search.a, b = search.b;
        const double f = 0.5 * (a + b);
        row.insert(row.end(), {f, value(f).amplitude});
      }
      peak_limit_rows.push_back(row);
    }
    std::vector<std::string> lcols = {"limit"};
    for (const std::string& k : kinds) lcols.insert(lcols.end(), {k + "_hz", k + "_amp_per_n"});
    ResultTable t = table_from_rows("limit_peaks", lcols, peak_limit_rows);
    t.add_text_column("model", {"free (no contacts)", "stuck (contacts as springs kn, kt)"});
    // Distance of each level's peaks from the stuck limit: zero as Fe -> 0 (eq 3.51).
    std::vector<std::vector<double>> dev_rows;
    std::vector<std::string> dev_cols = {"level", "fe_n"};
    for (const std::string& k : kinds) dev_cols.insert(dev_cols.end(), {k + "_hz", k + "_amp_per_n"});
    for (size_t l = 0; l < o.levels.size(); ++l) {
      std::vector<double> row = {static_cast<double>(l + 1), o.levels[l].force};
      for (size_t k = 0; k < kinds.size(); ++k) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const bool ok = k < o.levels[l].peaks.size() && o.levels[l].peaks[k].solution.converged;
        const HbmPeak* pk = ok ? &o.levels[l].peaks[k] : nullptr;
        const double f = peak_limit_rows[1][1 + 2 * k], a = peak_limit_rows[1][2 + 2 * k];
        row.push_back(pk ? pk->frequency_hz / f - 1 : nan);
        row.push_back(pk ? pk->amplitude / o.levels[l].force / a - 1 : nan);
      }
      dev_rows.push_back(row);
    }
    o.tables.emplace("limit_peaks", std::move(t));
    o.tables.emplace("stuck_limit_deviation", table_from_rows("stuck_limit_deviation", dev_cols, dev_rows));
  }
  if (p.damper_static) {
    const damper::DamperStaticState& s = *p.damper_static;
    std::vector<std::vector<double>> rows;
    for (size_t c = 0; c < p.damper->contacts.size(); ++c)
      rows.push_back({static_cast<double>(c + 1), s.normal_preload[static_cast<Index>(c)], s.normal_displacement[static_cast<Index>(c)],
                      s.open[c] ? 1.0 : 0.0});
    ResultTable t = table_from_rows("damper_static", {"contact", "normal_preload_n", "normal_displacement_m", "open"}, rows);
    std::vector<std::string> names;
    for (const auto& c : p.damper->contacts) names.push_back(c.name);
    t.add_text_column("name", names);
    o.tables.emplace("damper_static", std::move(t));
  }
  return o;
}

}  // namespace bb
