#include "hbm/nonlinear_modes.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "friction/state_fractions.hpp"
#include "hbm/condensed_balance.hpp"
#include "linalg/damped_newton.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb::hbm {

namespace {

using Eigen::Index;

// The EPMC system at one amplitude. Unknowns z = [Q0 / s0; Q_1..H / a; omega / w0; kappa / w0]
// (Q_j column j of the n x (2H + 1) coefficients), residual rows scaled alike by k_max: the
// static block by k_max s0, the dynamic one by k_max a, so that both are O(1) at every amplitude.
class EpmcSystem {
 public:
  EpmcSystem(const friction::FrictionModel& model, const HarmonicBalance& contacts, const Eigen::VectorXd& phi,
             double w0, double kmax)
      : m_(model),
        hb_(contacts),
        phi_(phi),
        w0_(w0),
        kmax_(kmax),
        n_(model.mass.rows()),
        h_(contacts.options().harmonics),
        size_(n_ * friction::harmonic_size(h_)) {}

  Index unknowns() const { return size_ + 2; }

  void set_amplitude(double a, double static_scale) {
    a_ = a;
    s0_ = static_scale;
  }

  Eigen::MatrixXd coefficients(const Eigen::VectorXd& z) const {
    Eigen::MatrixXd q = Eigen::Map<const Eigen::MatrixXd>(z.data(), n_, size_ / n_);
    q.col(0) *= s0_;
    q.rightCols(q.cols() - 1) *= a_;
    return q;
  }
  Eigen::VectorXd scaled(const Eigen::MatrixXd& q, double omega, double kappa) const {
    Eigen::VectorXd z(unknowns());
    Eigen::MatrixXd s = q;
    s.col(0) /= s0_;
    s.rightCols(s.cols() - 1) /= a_;
    z.head(size_) = Eigen::Map<const Eigen::VectorXd>(s.data(), size_);
    z[size_] = omega / w0_;
    z[size_ + 1] = kappa / w0_;
    return z;
  }
  double omega(const Eigen::VectorXd& z) const { return z[size_] * w0_; }
  double kappa(const Eigen::VectorXd& z) const { return z[size_ + 1] * w0_; }

  NewtonPoint operator()(const Eigen::VectorXd& z) const {
    NewtonPoint p;
    p.valid = false;
    if (!z.allFinite()) return p;
    const Eigen::MatrixXd q = coefficients(z);
    const double w = omega(z), k = kappa(z);
    const Index nc = static_cast<Index>(hb_.contact_dofs().size()), m = q.cols();
    Eigen::VectorXd x(nc * m);
    for (Index j = 0; j < m; ++j)
      for (Index i = 0; i < nc; ++i) x[j * nc + i] = q(hb_.contact_dofs()[static_cast<size_t>(i)], j);
    HarmonicBalance::ContactForces g = hb_.contact_forces(x);
    if (!g.closed) return p;

    // Unscaled residual and Jacobian in (Q, omega, kappa).
    Eigen::VectorXd r = Eigen::VectorXd::Zero(unknowns());
    Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(unknowns(), unknowns());
    const Eigen::MatrixXd& M = m_.mass;
    const Eigen::MatrixXd c = m_.damping - k * M;
    r.head(n_) = m_.stiffness * q.col(0) - m_.static_load;
    jac.topLeftCorner(n_, n_) = m_.stiffness;
    for (int h = 1; h <= h_; ++h) {
      // cos rows: (K - (h w)^2 M) a + h w C' b;  sin rows: (K - (h w)^2 M) b - h w C' a.
      const Index ia = (2 * h - 1) * n_, ib = 2 * h * n_;
      const Eigen::VectorXd a = q.col(2 * h - 1), b = q.col(2 * h);
      const Eigen::MatrixXd d = m_.stiffness - (h * w) * (h * w) * M;
      r.segment(ia, n_) = d * a + h * w * (c * b);
      r.segment(ib, n_) = d * b - h * w * (c * a);
      jac.block(ia, ia, n_, n_) = d;
      jac.block(ia, ib, n_, n_) = h * w * c;
      jac.block(ib, ib, n_, n_) = d;
      jac.block(ib, ia, n_, n_) = -h * w * c;
      jac.block(ia, size_, n_, 1) = -2.0 * h * h * w * (M * a) + h * (c * b);
      jac.block(ib, size_, n_, 1) = -2.0 * h * h * w * (M * b) - h * (c * a);
      jac.block(ia, size_ + 1, n_, 1) = -h * w * (M * b);
      jac.block(ib, size_ + 1, n_, 1) = h * w * (M * a);
    }
    for (Index j = 0; j < m; ++j)
      for (Index i = 0; i < nc; ++i) {
        const Index row = j * n_ + hb_.contact_dofs()[static_cast<size_t>(i)];
        r[row] += g.force[j * nc + i];
        for (Index l = 0; l < m; ++l)
          for (Index p2 = 0; p2 < nc; ++p2)
            jac(row, l * n_ + hb_.contact_dofs()[static_cast<size_t>(p2)]) += g.jacobian(j * nc + i, l * nc + p2);
      }
    // Amplitude: a1^T M a1 + b1^T M b1 = a^2; phase: b1 . M phi = 0.
    const Eigen::VectorXd a1 = q.col(1), b1 = q.col(2);
    r[size_] = (a1.dot(M * a1) + b1.dot(M * b1)) / (a_ * a_) - 1.0;
    jac.block(size_, n_, 1, n_) = 2.0 * (M * a1).transpose() / (a_ * a_);
    jac.block(size_, 2 * n_, 1, n_) = 2.0 * (M * b1).transpose() / (a_ * a_);
    const Eigen::VectorXd mphi = M * phi_;
    r[size_ + 1] = b1.dot(mphi) / a_;
    jac.block(size_ + 1, 2 * n_, 1, n_) = mphi.transpose() / a_;

    // Scale: rows of the balance by k_max s0 (static) and k_max a (dynamic); columns by the unknowns' scales.
    r.head(n_) /= kmax_ * s0_;
    r.segment(n_, size_ - n_) /= kmax_ * a_;
    jac.topRows(n_) /= kmax_ * s0_;
    jac.middleRows(n_, size_ - n_) /= kmax_ * a_;
    jac.leftCols(n_) *= s0_;
    jac.middleCols(n_, size_ - n_) *= a_;
    jac.rightCols(2) *= w0_;
    if (!r.allFinite() || !jac.allFinite()) return p;
    p.valid = true;
    p.residual = std::move(r);
    p.jacobian = std::move(jac);
    p.data = std::move(g.contacts);
    return p;
  }

