#include "ffrf/rotating_modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb::ffrf {
namespace {

struct DenseOperators {
  Eigen::MatrixXd m, k, mp, g, ks;
};

DenseOperators dense_operators(const ProjectedBody& body, const RotatingModesOptions& o) {
  if (o.n_modes < 1) throw InputError(fmt::format("rotating modes: n_modes must be >= 1, got {}", o.n_modes));
  if (o.n_modes > body.n())
    throw InputError(
        fmt::format("rotating modes: {} modes asked from an elastic basis of {} coordinates; ask for "
                    "fewer modes or enlarge the basis",
                    o.n_modes, body.n()));
  if (!body.mass.is_dense() && body.n() > o.max_dense_size)
    throw InputError(
        fmt::format("rotating modes of a nodal basis of {} coordinates need a dense {}x{} state-space "
                    "eigenproblem; use a modal elastic basis (BasisKind::modal) or raise max_dense_size",
                    body.n(), 2 * body.n(), 2 * body.n()));
  return {body.mass.to_dense(), body.stiffness.to_dense(), body.projected_mass.to_dense(), body.gyroscopic.to_dense(),
          body.geometric_stiffness.to_dense()};
}

// Eigenvalues of M s^2 + C s + K_eff = 0. First the symmetric problem K_eff psi = lambda M psi
// (accurate, any sign of lambda); in its coordinates z the equations read z'' + C~ z' + Lambda z = 0,
// C~ = Psi^T C Psi skew, and with the state x = [W z; z'], W = diag(sqrt|lambda|), the first-order
// matrix [0 W; -Lambda W^-1 -C~] has entries of the size of the frequencies rather than of their
// squares: the small eigenvalues keep their relative accuracy next to the large ones.
Eigen::VectorXcd state_space_eigenvalues(const DenseOperators& ops, double speed, const RotatingModesOptions& o) {
  const double s = o.stiffening ? 1.0 : 0.0, w2 = speed * speed;
  const Eigen::MatrixXd k_eff = ops.k + (s * w2) * ops.ks - w2 * ops.mp;
  const DenseEigen<double> sym = symmetric_eigen(k_eff, ops.m);
  if (!sym.ok) throw SolverError(fmt::format("rotating modes at {} rad/s: eigensolver failed", speed));
  const Eigen::VectorXd lambda = sym.values;
  const Eigen::Index n = lambda.size();
  Eigen::VectorXcd out(2 * n);
  if (!o.coriolis || speed == 0.0) {  // s = +-sqrt(-lambda): purely imaginary or a real pair
    for (Eigen::Index i = 0; i < n; ++i) {
      const double r = std::sqrt(std::abs(lambda[i]));
      out[2 * i] = lambda[i] >= 0.0 ? std::complex<double>(0.0, r) : std::complex<double>(r, 0.0);
      out[2 * i + 1] = -out[2 * i];
    }
    return out;
  }
  const Eigen::MatrixXd& psi = sym.vectors;
  const Eigen::MatrixXd c = psi.transpose() * ((2.0 * speed) * ops.g) * psi;
  const double w_floor = 1e-12 * std::sqrt(lambda.cwiseAbs().maxCoeff());
  Eigen::VectorXd w(n);
  for (Eigen::Index i = 0; i < n; ++i) w[i] = std::max(std::sqrt(std::abs(lambda[i])), w_floor);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n) = w.asDiagonal();
  a.bottomLeftCorner(n, n) = (-lambda.cwiseQuotient(w)).asDiagonal();
  a.bottomRightCorner(n, n) = -c;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(a, false);
  if (eig.info() != Eigen::Success)
    throw SolverError(fmt::format("rotating modes at {} rad/s: eigensolver failed", speed));
  return eig.eigenvalues();
}

