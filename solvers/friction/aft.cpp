#include "friction/aft.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace bb::friction {

Eigen::Index harmonic_size(int harmonics) {
  if (harmonics < 0) throw std::invalid_argument(fmt::format("harmonic count must be >= 0 (got {})", harmonics));
  return 2 * static_cast<Eigen::Index>(harmonics) + 1;
}

int harmonics_of(Eigen::Index coefficients) {
  if (coefficients < 1 || coefficients % 2 == 0)
    throw std::invalid_argument(
        fmt::format("{} harmonic coefficients: expected an odd count [c0, a1, b1, ..., aH, bH]", coefficients));
  return static_cast<int>((coefficients - 1) / 2);
}

namespace {

void require_samples(int harmonics, int samples) {
  if (samples < harmonic_size(harmonics))
    throw std::invalid_argument(fmt::format("AFT: {} time samples cannot resolve {} harmonics (need >= {})", samples,
                                            harmonics, harmonic_size(harmonics)));
}

// cos and sin of h theta_k with the phase reduced to an integer index first: 2 pi (h k mod n) / n
// keeps the samples exact to rounding for large h k.
double phase(int h, int k, int samples) {
  const long long index = (static_cast<long long>(h) * k) % samples;
  return 2.0 * std::numbers::pi * static_cast<double>(index) / static_cast<double>(samples);
}

}  // namespace

Eigen::MatrixXd synthesis_matrix(int harmonics, int samples) {
  require_samples(harmonics, samples);
  Eigen::MatrixXd e(samples, harmonic_size(harmonics));
  for (int k = 0; k < samples; ++k) {
    e(k, 0) = 1.0;
    for (int h = 1; h <= harmonics; ++h) {
      const double a = phase(h, k, samples);
      e(k, 2 * h - 1) = std::cos(a);
      e(k, 2 * h) = std::sin(a);
    }
  }
  return e;
}

Eigen::MatrixXd analysis_matrix(int harmonics, int samples) {
  // Discrete orthogonality on the uniform grid: sum_k cos(h theta_k) cos(g theta_k) = n/2 delta_hg
  // for 0 < h, g < n / 2 (likewise sin), so P = diag(1/n, 2/n, ..., 2/n) E^T inverts E exactly.
  Eigen::MatrixXd p = synthesis_matrix(harmonics, samples).transpose() * (2.0 / samples);
  p.row(0) *= 0.5;
  return p;
}

const AftTransforms& aft_transforms(int harmonics, int samples) {
  thread_local struct {
    int harmonics = -1, samples = -1;
    AftTransforms transforms;
  } cache;
  if (cache.harmonics != harmonics || cache.samples != samples) {
    cache.transforms.synthesis = synthesis_matrix(harmonics, samples);
    cache.transforms.analysis = analysis_matrix(harmonics, samples);
    cache.harmonics = harmonics;
    cache.samples = samples;
  }
  return cache.transforms;
}

int checked_aft_inputs(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                       const AftOptions& options, int directions) {
  validate(p);
  if (u.size() != directions * v.size())
    throw std::invalid_argument(
        directions == 1
            ? fmt::format("AFT: {} tangential and {} normal coefficients", u.size(), v.size())
            : fmt::format("AFT: {} tangential coefficients for {} normal ones ({} directions: {} times as many)",
                          u.size(), v.size(), directions, directions));
  const int harmonics = harmonics_of(v.size());
  if (!u.allFinite() || !v.allFinite()) throw std::invalid_argument("AFT: a displacement coefficient is not finite");
  require_samples(harmonics, options.samples);
  if (options.max_periods < 2)
    throw std::invalid_argument(fmt::format("AFT: max_periods must be >= 2 (got {})", options.max_periods));
  if (!(options.closure_tolerance >= 0.0) || !std::isfinite(options.closure_tolerance))
    throw std::invalid_argument("AFT: closure_tolerance must be finite and >= 0");
  if (!std::isfinite(options.initial_slider)) throw std::invalid_argument("AFT: initial_slider must be finite");
  return harmonics;
}

