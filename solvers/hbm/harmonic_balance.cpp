#include "hbm/harmonic_balance.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "common/errors.hpp"

namespace bb::hbm {

namespace {

using Index = Eigen::Index;
using Complex = std::complex<double>;

// A partial-pivoting LU is singular for our purposes when its reciprocal condition estimate is
// below this: the solve would amplify rounding by more than ~1e13.
constexpr double kSingularRcond = 1e-13;

Eigen::MatrixXd select(const Eigen::MatrixXd& a, const std::vector<Index>& rows, const std::vector<Index>& cols) {
  Eigen::MatrixXd s(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  for (Index i = 0; i < s.rows(); ++i)
    for (Index j = 0; j < s.cols(); ++j) s(i, j) = a(rows[static_cast<size_t>(i)], cols[static_cast<size_t>(j)]);
  return s;
}

Eigen::VectorXcd select(const Eigen::VectorXcd& v, const std::vector<Index>& rows) {
  Eigen::VectorXcd s(static_cast<Index>(rows.size()));
  for (Index i = 0; i < s.size(); ++i) s[i] = v[rows[static_cast<size_t>(i)]];
  return s;
}

// D_h = K + i h w C - (h w)^2 M restricted to rows x cols.
Eigen::MatrixXcd dynamic_stiffness(const HbmModel& m, double hw, const std::vector<Index>& rows,
                                   const std::vector<Index>& cols) {
  Eigen::MatrixXcd d(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  const bool damped = m.damping.size() > 0;
  for (Index i = 0; i < d.rows(); ++i)
    for (Index j = 0; j < d.cols(); ++j) {
      const Index r = rows[static_cast<size_t>(i)], c = cols[static_cast<size_t>(j)];
      d(i, j) = Complex(m.stiffness(r, c) - hw * hw * m.mass(r, c), damped ? hw * m.damping(r, c) : 0.0);
    }
  return d;
}

bool all_finite(const Eigen::MatrixXd& a) { return a.allFinite(); }

// Newton steps are taken as minimum-norm solutions: the Jacobian is genuinely singular when a
// direction leaves R unchanged, e.g. the static tangential position of a damper whose contacts all
// slip somewhere in the cycle (shifting it shifts every slider by the same amount), or a
// frictionless tangential direction. A pivoted LU would put an arbitrary, possibly huge, component
// along that null space; the complete orthogonal decomposition puts none.
Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  cod.setThreshold(1e-13);
  cod.compute(a);
  return cod.solve(b);
}

}  // namespace

void validate_model(HbmModel& m, const std::string& who) {
  const Index n = m.mass.rows();
  const auto fail = [&who](const std::string& what) { throw std::invalid_argument(fmt::format("{}: {}", who, what)); };
  if (n == 0 || m.mass.cols() != n || m.stiffness.rows() != n || m.stiffness.cols() != n)
    fail("M and K must be square and of the same non-zero size");
  if (m.damping.size() == 0) m.damping = Eigen::MatrixXd::Zero(n, n);
  if (m.damping.rows() != n || m.damping.cols() != n) fail("C must be empty or of the size of M");
  if (!all_finite(m.mass) || !all_finite(m.stiffness) || !all_finite(m.damping)) fail("M, C and K must be finite");
  if (m.static_load.size() == 0) m.static_load = Eigen::VectorXd::Zero(n);
  if (m.harmonic_load.size() == 0) m.harmonic_load = Eigen::VectorXcd::Zero(n);
  if (m.static_load.size() != n || m.harmonic_load.size() != n) fail(fmt::format("loads must have {} entries (one per DOF)", n));
  if (!m.static_load.allFinite() || !m.harmonic_load.allFinite()) fail("loads must be finite");
  for (size_t k = 0; k < m.contacts.size(); ++k) {
    const ContactElement& e = m.contacts[k];
    try {
      contact::validate(e.law);
    } catch (const std::invalid_argument& error) {
      fail(fmt::format("contact {}: {}", k, error.what()));
    }
    if (e.tangential.size() != n || e.normal.size() != n)
      fail(fmt::format("contact {}: a_t and a_n must have {} entries (one per DOF)", k, n));
    if (!e.tangential.allFinite() || !e.normal.allFinite() || !std::isfinite(e.tangential_offset))
      fail(fmt::format("contact {}: a_t, a_n and the tangential offset must be finite", k));
  }
}

HarmonicBalance::HarmonicBalance(HbmModel model, HbmOptions options) : model_(std::move(model)), options_(options) {
  const Index n = model_.mass.rows();
  const auto fail = [](const std::string& what) { throw std::invalid_argument("harmonic balance: " + what); };
  validate_model(model_, "harmonic balance");
  if (model_.contacts.empty()) fail("at least one contact element is required (use the linear FRF otherwise)");
  if (options_.harmonics < 1) fail("at least one harmonic");
  if (options_.max_iterations < 1 || options_.max_backtracks < 0 || !(options_.tolerance > 0.0))
    fail("max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");

  std::vector<bool> touched(static_cast<size_t>(n), false);
  for (const ContactElement& e : model_.contacts) {
    for (Index i = 0; i < n; ++i)
      if (e.tangential[i] != 0.0 || e.normal[i] != 0.0) touched[static_cast<size_t>(i)] = true;
  }
  for (Index i = 0; i < n; ++i) (touched[static_cast<size_t>(i)] ? contact_dofs_ : other_dofs_).push_back(i);
  if (contact_dofs_.empty()) fail("every contact has zero a_t and a_n: no contact DOF");

  const Index nc = static_cast<Index>(contact_dofs_.size());
  const Index nk = static_cast<Index>(model_.contacts.size());
  tangential_c_.resize(nk, nc);
  normal_c_.resize(nk, nc);
  for (Index k = 0; k < nk; ++k)
    for (Index i = 0; i < nc; ++i) {
      tangential_c_(k, i) = model_.contacts[static_cast<size_t>(k)].tangential[contact_dofs_[static_cast<size_t>(i)]];
      normal_c_(k, i) = model_.contacts[static_cast<size_t>(k)].normal[contact_dofs_[static_cast<size_t>(i)]];
    }

  // The static condensation needs K_oo invertible: the model with its contact DOFs clamped must be
  // held. We do not add ground springs to make it so; the model must be fixed instead.
  if (!other_dofs_.empty()) {
    const Eigen::MatrixXd koo = select(model_.stiffness, other_dofs_, other_dofs_);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(koo);
    if (lu.rank() < koo.rows() || lu.rcond() < kSingularRcond)
      fail(fmt::format("K restricted to the {} non-contact DOFs is singular (rank {}): the model with its contact DOFs "
                       "clamped has a rigid-body mode. Constrain it (boundary conditions) or list those DOFs in a "
                       "contact; no ground spring is added",
                       koo.rows(), lu.rank()));
  }

  aft_ = options_.aft;
  if (aft_.samples == 0) aft_.samples = std::max(64, 16 * (2 * options_.harmonics + 1));
  if (aft_.samples < 2 * options_.harmonics + 1) fail("aft.samples must be >= 2H + 1");

  double preload = 0.0;
  for (const ContactElement& e : model_.contacts) preload += (1.0 + e.law.mu) * e.law.n0;
  force_scale_ = model_.static_load.norm() + model_.harmonic_load.norm() + preload;
}

Index HarmonicBalance::unknowns() const {
  return static_cast<Index>(contact_dofs_.size()) * contact::harmonic_size(options_.harmonics);
}

std::optional<HarmonicBalance::Linear> HarmonicBalance::condense(double omega) const {
  const Index nc = static_cast<Index>(contact_dofs_.size());
  const int harmonics = options_.harmonics;
  Linear linear{Eigen::MatrixXd::Zero(unknowns(), unknowns()), Eigen::VectorXd::Zero(unknowns())};
  for (int h = 0; h <= harmonics; ++h) {
    const double hw = h * omega;
    Eigen::MatrixXcd reduced = dynamic_stiffness(model_, hw, contact_dofs_, contact_dofs_);
    Eigen::VectorXcd load = Eigen::VectorXcd::Zero(nc);
    if (h == 0) load = select(Eigen::VectorXcd(model_.static_load.cast<Complex>()), contact_dofs_);
    if (h == 1) load = select(model_.harmonic_load, contact_dofs_);
    if (!other_dofs_.empty()) {
      const Eigen::MatrixXcd doo = dynamic_stiffness(model_, hw, other_dofs_, other_dofs_);
      const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(doo);
      if (!(lu.rcond() >= kSingularRcond)) return std::nullopt;
      const Eigen::MatrixXcd doc = dynamic_stiffness(model_, hw, other_dofs_, contact_dofs_);
      const Eigen::MatrixXcd dco = dynamic_stiffness(model_, hw, contact_dofs_, other_dofs_);
      reduced -= dco * lu.solve(doc);
      if (h <= 1) {
        Eigen::VectorXcd fo = h == 0 ? select(Eigen::VectorXcd(model_.static_load.cast<Complex>()), other_dofs_)
                                     : select(model_.harmonic_load, other_dofs_);
        load -= dco * lu.solve(fo);
      }
    }
    if (h == 0) {
      linear.operator_.topLeftCorner(nc, nc) = reduced.real();
      linear.load.head(nc) = load.real();
      continue;
    }
    // (A + iB)(a - ib) = (Aa + Bb) + i(Ba - Ab) = F: rows a: [A B], rows b: [-B A], load (Re F, -Im F).
    const Index a = (2 * h - 1) * nc, b = 2 * h * nc;
    linear.operator_.block(a, a, nc, nc) = reduced.real();
    linear.operator_.block(a, b, nc, nc) = reduced.imag();
    linear.operator_.block(b, a, nc, nc) = -reduced.imag();
    linear.operator_.block(b, b, nc, nc) = reduced.real();
    linear.load.segment(a, nc) = load.real();
    linear.load.segment(b, nc) = -load.imag();
  }
  if (!linear.operator_.allFinite() || !linear.load.allFinite()) return std::nullopt;
  return linear;
}

HarmonicBalance::ContactForces HarmonicBalance::contact_forces(const Eigen::VectorXd& x) const {
  const Index nc = static_cast<Index>(contact_dofs_.size());
  const Index m = contact::harmonic_size(options_.harmonics);
  // Column j of the nc x m matrix is harmonic coefficient j of every contact DOF.
  const Eigen::Map<const Eigen::MatrixXd> coefficients(x.data(), nc, m);
  ContactForces out{Eigen::VectorXd::Zero(unknowns()), Eigen::MatrixXd::Zero(unknowns(), unknowns()), {}, true};
  Eigen::Map<Eigen::MatrixXd> force(out.force.data(), nc, m);
  for (Index k = 0; k < tangential_c_.rows(); ++k) {
    const Eigen::RowVectorXd at = tangential_c_.row(k), an = normal_c_.row(k);
    Eigen::VectorXd u = (at * coefficients).transpose();
    const Eigen::VectorXd v = (an * coefficients).transpose();
    u[0] -= model_.contacts[static_cast<size_t>(k)].tangential_offset;
    contact::AftResult r = contact::aft_jenkins(model_.contacts[static_cast<size_t>(k)].law, u, v, aft_);
    out.closed = out.closed && r.closed;
    // g = a_t^T T + a_n^T N, per coefficient.
    force += at.transpose() * r.tangential.transpose() + an.transpose() * r.normal.transpose();
    // dg_(j,i)/dx_(l,p) = at_i (dT/du_jl at_p + dT/dv_jl an_p) + an_i dN/dv_jl an_p.
    const Eigen::MatrixXd tt = at.transpose() * at, tn = at.transpose() * an, nn = an.transpose() * an;
    for (Index j = 0; j < m; ++j)
      for (Index l = 0; l < m; ++l) {
        const double tu = r.dtangential_du(j, l), tv = r.dtangential_dv(j, l), nv = r.dnormal_dv(j, l);
        if (tu == 0.0 && tv == 0.0 && nv == 0.0) continue;
        out.jacobian.block(j * nc, l * nc, nc, nc) += tu * tt + tv * tn + nv * nn;
      }
    out.contacts.push_back(std::move(r));
  }
  return out;
}

Eigen::MatrixXd HarmonicBalance::recover(const Eigen::VectorXd& x, double omega) const {
  const Index n = model_.mass.rows(), nc = static_cast<Index>(contact_dofs_.size());
  const Index m = contact::harmonic_size(options_.harmonics);
  if (x.size() != unknowns()) throw std::invalid_argument("harmonic balance: x has the wrong size");
  Eigen::MatrixXd q = Eigen::MatrixXd::Zero(n, m);
  const Eigen::Map<const Eigen::MatrixXd> xc(x.data(), nc, m);
  for (Index i = 0; i < nc; ++i) q.row(contact_dofs_[static_cast<size_t>(i)]) = xc.row(i);
  if (other_dofs_.empty()) return q;
  for (int h = 0; h <= options_.harmonics; ++h) {
    const double hw = h * omega;
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(dynamic_stiffness(model_, hw, other_dofs_, other_dofs_));
    if (!(lu.rcond() >= kSingularRcond))
      throw SolverError(fmt::format("harmonic balance: D_oo singular at harmonic {}, omega = {} rad/s", h, omega));
    Eigen::VectorXcd qc(nc), fo = Eigen::VectorXcd::Zero(static_cast<Index>(other_dofs_.size()));
    if (h == 0) {
      qc = xc.col(0).cast<Complex>();
      fo = select(Eigen::VectorXcd(model_.static_load.cast<Complex>()), other_dofs_);
    } else {
      qc = xc.col(2 * h - 1).cast<Complex>() - Complex(0.0, 1.0) * xc.col(2 * h).cast<Complex>();
      if (h == 1) fo = select(model_.harmonic_load, other_dofs_);
    }
    const Eigen::VectorXcd qo = lu.solve(fo - dynamic_stiffness(model_, hw, other_dofs_, contact_dofs_) * qc);
    for (size_t i = 0; i < other_dofs_.size(); ++i) {
      const Index dof = other_dofs_[i];
      if (h == 0) q(dof, 0) = qo[static_cast<Index>(i)].real();
      else {
        q(dof, 2 * h - 1) = qo[static_cast<Index>(i)].real();
        q(dof, 2 * h) = -qo[static_cast<Index>(i)].imag();
      }
    }
  }
  return q;
}

std::optional<Eigen::VectorXd> HarmonicBalance::linearized(double omega, bool stuck) const {
  const auto linear = condense(omega);
  if (!linear) return std::nullopt;
  const Index nc = static_cast<Index>(contact_dofs_.size());
  const Index m = contact::harmonic_size(options_.harmonics);
  Eigen::MatrixXd springs = Eigen::MatrixXd::Zero(nc, nc);
  Eigen::VectorXd preload = Eigen::VectorXd::Zero(nc);
  for (Index k = 0; k < tangential_c_.rows(); ++k) {
    const contact::JenkinsParameters& law = model_.contacts[static_cast<size_t>(k)].law;
    springs += law.kn * normal_c_.row(k).transpose() * normal_c_.row(k);
    preload += law.n0 * normal_c_.row(k).transpose();
    if (stuck) {
      springs += law.kt * tangential_c_.row(k).transpose() * tangential_c_.row(k);
      preload -= law.kt * model_.contacts[static_cast<size_t>(k)].tangential_offset * tangential_c_.row(k).transpose();
    }
  }
  Eigen::MatrixXd a = linear->operator_;
  for (Index j = 0; j < m; ++j) a.block(j * nc, j * nc, nc, nc) += springs;
  Eigen::VectorXd b = linear->load;
  b.head(nc) -= preload;
  const Eigen::VectorXd x = a.fullPivLu().solve(b);
  if (!x.allFinite()) return std::nullopt;
  return x;
}

namespace {

struct Evaluation {
  Eigen::VectorXd residual;
  double norm = std::numeric_limits<double>::infinity();
  HarmonicBalance::ContactForces forces;
  bool ok = false;  // finite and every loop closed
};

Evaluation evaluate(const HarmonicBalance& s, const HarmonicBalance::Linear& linear, const Eigen::VectorXd& x) {
  Evaluation e;
  if (!x.allFinite()) return e;
  e.forces = s.contact_forces(x);
  e.residual = linear.operator_ * x + e.forces.force - linear.load;
  e.ok = e.residual.allFinite() && e.forces.closed;
  if (e.ok) e.norm = e.residual.norm();
  return e;
}

double target_norm(const HarmonicBalance& s) { return s.options().tolerance * s.force_scale(); }

}  // namespace

namespace {

// Newton-Raphson with backtracking from x (its evaluation `current`), then Levenberg-Marquardt
// steps when backtracking fails. Never throws, never returns NaN.
HbmSolution newton(const HarmonicBalance& s, const HarmonicBalance::Linear& linear_ref, double omega, Eigen::VectorXd x,
                   Evaluation current) {
  const HarmonicBalance::Linear* linear = &linear_ref;
  HbmSolution out;
  out.omega = omega;
  out.residual = std::numeric_limits<double>::infinity();
  const double target = target_norm(s);
  for (int iteration = 0;; ++iteration) {
    out.iterations = iteration;
    if (!current.ok) {
      out.failure = fmt::format("contact evaluation failed (non-finite or slider loop not closed) at omega = {:.6g} rad/s",
                                omega);
      break;
    }
    if (current.norm <= target) {
      out.converged = true;
      break;
    }
    if (iteration == s.options().max_iterations) {
      out.failure = fmt::format("no convergence in {} Newton iterations (|R| = {:.3g} N, target {:.3g} N) at omega = "
                                "{:.6g} rad/s",
                                iteration, current.norm, target, omega);
      break;
    }
    const Eigen::MatrixXd jacobian = linear->operator_ + current.forces.jacobian;
    const Eigen::VectorXd step = minimum_norm_solve(jacobian, -current.residual);
    if (!step.allFinite()) {
      out.failure = fmt::format("singular Jacobian (|R| = {:.3g} N) at omega = {:.6g} rad/s", current.norm, omega);
      break;
    }
    // Backtracking (Armijo on ||R||): the map is piecewise smooth, a full step can cross stick/slip
    // or contact/lift-off switches and land further away than it started.
    double alpha = 1.0;
    bool accepted = false;
    for (int b = 0; b <= s.options().max_backtracks; ++b, alpha *= 0.5) {
      Evaluation trial = evaluate(s, *linear, x + alpha * step);
      if (trial.ok && trial.norm <= (1.0 - 1e-4 * alpha) * current.norm) {
        x += alpha * step;
        current = std::move(trial);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      // Levenberg-Marquardt fallback: where the exact Jacobian of the piecewise-smooth map points
      // across a switch (a stick/slip kink near the solution), a damped Gauss-Newton step along a
      // blend of the Newton and steepest-descent directions still reduces ||R||.
      const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
      const Eigen::VectorXd gradient = jacobian.transpose() * current.residual;
      const double scale = normal.diagonal().maxCoeff();
      for (double lambda = 1e-8; lambda <= 1e2 && !accepted && scale > 0.0; lambda *= 10.0) {
        Eigen::MatrixXd damped = normal;
        damped.diagonal().array() += lambda * scale;
        const Eigen::VectorXd lm = damped.ldlt().solve(-gradient);
        if (!lm.allFinite()) continue;
        Evaluation trial = evaluate(s, *linear, x + lm);
        if (trial.ok && trial.norm < current.norm) {
          x += lm;
          current = std::move(trial);
          accepted = true;
        }
      }
    }
    if (!accepted) {
      out.iterations = iteration + 1;
      out.failure = fmt::format("line search failed after {} halvings (|R| = {:.3g} N, target {:.3g} N) at omega = "
                                "{:.6g} rad/s",
                                s.options().max_backtracks, current.norm, target, omega);
      break;
    }
  }
  out.x = x;
  if (std::isfinite(current.norm)) out.residual = current.norm;
  out.contacts = std::move(current.forces.contacts);
  if (!out.x.allFinite()) {  // never hand NaN to a caller
    out.x.setZero();
    out.converged = false;
  }
  if (!std::isfinite(out.residual)) out.residual = std::numeric_limits<double>::max();
  return out;
}

}  // namespace

HbmSolution solve_at_frequency(const HarmonicBalance& s, double omega, const std::optional<Eigen::VectorXd>& initial) {
  if (!(omega > 0.0) || !std::isfinite(omega)) throw std::invalid_argument("harmonic balance: omega must be finite and > 0");
  const auto linear = s.condense(omega);
  if (!linear) {
    HbmSolution out;
    out.omega = omega;
    out.residual = std::numeric_limits<double>::max();
    out.x = Eigen::VectorXd::Zero(s.unknowns());
    out.failure = fmt::format("singular dynamic stiffness of the non-contact DOFs at omega = {:.6g} rad/s", omega);
    return out;
  }
  // Starts, in order: the caller's guess, then the two linear limits (contacts stuck: small
  // amplitude; normal springs only: large amplitude), the better one first. Newton on this
  // piecewise-smooth map can stall on a kink from one start and converge from another; each start
  // gets max_iterations, so a solve costs at most three times that.
  HbmSolution best;
  int iterations = 0;
  const auto attempt = [&](Eigen::VectorXd x, Evaluation e) {
    HbmSolution trial = newton(s, *linear, omega, std::move(x), std::move(e));
    iterations += trial.iterations;
    const bool converged = trial.converged;
    if (converged || best.x.size() == 0 || trial.residual < best.residual) best = std::move(trial);
    best.iterations = iterations;
    return converged;
  };
  if (initial) {
    if (initial->size() != s.unknowns())
      throw std::invalid_argument(fmt::format("harmonic balance: initial guess has {} entries, expected {}",
                                              initial->size(), s.unknowns()));
    if (attempt(*initial, evaluate(s, *linear, *initial))) return best;
  }
  // The linear limits only when needed: on a sweep the caller's guess almost always converges.
  std::vector<std::pair<Eigen::VectorXd, Evaluation>> limits;
  for (const bool stuck : {true, false}) {
    const auto guess = s.linearized(omega, stuck);
    if (!guess) continue;
    Evaluation e = evaluate(s, *linear, *guess);
    if (e.ok) limits.emplace_back(*guess, std::move(e));
  }
  std::sort(limits.begin(), limits.end(), [](const auto& a, const auto& b) { return a.second.norm < b.second.norm; });
  if (limits.empty() && !initial) {
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.unknowns());
    limits.emplace_back(zero, evaluate(s, *linear, zero));
  }
  for (auto& [x, e] : limits)
    if (attempt(std::move(x), std::move(e))) return best;
  return best;
}

CycleEnergy cycle_energy(const HarmonicBalance& s, const HbmSolution& solution) {
  const Eigen::MatrixXd q = s.recover(solution.x, solution.omega);
  const HbmModel& model = s.model();
  const Index n = q.rows();
  const int harmonics = s.options().harmonics;
  CycleEnergy e;
  // Excitation: harmonic 1 only, f = Re F cos - Im F sin.
  for (Index i = 0; i < n; ++i) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(q.cols()), qi = q.row(i).transpose();
    f[1] = model.harmonic_load[i].real();
    f[2] = -model.harmonic_load[i].imag();
    e.excitation += contact::cycle_work(f, qi);
  }
  // Viscous: integral over a period of q'^T C q' = pi h^2 w (a^T C a + b^T C b) per harmonic.
  if (model.damping.size() > 0)
    for (int h = 1; h <= harmonics; ++h) {
      const Eigen::VectorXd a = q.col(2 * h - 1), b = q.col(2 * h);
      e.viscous += std::numbers::pi * h * h * solution.omega * (a.dot(model.damping * a) + b.dot(model.damping * b));
    }
  for (size_t k = 0; k < solution.contacts.size() && k < model.contacts.size(); ++k) {
    const contact::AftResult& r = solution.contacts[k];
    const Eigen::VectorXd u = (model.contacts[k].tangential * q).transpose();
    const Eigen::VectorXd v = (model.contacts[k].normal * q).transpose();
    e.friction += contact::cycle_work(r.tangential, u);
    e.normal += contact::cycle_work(r.normal, v);
  }
  return e;
}

// ---------------------------------------------------------------------------------------------
// Continuation. Scaled unknowns y = (x / x_ref, omega / omega_ref); R(y) as above. Each step:
// tangent t (J_y t = 0, |t| = 1, oriented like the previous one), predictor y_p = y + s t,
// corrector Newton on {R(y) = 0, t . (y - y_p) = 0} with backtracking on ||(R / r_ref, g)||.

namespace {

struct PathState {
  Eigen::VectorXd y;  // scaled (x, omega)
  Eigen::VectorXd tangent;
};

}  // namespace

ContinuationResult continue_in_frequency(const HarmonicBalance& s, const ContinuationOptions& o) {
  if (!(o.omega_start > 0.0) || !(o.omega_end > 0.0) || !std::isfinite(o.omega_start) || !std::isfinite(o.omega_end) ||
      o.omega_start == o.omega_end)
    throw std::invalid_argument("continuation: omega_start and omega_end must be finite, > 0 and distinct");
  if (!(o.min_step > 0.0) || !(o.initial_step >= o.min_step) || !(o.max_step >= o.initial_step) || !(o.grow >= 1.0) ||
      !(o.shrink > 0.0 && o.shrink < 1.0) || o.max_points < 2 || o.max_corrector_iterations < 1)
    throw std::invalid_argument(
        "continuation: need 0 < min_step <= initial_step <= max_step, grow >= 1, 0 < shrink < 1, max_points >= 2, "
        "max_corrector_iterations >= 1");

  ContinuationResult result;
  const Index m = s.unknowns();
  const Index nc = static_cast<Index>(s.contact_dofs().size());
  const double direction = o.omega_end > o.omega_start ? 1.0 : -1.0;
  const double w_ref = o.omega_start;
  const double target = target_norm(s);
  const double r_ref = s.force_scale() > 0.0 ? s.force_scale() : 1.0;

  HbmSolution first = solve_at_frequency(s, o.omega_start, o.initial);
  if (!first.converged) {
    result.failure = "first point: " + first.failure;
    return result;
  }
  double x_ref = o.amplitude_scale;
  if (!(x_ref > 0.0)) x_ref = first.x.tail(m - nc).norm();
  if (!(x_ref > 0.0)) x_ref = first.x.norm();
  if (!(x_ref > 0.0)) x_ref = 1.0;
  result.amplitude_scale = x_ref;

  const auto amplitude = [&](const Eigen::VectorXd& x) {
    double a = 0.0;
    for (Index i = 0; i < nc; ++i) a = std::max(a, std::hypot(x[nc + i], x[2 * nc + i]));
    return a;
  };
  const auto unscale = [&](const Eigen::VectorXd& y, Eigen::VectorXd& x, double& w) {
    x = y.head(m) * x_ref;
    w = y[m] * w_ref;
  };
  // R and the scaled Jacobian [dR/dx x_ref, dR/domega w_ref] at y; dR/domega by central differences
  // of the linear part (the contact forces do not depend on omega).
  struct Augmented {
    Eigen::VectorXd residual;
    double norm = std::numeric_limits<double>::infinity();
    Eigen::MatrixXd jacobian;  // m x (m + 1), scaled columns
    std::vector<contact::AftResult> contacts;
    bool ok = false;
  };
  const auto evaluate_at = [&](const Eigen::VectorXd& y, bool with_jacobian) {
    Augmented a;
    Eigen::VectorXd x;
    double w = 0.0;
    unscale(y, x, w);
    if (!x.allFinite() || !(w > 0.0)) return a;
    const auto linear = s.condense(w);
    if (!linear) return a;
    Evaluation e = evaluate(s, *linear, x);
    if (!e.ok) return a;
    a.residual = e.residual;
    a.norm = e.norm;
    a.ok = true;
    if (with_jacobian) {
      const double dw = 1e-6 * w;
      const auto plus = s.condense(w + dw), minus = s.condense(w - dw);
      if (!plus || !minus) {
        a.ok = false;
        return a;
      }
      const Eigen::VectorXd drdw =
          ((plus->operator_ - minus->operator_) * x - (plus->load - minus->load)) / (2.0 * dw);
      a.jacobian.resize(m, m + 1);
      a.jacobian.leftCols(m) = (linear->operator_ + e.forces.jacobian) * x_ref;
      a.jacobian.col(m) = drdw * w_ref;
      if (!a.jacobian.allFinite()) a.ok = false;
    }
    a.contacts = std::move(e.forces.contacts);
    return a;
  };
  const auto tangent_at = [&](const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& previous) {
    Eigen::MatrixXd a(m + 1, m + 1);
    a.topRows(m) = jacobian;
    a.row(m) = previous.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
    rhs[m] = 1.0;
    Eigen::VectorXd t = a.fullPivLu().solve(rhs);
    if (!t.allFinite() || t.norm() == 0.0) return Eigen::VectorXd();
    t.normalize();
    if (t.dot(previous) < 0.0) t = -t;
    return Eigen::VectorXd(t);
  };

  PathState state;
  state.y.resize(m + 1);
  state.y.head(m) = first.x / x_ref;
  state.y[m] = 1.0;
  Augmented at = evaluate_at(state.y, true);
  Eigen::VectorXd seed = Eigen::VectorXd::Zero(m + 1);
  seed[m] = direction;
  state.tangent = at.ok ? tangent_at(at.jacobian, seed) : Eigen::VectorXd();
  if (state.tangent.size() == 0) {
    result.failure = fmt::format("no tangent at the first point (|R| = {:.3g} N, omega = {:.6g} rad/s)", first.residual,
                                 o.omega_start);
    return result;
  }
  result.points.push_back({o.omega_start, first.x, first.residual, first.iterations, 0.0, state.tangent[m]});
  if (o.progress) o.progress({0, o.omega_start, amplitude(first.x), 0.0, first.iterations});

  double step = o.initial_step, last_good_step = o.initial_step;
  int jumps = 0;
  const double w_end_scaled = o.omega_end / w_ref;
  while (true) {
    if (static_cast<int>(result.points.size()) >= o.max_points) {
      result.failure = fmt::format("stopped after {} points at omega = {:.6g} rad/s (|R| = {:.3g} N) before omega_end",
                                   result.points.size(), result.points.back().omega, result.points.back().residual);
      break;
    }
    const Eigen::VectorXd predicted = state.y + step * state.tangent;
    Eigen::VectorXd y = predicted;
    Augmented cur = evaluate_at(y, true);
    bool converged = false;
    int iterations = 0;
    double last_norm = cur.norm;
    for (; cur.ok && iterations <= o.max_corrector_iterations; ++iterations) {
      const double g = state.tangent.dot(y - predicted);
      if (cur.norm <= target && std::abs(g) <= 1e-6 * step) {
        converged = true;
        break;
      }
      if (iterations == o.max_corrector_iterations) break;
      Eigen::MatrixXd a(m + 1, m + 1);
      a.topRows(m) = cur.jacobian;
      a.row(m) = state.tangent.transpose();
      Eigen::VectorXd rhs(m + 1);
      rhs.head(m) = -cur.residual;
      rhs[m] = -g;
      const Eigen::VectorXd dy = minimum_norm_solve(a, rhs);
      if (!dy.allFinite()) break;
      const auto merit = [&](const Augmented& e, const Eigen::VectorXd& yy) {
        return std::hypot(e.norm / r_ref, state.tangent.dot(yy - predicted));
      };
      const double m0 = merit(cur, y);
      double alpha = 1.0;
      bool accepted = false;
      for (int b = 0; b <= s.options().max_backtracks; ++b, alpha *= 0.5) {
        const Eigen::VectorXd trial_y = y + alpha * dy;
        Augmented trial = evaluate_at(trial_y, true);
        if (trial.ok && merit(trial, trial_y) <= (1.0 - 1e-4 * alpha) * m0) {
          y = trial_y;
          cur = std::move(trial);
          accepted = true;
          break;
        }
      }
      if (!accepted) break;
      last_norm = cur.norm;
    }
    result.corrector_iterations += iterations;
    if (!converged) {
      ++result.rejected_steps;
      // Where the path crosses a grazing or stick-slip switch, a point can sit on a kink of the
      // piecewise-smooth R that Newton cannot reach to tolerance from either side. Shrinking does
      // not help there; stepping over the kink does: after the step falls below min_step, try
      // steps 1, 4, 16, 64 times max(last accepted, initial_step) (one corrector each) before giving up.
      if (jumps > 0 || step * o.shrink < o.min_step) {
        if (jumps < 4) {
          ++jumps;
          step = std::min(o.max_step, std::max(last_good_step, o.initial_step) * std::pow(4.0, jumps - 1));
          continue;
        }
        step = 0.0;
      }
      step *= o.shrink;
      if (step < o.min_step) {
        result.failure = fmt::format(
            "corrector failed with step below min_step {:.3g} near omega = {:.6g} rad/s (|R| = {:.3g} N, target {:.3g} "
            "N)",
            o.min_step, result.points.back().omega, std::isfinite(last_norm) ? last_norm : -1.0, target);
        break;
      }
      continue;
    }
    Eigen::VectorXd t = tangent_at(cur.jacobian, state.tangent);
    if (t.size() == 0) {
      ++result.rejected_steps;
      step *= o.shrink;
      if (step < o.min_step) {
        result.failure = fmt::format("no tangent near omega = {:.6g} rad/s", result.points.back().omega);
        break;
      }
      continue;
    }
    if (jumps > 0) ++result.jumps;
    jumps = 0;
    last_good_step = step;
    if ((t[m] > 0.0) != (state.tangent[m] > 0.0) && t[m] != 0.0 && state.tangent[m] != 0.0) ++result.turning_points;
    state.y = y;
    state.tangent = t;
    Eigen::VectorXd x;
    double w = 0.0;
    unscale(y, x, w);
    result.points.push_back({w, x, cur.norm, iterations, step, t[m]});
    if (o.progress)
      o.progress({static_cast<int>(result.points.size()) - 1, w, amplitude(x), step, iterations});
    if (direction * (y[m] - w_end_scaled) >= 0.0) {
      result.converged = true;
      break;
    }
    if (direction * (y[m] - 1.0) < -0.5 * std::abs(w_end_scaled - 1.0)) {
      result.failure = fmt::format("the path turned back past omega_start (omega = {:.6g} rad/s)", w);
      break;
    }
    if (iterations <= o.easy_iterations) step = std::min(o.max_step, step * o.grow);
  }
  return result;
}

}  // namespace bb::hbm