RotatingModes modes_at(const DenseOperators& ops, double speed, const RotatingModesOptions& o) {
  const Eigen::VectorXcd lambda = state_space_eigenvalues(ops, speed, o);
  const double scale = lambda.cwiseAbs().maxCoeff();
  const double tol = 1e-12 * scale;
  // One eigenvalue per mode: Im > 0 for an oscillation, the non-negative one of a real pair.
  std::vector<std::pair<double, double>> modes;  // (omega, growth)
  double max_growth = 0.0;
  for (const auto& l : lambda) {
    max_growth = std::max(max_growth, l.real());
    if (l.imag() > tol)
      modes.emplace_back(l.imag(), l.real());
    else if (std::abs(l.imag()) <= tol && l.real() >= 0.0)
      modes.emplace_back(0.0, l.real());
  }
  std::sort(modes.begin(), modes.end());
  RotatingModes r;
  r.speed = speed;
  const auto kept = static_cast<Eigen::Index>(std::min<size_t>(modes.size(), static_cast<size_t>(o.n_modes)));
  r.frequencies_hz.resize(kept);
  r.growth_rates.resize(kept);
  for (Eigen::Index i = 0; i < kept; ++i) {
    r.frequencies_hz[i] = modes[static_cast<size_t>(i)].first / kTwoPi;
    r.growth_rates[i] = modes[static_cast<size_t>(i)].second;
  }
  r.max_growth_rate = max_growth;
  r.stable = max_growth <= 1e-9 * scale;
  return r;
}

// Secant refinement of f_k(Omega) - EO Omega / 2 pi = 0 between two bracketing speeds.
double refine_crossing(const DenseOperators& ops, const RotatingModesOptions& o, int mode, int eo, double w0, double d0,
                       double w1, double d1) {
  for (int it = 0; it < 30 && std::abs(w1 - w0) > 1e-10 * std::max(std::abs(w1), 1.0); ++it) {
    if (d1 == d0) break;
    const double w = w1 - d1 * (w1 - w0) / (d1 - d0);
    const RotatingModes m = modes_at(ops, w, o);
    if (mode >= m.frequencies_hz.size()) break;
    const double d = m.frequencies_hz[mode] - eo * w / kTwoPi;
    w0 = w1;
    d0 = d1;
    w1 = w;
    d1 = d;
  }
  return w1;
}

}  // namespace

RotatingModes rotating_modes(const ProjectedBody& body, double speed, const RotatingModesOptions& options) {
  return modes_at(dense_operators(body, options), speed, options);
}

CampbellDiagram campbell_diagram(const ProjectedBody& body, const std::vector<double>& speeds,
                                 const RotatingModesOptions& options) {
  const DenseOperators ops = dense_operators(body, options);
  CampbellDiagram c;
  c.speeds = speeds;
  c.frequencies_hz = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(speeds.size()), options.n_modes);
  for (size_t i = 0; i < speeds.size(); ++i) {
    const RotatingModes m = modes_at(ops, speeds[i], options);
    c.frequencies_hz.row(static_cast<Eigen::Index>(i)).head(m.frequencies_hz.size()) = m.frequencies_hz.transpose();
    c.stable.push_back(m.stable);
  }
  return c;
}

std::vector<EngineOrderCrossing> engine_order_crossings(const ProjectedBody& body, const CampbellDiagram& diagram,
                                                        const std::vector<int>& engine_orders,
                                                        const RotatingModesOptions& options) {
  const DenseOperators ops = dense_operators(body, options);
  std::vector<EngineOrderCrossing> out;
  const auto& w = diagram.speeds;
  for (int eo : engine_orders) {
    for (Eigen::Index k = 0; k < diagram.frequencies_hz.cols(); ++k) {
      for (size_t i = 0; i + 1 < w.size(); ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        const double d0 = diagram.frequencies_hz(r, k) - eo * w[i] / kTwoPi;
        const double d1 = diagram.frequencies_hz(r + 1, k) - eo * w[i + 1] / kTwoPi;
        if (d0 == 0.0 || d0 * d1 >= 0.0) {
          if (d0 == 0.0) out.push_back({eo, static_cast<int>(k) + 1, w[i], eo * w[i] / kTwoPi});
          continue;
        }
        const double ws = refine_crossing(ops, options, static_cast<int>(k), eo, w[i], d0, w[i + 1], d1);
        out.push_back({eo, static_cast<int>(k) + 1, ws, eo * ws / kTwoPi});
      }
    }
  }
  return out;
}