namespace {

// One sample of the chain rule below for the coefficients [u; v]: the row dT_k (from the row dN_k
// and the synthesis row phi_k) and the slider's row dw, updated from w_{k-1}'s to w_k's.
void coefficient_derivative_step(const PointParameters& p, const JenkinsStep& s, const Eigen::RowVectorXd& phi,
                                 const Eigen::RowVectorXd& dn, Eigen::RowVectorXd& dt, Eigen::RowVectorXd& dw) {
  const Eigen::Index m = phi.size();
  switch (s.state) {
    case ContactState::lift_off:
      dt.setZero();
      dw.setZero();
      dw.head(m) = phi;
      break;
    case ContactState::stick:
      dt = -p.kt * dw;
      dt.head(m) += p.kt * phi;
      break;
    case ContactState::slip_positive:
    case ContactState::slip_negative: {
      const double sign = s.state == ContactState::slip_positive ? 1.0 : -1.0;
      dt = sign * p.mu * dn;
      dw = -dt / p.kt;
      dw.head(m) += phi;
      break;
    }
  }
}

// The same for the law's parameters (kt, mu, kn, n0); `elongation` is u_k - w_{k-1}.
void law_derivative_step(const PointParameters& p, const JenkinsStep& s, double elongation,
                         const Eigen::RowVector4d& dn, Eigen::RowVector4d& dt, Eigen::RowVector4d& dw) {
  switch (s.state) {
    case ContactState::lift_off:
      dt.setZero();
      dw.setZero();
      break;
    case ContactState::stick:
      dt = -p.kt * dw;
      dt[law_kt] += elongation;
      break;
    case ContactState::slip_positive:
    case ContactState::slip_negative: {
      const double sign = s.state == ContactState::slip_positive ? 1.0 : -1.0;
      dt = sign * p.mu * dn;
      dt[law_mu] += sign * s.normal;
      dw = -dt / p.kt;
      dw[law_kt] += s.tangential / (p.kt * p.kt);
      break;
    }
  }
}

}  // namespace