 private:
  const friction::FrictionModel& m_;
  const HarmonicBalance& hb_;
  Eigen::VectorXd phi_;
  double w0_, kmax_;
  Index n_;
  int h_;
  Index size_;
  double a_ = 1.0, s0_ = 1.0;
};

// Where a Newton iteration stopped short: each contact's states over the samples at its last
// iterate, and the contacts at a corner (stuck the whole period with the loop at its Coulomb limit,
// where the slider's convention, kept or shaken down to the limit, has a kink the Jacobian does not
// see; bench/README.md). Empty without the contacts' data.
std::string contact_states_at(const friction::FrictionModel& model, const NewtonPoint& at) {
  const auto* contacts = std::any_cast<std::vector<friction::AftResult>>(&at.data);
  if (!at.valid || !contacts) return {};
  std::vector<std::string> states, corners;
  for (size_t k = 0; k < contacts->size() && k < model.contacts.size(); ++k) {
    const friction::AftResult& c = (*contacts)[k];
    const double mu = model.contacts[k].point.mu;
    const friction::StateFractions f = friction::state_fractions(c.state);
    double ratio = 0.0;  // largest |T| / (mu N) over the samples
    for (size_t i = 0; i < c.state.size(); ++i) {
      const double n = c.n[static_cast<Index>(i)];
      if (n > 0.0 && mu > 0.0) ratio = std::max(ratio, std::abs(c.t[static_cast<Index>(i)]) / (mu * n));
    }
    states.push_back(fmt::format("{}: stick {:.0f} %, slip {:.0f} %, lift-off {:.0f} %", k + 1, 100.0 * f.stick,
                                 100.0 * f.slip, 100.0 * f.lift_off));
    if (f.stick == 1.0 && ratio > 0.99) corners.push_back(fmt::format("{} (|T| / mu N = {:.5f})", k + 1, ratio));
  }
  std::string out = fmt::format("; contacts at the last iterate {}", fmt::join(states, "; "));
  if (!corners.empty())
    out += fmt::format(
        "; at a corner of the contact states: contact {} stuck the whole period with its loop at the "
        "Coulomb limit",
        fmt::join(corners, ", "));
  return out;
}

}  // namespace