double time_step_resolving(const ProjectedBody& body, double speed, int mode, int steps_per_period,
                           const RotatingModesOptions& options) {
  if (mode < 1 || steps_per_period < 1) throw InputError("time_step_resolving: mode and steps_per_period must be >= 1");
  RotatingModesOptions o = options;
  o.n_modes = std::max(o.n_modes, mode);
  const RotatingModes m = rotating_modes(body, speed, o);
  const auto k = static_cast<Eigen::Index>(mode - 1);
  if (k >= m.frequencies_hz.size() || !(m.frequencies_hz[k] > 0.0))
    throw SolverError(
        fmt::format("time_step_resolving: mode {} at {} rad/s has no positive frequency (diverging, "
                    "or beyond the basis)",
                    mode, speed));
  return 1.0 / (steps_per_period * m.frequencies_hz[k]);
}

double divergence_speed(const ProjectedBody& body, bool stiffening) {
  // K phi = lambda (M_p - s K_s1) phi with K > 0: the largest mu of L^-1 (M_p - s K_s1) L^-T
  // (K = L L^T) gives the lowest positive lambda = Omega^2 = 1 / mu.
  const Eigen::MatrixXd k = body.stiffness.to_dense();
  const Eigen::MatrixXd soft =
      body.projected_mass.to_dense() - (stiffening ? 1.0 : 0.0) * body.geometric_stiffness.to_dense();
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  if (llt.info() != Eigen::Success) throw SolverError("divergence speed: stiffness not positive definite");
  const Eigen::MatrixXd li = llt.matrixL().solve(Eigen::MatrixXd::Identity(k.rows(), k.cols()));
  Eigen::MatrixXd b = li * soft * li.transpose();
  b = 0.5 * (b + b.transpose()).eval();
  const double mu = symmetric_eigen(b, false).values.maxCoeff();
  return mu > 0.0 ? 1.0 / std::sqrt(mu) : std::numeric_limits<double>::infinity();
}

StaticDeflection centrifugal_deflection(const RotatingBody& body, double speed, const StaticDeflectionOptions& o) {
  if (!std::isfinite(speed) || !o.gravity.allFinite() || (body.dim == 2 && o.gravity.z() != 0.0))
    throw InputError("static centrifugal deflection: speed and gravity must be finite (gravity in the plane in 2D)");
  const double w2 = speed * speed, s = o.stiffening ? 1.0 : 0.0;
  Eigen::SparseMatrix<double> op = body.stiffness + (s * w2) * body.geometric_stiffness - w2 * body.projected_mass;
  op.makeCompressed();
  const Eigen::VectorXd g_body = axis_rotation(body, o.angle).transpose() * o.gravity.head(body.dim);
  const Eigen::VectorXd load = w2 * body.centrifugal_load + body.gravity_load * g_body;
  // LDL^T without pivoting: by Sylvester's law of inertia the operator is positive definite iff
  // every pivot of D is. (linalg/spd_factor cannot tell: CHOLMOD's simplicial LDL^T, which it
  // uses on small models, accepts negative pivots.)
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(op);
  const Eigen::VectorXd d = ldlt.info() == Eigen::Success ? ldlt.vectorD() : Eigen::VectorXd();
  const double d_max = d.size() ? d.cwiseAbs().maxCoeff() : 0.0;
  const long negative = d.size() ? (d.array() <= 1e-13 * d_max).count() : -1;
  if (negative != 0)
    throw SolverError(
        fmt::format("static centrifugal deflection at Omega = {:.6g} rad/s: K{} - Omega^2 M_p is not "
                    "positive definite ({} non-positive pivots); the speed is at or above the "
                    "divergence speed of the spin-softened model, which has no stable steady state there",
                    speed, o.stiffening ? " + Omega^2 K_sigma1" : "", negative));
  StaticDeflection out;
  out.speed = speed;
  out.displacement = ldlt.solve(load);
  out.pivot_ratio = d.cwiseAbs().minCoeff() / d_max;
  const double scale = load.norm() + (body.stiffness * out.displacement).norm();
  out.relative_residual = scale > 0.0 ? (op * out.displacement - load).norm() / scale : 0.0;
  return out;
}

}  // namespace bb::ffrf