// The march and its derivative. At sample k, with the slider w_{k-1} left by the previous sample,
// jenkins_step gives (all quantities at sample k; e_k is row k of the synthesis matrix, so
// du_k = e_k du and dv_k = e_k dv):
//   N > 0:     dN = kn dv_k                               (eq 3.28, zero where the contact is open)
//   lift-off:  dT = 0,                    dw_k = du_k
//   stick:     dT = kt (du_k - dw_{k-1}), dw_k = dw_{k-1}
//   slip:      dT = s mu dN,              dw_k = du_k - dT / kt  (s = sign of the slip)
// The row vector dw (derivative of the slider w.r.t. all 2 (2H+1) input coefficients) is carried
// through every marched period, starting from dw = 0 (initial_slider is a constant). Over a loop
// that slips or lifts off somewhere this is the standard chain through the last stick start: in a
// stick segment opened at sample j, T_k = kt (u_k - u_j) + T_j, T_j = s mu N_j (or 0 after
// lift-off), so the stuck force depends on u_k, u_j and v_j only; the transient of the first
// periods has been forgotten by then. Over a loop stuck throughout from the start, dw stays 0 and
// dT = kt du. (A loop that slipped only in its first, transient period ends with the slider on the
// Coulomb limit at one sample: a kink of the map, where the carried dw gives the one-sided
// derivative of the state that sample reports.) These are exact derivatives of the discrete,
// piecewise-linear map and hold as long as no sample changes state; a perturbation that moves a
// stick/slip switch by one sample changes the map by O(1 / n_t), which is the non-smoothness of
// dry friction, not an error.
//
// The law derivatives (options.law_derivatives) follow the same chain with the parameter vector
// p = (kn, kt, mu, n0) in place of [u; v], the slider's dw/dp carried likewise (w_{k-1} the slider
// before the step):
//   N > 0:     dN = v_k dkn + dn0
//   lift-off:  dT = 0,                                        dw_k/dp = 0
//   stick:     dT = (u_k - w_{k-1}) dkt - kt dw_{k-1},        dw_k = dw_{k-1}
//   slip:      dT = s (N dmu + mu dN),                        dw_k = -dT / kt + T / kt^2 dkt
// so a contact stuck throughout has dT/dmu = 0 exactly and a frictionless one dT/dkt = 0.
AftResult aft_jenkins_sampled(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                              const AftOptions& options) {
  const int harmonics = harmonics_of(u.size());

  const int n = options.samples;
  const Eigen::Index m = u.size();
  // The per-sample matrices are row-major as the synthesis (aft_transforms).
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const AftTransforms& transforms = aft_transforms(harmonics, n);
  const RowMajor& synthesis = transforms.synthesis;
  const Eigen::MatrixXd& analysis = transforms.analysis;

  AftResult r;
  r.u = synthesis * u;
  r.v = synthesis * v;
  r.t.resize(n);
  r.n.resize(n);
  r.w.resize(n);
  r.state.assign(static_cast<size_t>(n), ContactState::stick);

  // Rows of d(T_k)/d[u; v] and d(N_k)/d[u; v] over the current period.
  RowMajor dt_rows = RowMajor::Zero(n, 2 * m);
  RowMajor dn_rows = RowMajor::Zero(n, 2 * m);
  Eigen::RowVectorXd dw = Eigen::RowVectorXd::Zero(2 * m);
  Eigen::RowVectorXd dn(2 * m), dt(2 * m);
  const bool with_law = options.law_derivatives;
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> dt_law, dn_law;
  if (with_law) dt_law = dn_law = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>::Zero(n, 4);
  Eigen::RowVector4d dw_law = Eigen::RowVector4d::Zero(), dn_p = Eigen::RowVector4d::Zero();

  double slider = options.initial_slider;
  const double scale = r.u.cwiseAbs().maxCoeff() + p.mu * std::max(p.n0 + p.kn * r.v.maxCoeff(), 0.0) / p.kt;
  for (int period = 1; period <= options.max_periods; ++period) {
    const double start = slider;
    for (int k = 0; k < n; ++k) {
      const JenkinsStep s = jenkins_step(p, slider, r.u[k], r.v[k]);
      if (with_law) {
        dn_p.setZero();
        if (s.normal > 0.0) dn_p << r.v[k], 0.0, 0.0, 1.0;
        dn_law.row(k) = dn_p;
        Eigen::RowVector4d dt_p = Eigen::RowVector4d::Zero();
        law_derivative_step(p, s, r.u[k] - slider, dn_p, dt_p, dw_law);
        dt_law.row(k) = dt_p;
      }
      slider = s.slider;
      r.t[k] = s.tangential;
      r.n[k] = s.normal;
      r.w[k] = s.slider;
      r.state[static_cast<size_t>(k)] = s.state;

      dn.setZero();
      if (s.normal > 0.0) dn.tail(m) = p.kn * synthesis.row(k);
      dn_rows.row(k) = dn;
      coefficient_derivative_step(p, s, synthesis.row(k), dn, dt, dw);
      dt_rows.row(k) = dt;
    }
    r.periods = period;
    r.closure_mismatch = std::abs(slider - start);
    if (period >= 2 && r.closure_mismatch <= options.closure_tolerance * scale) {
      r.closed = true;
      break;
    }
  }

  r.tangential = analysis * r.t;
  r.normal = analysis * r.n;
  const Eigen::MatrixXd dt_coefficients = analysis * dt_rows;
  r.dtangential_du = dt_coefficients.leftCols(m);
  r.dtangential_dv = dt_coefficients.rightCols(m);
  r.dnormal_dv = (analysis * dn_rows).rightCols(m);
  if (with_law) {
    r.dtangential_dlaw = analysis * dt_law;
    r.dnormal_dlaw = analysis * dn_law;
  }
  return r;
}

double cycle_work(const Eigen::VectorXd& force, const Eigen::VectorXd& displacement) {
  if (force.size() != displacement.size())
    throw std::invalid_argument(
        fmt::format("cycle_work: {} force and {} displacement coefficients", force.size(), displacement.size()));
  const int harmonics = harmonics_of(force.size());
  // x' = sum h (b_h cos - a_h sin); the mean of cos^2 and sin^2 over a period is 1/2.
  double work = 0.0;
  for (int h = 1; h <= harmonics; ++h)
    work += h * (force[2 * h - 1] * displacement[2 * h] - force[2 * h] * displacement[2 * h - 1]);
  return std::numbers::pi * work;
}

}  // namespace bb::friction
