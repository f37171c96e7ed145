#include "hbm/hill_stability.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace bb::hbm {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;

// kron(A, B) for a coefficient-major layout: block (j, k) = A(j, k) B.
void add_kron(MatrixXd& into, const MatrixXd& a, const MatrixXd& b, double scale = 1.0) {
  const Index n = b.rows();
  for (Index j = 0; j < a.rows(); ++j)
    for (Index k = 0; k < a.cols(); ++k)
      if (a(j, k) != 0.0) into.block(j * n, k * n, n, n) += scale * a(j, k) * b;
}

}  // namespace

double HillStability::verdict() const {
  if (!ok) return std::numeric_limits<double>::quiet_NaN();
  return stable ? 1.0 : growing ? 0.0 : std::numeric_limits<double>::quiet_NaN();
}

double marginal_tolerance(double omega) { return 1e-7 * std::max(omega, 1.0); }

HillStability hill_stability(const HarmonicBalance& system, const Eigen::VectorXd& x, double omega) {
  HillStability out;
  const friction::FrictionModel& m = system.model();
  const Index n = m.mass.rows();
  const int harmonics = system.options().harmonics;
  const Index nh = 2 * harmonics + 1;
  const Index size = n * nh;
  MatrixXd nabla = MatrixXd::Zero(nh, nh);
  for (int h = 1; h <= harmonics; ++h) {
    nabla(2 * h - 1, 2 * h) = h * omega;
    nabla(2 * h, 2 * h - 1) = -h * omega;
  }
  const MatrixXd identity = MatrixXd::Identity(nh, nh);
  const MatrixXd damping = m.damping.size() ? m.damping : MatrixXd::Zero(n, n);
  MatrixXd d0 = MatrixXd::Zero(size, size), d1 = MatrixXd::Zero(size, size);
  add_kron(d0, nabla * nabla, m.mass);
  add_kron(d0, nabla, damping);
  add_kron(d0, identity, m.stiffness);
  add_kron(d1, nabla, m.mass, 2.0);
  add_kron(d1, identity, damping);
  // The contact forces' Jacobian, from the contact-DOF layout x[j nc + i] to the full q[j n + d].
  const HarmonicBalance::ContactForces forces = system.contact_forces(x);
  const auto& cd = system.contact_dofs();
  const Index nc = static_cast<Index>(cd.size());
  for (Index j = 0; j < nh; ++j)
    for (Index i = 0; i < nc; ++i)
      for (Index k = 0; k < nh; ++k)
        for (Index l = 0; l < nc; ++l) d0(j * n + cd[i], k * n + cd[l]) += forces.jacobian(j * nc + i, k * nc + l);
  if (!d0.allFinite()) {
    out.failure = "the Jacobian of the balance is not finite";
    return out;
  }
  // lambda^2 (I x M) P + lambda Delta1 P + Delta0 P = 0 as a first-order problem in [P; lambda P].
  const Eigen::LLT<MatrixXd> mass(m.mass);
  if (mass.info() != Eigen::Success) {
    out.failure = "the mass matrix is not positive definite (Hill's method here needs M^-1)";
    return out;
  }
  MatrixXd companion = MatrixXd::Zero(2 * size, 2 * size);
  companion.topRightCorner(size, size).setIdentity();
  for (Index j = 0; j < nh; ++j) {
    companion.block(size + j * n, 0, n, size) = -mass.solve(d0.middleRows(j * n, n));
    companion.block(size + j * n, size, n, size) = -mass.solve(d1.middleRows(j * n, n));
  }
  const Eigen::EigenSolver<MatrixXd> eig(companion, false);
  if (eig.info() != Eigen::Success) {
    out.failure = "the eigensolver did not converge";
    return out;
  }
  const Eigen::VectorXcd all = eig.eigenvalues();
  std::vector<Index> order(static_cast<size_t>(all.size()));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return std::abs(all[a].imag()) < std::abs(all[b].imag()); });
  out.exponents.resize(2 * n);
  for (Index i = 0; i < 2 * n; ++i) out.exponents[i] = all[order[static_cast<size_t>(i)]];
  std::sort(out.exponents.begin(), out.exponents.end(),
            [](const std::complex<double>& a, const std::complex<double>& b) { return a.real() > b.real(); });
  // A kept exponent beyond the band the H harmonics resolve, |Im| > (H + 1/2) omega, belongs to a
  // mode none of whose copies is central: its real part is spoiled by the truncation (the mode's
  // time-varying stiffness needs harmonics up to its own frequency), so its growth is unresolved.
  const double band = (harmonics + 0.5) * omega, tolerance = marginal_tolerance(omega);
  out.max_real = -std::numeric_limits<double>::infinity();
  for (const std::complex<double>& l : out.exponents) {
    if (std::abs(l.imag()) <= band) {
      out.max_real = std::max(out.max_real, l.real());
    } else if (l.real() > tolerance && (out.unresolved.empty() || l.real() > out.unresolved_real)) {
      out.unresolved_real = l.real();
      out.unresolved = fmt::format(
          "an exponent {:.4g} {:+.4g}i 1/s lies beyond the band the {} harmonic(s) resolve (|Im| <= (H + 1/2) omega = "
          "{:.4g} 1/s): its growth is not resolved; raise H",
          l.real(), l.imag(), harmonics, band);
    }
  }
  out.growing = out.max_real > tolerance;
  if (out.growing) out.unresolved.clear();
  out.stable = !out.growing && out.unresolved.empty();
  out.ok = true;
  return out;
}

}  // namespace bb::hbm