NonlinearModeBranch trace_nonlinear_mode(const friction::FrictionModel& input, int linear_mode,
                                         const std::vector<double>& amplitudes, const Eigen::VectorXd& static_guess,
                                         const NonlinearModeOptions& options) {
  friction::FrictionModel model = input;
  friction::validate_model(model, "nonlinear modes");
  const Index n = model.mass.rows();
  if (linear_mode < 1 || linear_mode > n)
    throw std::invalid_argument(fmt::format("nonlinear modes: linear mode {} of a model with {} DOFs", linear_mode, n));
  if (amplitudes.empty()) throw std::invalid_argument("nonlinear modes: no amplitude");
  for (size_t i = 0; i < amplitudes.size(); ++i)
    if (!(amplitudes[i] > 0.0) || !std::isfinite(amplitudes[i]) || (i > 0 && !(amplitudes[i] > amplitudes[i - 1])))
      throw std::invalid_argument("nonlinear modes: amplitudes must be positive, finite and increasing");
  if (static_guess.size() != 0 && static_guess.size() != n)
    throw std::invalid_argument(
        fmt::format("nonlinear modes: static guess of {} entries for {} DOFs", static_guess.size(), n));

  HbmOptions hb_options;
  hb_options.harmonics = options.harmonics;
  hb_options.aft = options.aft;
  const HarmonicBalance contacts(model, hb_options);  // validates the contacts, resolves the samples

  // The stuck linear mode: the start of the branch and its phase reference.
  const Eigen::MatrixXd k_stuck = friction::stuck_stiffness(model);
  const DenseEigen<double> eig = symmetric_eigen(k_stuck, model.mass);
  if (!eig.ok || !(eig.values[linear_mode - 1] > 0.0))
    throw std::invalid_argument(fmt::format(
        "nonlinear modes: stuck linear mode {} has no positive eigenvalue (M not positive definite, or a rigid-body "
        "mode with every contact stuck)",
        linear_mode));
  NonlinearModeBranch branch;
  branch.linear_mode = linear_mode;
  branch.linear_omega = std::sqrt(eig.values[linear_mode - 1]);
  branch.linear_shape = eig.vectors.col(linear_mode - 1);  // M-normalized
  const Eigen::VectorXd& phi = branch.linear_shape;
  const double kmax = k_stuck.diagonal().cwiseAbs().maxCoeff();

  EpmcSystem system(model, contacts, phi, branch.linear_omega, kmax);
  const Index m = friction::harmonic_size(options.harmonics);
  Eigen::MatrixXd q = Eigen::MatrixXd::Zero(n, m);
  if (static_guess.size() == n) {
    q.col(0) = static_guess;
  } else {
    Eigen::VectorXd load = model.static_load;
    for (const friction::ContactElement& c : model.contacts)
      load -= c.point.n0 * c.normal.transpose() - c.point.kt * c.tangential_offset * c.tangential.transpose();
    q.col(0) = k_stuck.ldlt().solve(load);
  }
  double omega = branch.linear_omega, kappa = phi.dot(model.damping * phi);

  const DampedNewtonOptions newton{.tolerance = options.tolerance,
                                   .max_iterations = options.max_iterations,
                                   .max_backtracks = 30,
                                   .step_solve = NewtonStepSolve::minimum_norm,
                                   .levenberg_marquardt = true};
  const auto solve_at = [&](double a, const Eigen::MatrixXd& q_guess, double w, double k) {
    system.set_amplitude(a, std::max(a, q_guess.col(0).cwiseAbs().maxCoeff()));
    return damped_newton(system, system.scaled(q_guess, w, k), newton);
  };
  // The first guess: the stuck mode at the first amplitude.
  q.col(1) = amplitudes.front() * phi;
  double last_a = amplitudes.front();
  int skips_in_a_row = 0;
  for (size_t i = 0; i < amplitudes.size(); ++i) {
    double target = amplitudes[i], from = i == 0 ? target : last_a;
    int halvings = 0;
    while (true) {
      const double a = from * std::pow(target / from, std::ldexp(1.0, -halvings));
      Eigen::MatrixXd guess = q;
      guess.rightCols(m - 1) *= a / last_a;
      const DampedNewtonResult r = solve_at(a, guess, omega, kappa);
      const double w = system.omega(r.x), k = system.kappa(r.x);
      if (r.converged && w > 0.0) {
        q = system.coefficients(r.x);
        omega = w, kappa = k, last_a = a;
        if (a == target) {
          NonlinearModePoint pt;
          pt.modal_amplitude = a;
          pt.omega = w;
          pt.kappa = k;
          pt.coefficients = q;
          pt.contacts = std::any_cast<std::vector<friction::AftResult>>(r.at.data);
          pt.residual = r.residual;
          pt.iterations = r.iterations;
          branch.points.push_back(std::move(pt));
          skips_in_a_row = 0;
          break;
        }
        halvings = std::max(halvings - 1, 0);
        from = a;
        continue;
      }
      if (++halvings > options.max_halvings) {
        const std::string why = fmt::format(
            "nonlinear mode {}: no periodic motion at modal amplitude {:.4g} (from {:.4g}, {} halvings of the step): "
            "{}",
            linear_mode, a, last_a, options.max_halvings,
            r.converged ? "negative frequency" : r.failure + contact_states_at(model, r.at));
        if (i + 1 < amplitudes.size() && skips_in_a_row < options.max_skips) {
          if (branch.skipped.empty()) branch.first_skip = why;
          branch.skipped.push_back(target);
          ++skips_in_a_row;
          break;
        }
        branch.failure = why;
        return branch;
      }
    }
  }
  branch.converged = branch.skipped.empty();
  return branch;
}

}  // namespace bb::hbm
