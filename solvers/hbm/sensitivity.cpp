#include "hbm/sensitivity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"

namespace bb::hbm {

namespace {

using Index = Eigen::Index;
using Complex = std::complex<double>;

// Rows x cols of K + i hw C - hw^2 M for any (M, C, K), also for their derivatives; empty = zero.
Eigen::MatrixXcd block(const Eigen::MatrixXd& k, const Eigen::MatrixXd& c, const Eigen::MatrixXd& m, double hw,
                       const std::vector<Index>& rows, const std::vector<Index>& cols) {
  Eigen::MatrixXcd d = Eigen::MatrixXcd::Zero(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  for (Index i = 0; i < d.rows(); ++i)
    for (Index j = 0; j < d.cols(); ++j) {
      const Index r = rows[static_cast<size_t>(i)], s = cols[static_cast<size_t>(j)];
      double re = 0.0, im = 0.0;
      if (k.size() > 0) re += k(r, s);
      if (m.size() > 0) re -= hw * hw * m(r, s);
      if (c.size() > 0) im += hw * c(r, s);
      d(i, j) = Complex(re, im);
    }
  return d;
}

Eigen::VectorXcd rows_of(const Eigen::VectorXcd& v, const std::vector<Index>& rows) {
  Eigen::VectorXcd s(static_cast<Index>(rows.size()));
  for (Index i = 0; i < s.size(); ++i) s[i] = v[rows[static_cast<size_t>(i)]];
  return s;
}

void check_sizes(const friction::FrictionModel& model, const std::vector<ModelDerivative>& derivatives) {
  const Index n = model.mass.rows();
  for (size_t j = 0; j < derivatives.size(); ++j) {
    const ModelDerivative& d = derivatives[j];
    const auto square = [n](const Eigen::MatrixXd& a) { return a.size() == 0 || (a.rows() == n && a.cols() == n); };
    if (!square(d.mass) || !square(d.damping) || !square(d.stiffness))
      throw std::invalid_argument(
          fmt::format("sensitivity: derivative {}: dM, dC and dK must be empty or {} x {}", j, n, n));
    if ((d.static_load.size() != 0 && d.static_load.size() != n) ||
        (d.harmonic_load.size() != 0 && d.harmonic_load.size() != n) ||
        std::any_of(d.higher_loads.begin(), d.higher_loads.end(),
                    [n](const Eigen::VectorXcd& f) { return f.size() != 0 && f.size() != n; }))
      throw std::invalid_argument(
          fmt::format("sensitivity: derivative {}: load derivatives must be empty or have {} entries", j, n));
    if (!d.laws.empty() && d.laws.size() != model.contacts.size())
      throw std::invalid_argument(fmt::format("sensitivity: derivative {}: {} law derivatives for {} contacts", j,
                                              d.laws.size(), model.contacts.size()));
  }
}

// Complex amplitude of harmonic h from real coefficient columns: Z = a - i b (harmonic_balance.hpp).
Eigen::VectorXcd harmonic(const Eigen::MatrixXd& q, int h) {
  if (h == 0) return q.col(0).cast<Complex>();
  return q.col(2 * h - 1).cast<Complex>() - Complex(0.0, 1.0) * q.col(2 * h).cast<Complex>();
}

struct Sensitivities {
  Eigen::MatrixXd dx;               // unknowns x P
  std::vector<Eigen::MatrixXd> dq;  // n x m per parameter, when asked for
};

Sensitivities compute(const HarmonicBalance& s, const HbmSolution& solution,
                      const std::vector<ModelDerivative>& derivatives, bool with_response) {
  if (!solution.converged)
    throw SolverError("sensitivity: the solution is not converged (" + solution.failure +
                      "); the implicit function theorem needs R = 0");
  if (solution.x.size() != s.unknowns())
    throw std::invalid_argument(
        fmt::format("sensitivity: x has {} entries, expected {}", solution.x.size(), s.unknowns()));
  const friction::FrictionModel& model = s.model();
  check_sizes(model, derivatives);
  const double omega = solution.omega;
  const int harmonics = s.options().harmonics;
  const Index n = model.mass.rows(), m = friction::harmonic_size(harmonics);
  const std::vector<Index>& c = s.contact_dofs();
  const Index nc = static_cast<Index>(c.size());
  const std::vector<Index>& o = s.other_dofs();
  const Index no = static_cast<Index>(o.size()), np = static_cast<Index>(derivatives.size());

  const auto linear = s.condense(omega);
  if (!linear) throw SolverError(fmt::format("sensitivity: D_oo singular at omega = {} rad/s", omega));
  const HarmonicBalance::ContactForces forces = s.contact_forces(solution.x);
  const Eigen::PartialPivLU<Eigen::MatrixXd> jacobian(linear->operator_ + forces.jacobian);
  if (!(jacobian.rcond() >= kSingularRcond))
    throw SolverError(
        fmt::format("sensitivity: the Jacobian is singular at omega = {} rad/s (rcond {:.2e}): dx/dp "
                    "is not unique (a free static position?)",
                    omega, jacobian.rcond()));
  const Eigen::MatrixXd q = s.recover(solution.x, omega);

  // dR/dp at fixed x, one column per parameter, in the real layout of the unknowns.
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(s.unknowns(), np);
  // Per harmonic and parameter, D_oo^-1 r_o, kept for the recovery of dq_o.
  std::vector<std::vector<Eigen::VectorXcd>> condensed_o(static_cast<size_t>(harmonics + 1));
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXcd>> doo_lu(static_cast<size_t>(harmonics + 1));
  for (int h = 0; h <= harmonics; ++h) {
    const double hw = h * omega;
    const Eigen::VectorXcd qh = harmonic(q, h);
    Eigen::MatrixXcd dco;
    if (no > 0) {
      doo_lu[static_cast<size_t>(h)].compute(block(model.stiffness, model.damping, model.mass, hw, o, o));
      dco = block(model.stiffness, model.damping, model.mass, hw, c, o);
    }
    for (Index j = 0; j < np; ++j) {
      const ModelDerivative& d = derivatives[static_cast<size_t>(j)];
      Eigen::VectorXcd r = Eigen::VectorXcd::Zero(n);
      if (d.stiffness.size() > 0) r += d.stiffness * qh;
      if (d.mass.size() > 0) r -= hw * hw * (d.mass * qh);
      if (d.damping.size() > 0) r += Complex(0.0, hw) * (d.damping * qh);
      if (h == 0 && d.static_load.size() > 0) r -= d.static_load.cast<Complex>();
      if (h == 1 && d.harmonic_load.size() > 0) r -= d.harmonic_load;
      if (h >= 2 && static_cast<size_t>(h - 2) < d.higher_loads.size() && d.higher_loads[h - 2].size() > 0)
        r -= d.higher_loads[static_cast<size_t>(h - 2)];
      Eigen::VectorXcd rc = rows_of(r, c);
      if (no > 0) {
        Eigen::VectorXcd y = doo_lu[static_cast<size_t>(h)].solve(rows_of(r, o));
        rc -= dco * y;
        condensed_o[static_cast<size_t>(h)].push_back(std::move(y));
      }
      // Residual rows (Re r, -Im r) as in HarmonicBalance::condense.
      if (h == 0)
        rhs.col(j).head(nc) = rc.real();
      else {
        rhs.col(j).segment((2 * h - 1) * nc, nc) = rc.real();
        rhs.col(j).segment(2 * h * nc, nc) = -rc.imag();
      }
    }
  }

  bool any_law = false;
  for (const ModelDerivative& d : derivatives) any_law = any_law || !d.laws.empty();
  if (any_law) {
    // A second AFT per contact, with the law derivatives: contact_forces keeps the Newton's cost.
    friction::AftOptions options = s.aft_options();
    options.law_derivatives = true;
    const Eigen::Map<const Eigen::MatrixXd> coefficients(solution.x.data(), nc, m);
    for (size_t k = 0; k < model.contacts.size(); ++k) {
      const friction::ContactElement& e = model.contacts[k];
      if (e.cyclic())
        throw std::invalid_argument("harmonic-balance sensitivities: a cyclic contact's law derivatives are not built");
      Eigen::RowVectorXd at(nc), an(nc);
      for (Index i = 0; i < nc; ++i)
        at[i] = e.tangential[c[static_cast<size_t>(i)]], an[i] = e.normal[c[static_cast<size_t>(i)]];
      Eigen::VectorXd u = (at * coefficients).transpose();
      const Eigen::VectorXd v = (an * coefficients).transpose();
      u[0] -= e.tangential_offset;
      const friction::AftResult r = e.law->harmonics(e.point, u, v, options);
      for (Index j = 0; j < np; ++j) {
        const ModelDerivative& d = derivatives[static_cast<size_t>(j)];
        if (d.laws.empty()) continue;
        const friction::PointParameters& dl = d.laws[k];
        const Eigen::Vector4d theta(dl.kn, dl.kt, dl.mu, dl.n0);
        const Eigen::VectorXd dt = r.dtangential_dlaw * theta, dn = r.dnormal_dlaw * theta;
        Eigen::Map<Eigen::MatrixXd> column(rhs.col(j).data(), nc, m);
        column += at.transpose() * dt.transpose() + an.transpose() * dn.transpose();
      }
    }
  }

  Sensitivities out;
  out.dx = -jacobian.solve(rhs);
  if (!out.dx.allFinite()) throw SolverError("sensitivity: non-finite dx/dp (singular Jacobian)");
  if (!with_response) return out;

  for (Index j = 0; j < np; ++j) {
    Eigen::MatrixXd dq = Eigen::MatrixXd::Zero(n, m);
    const Eigen::Map<const Eigen::MatrixXd> dxc(out.dx.col(j).data(), nc, m);
    for (Index i = 0; i < nc; ++i) dq.row(c[static_cast<size_t>(i)]) = dxc.row(i);
    for (int h = 0; h <= harmonics && no > 0; ++h) {
      const Eigen::MatrixXcd doc = block(model.stiffness, model.damping, model.mass, h * omega, o, c);
      const Eigen::VectorXcd dqo = -condensed_o[static_cast<size_t>(h)][static_cast<size_t>(j)] -
                                   doo_lu[static_cast<size_t>(h)].solve(doc * harmonic(Eigen::MatrixXd(dxc), h));
      for (Index i = 0; i < no; ++i) {
        const Index dof = o[static_cast<size_t>(i)];
        if (h == 0)
          dq(dof, 0) = dqo[i].real();
        else {
          dq(dof, 2 * h - 1) = dqo[i].real();
          dq(dof, 2 * h) = -dqo[i].imag();
        }
      }
    }
    out.dq.push_back(std::move(dq));
  }
  return out;
}

}  // namespace

ModelDerivative law_derivative(const friction::FrictionModel& model, friction::LawParameter parameter) {
  friction::PointParameters unit;
  switch (parameter) {
    case friction::law_kn:
      unit.kn = 1.0;
      break;
    case friction::law_kt:
      unit.kt = 1.0;
      break;
    case friction::law_mu:
      unit.mu = 1.0;
      break;
    case friction::law_n0:
      unit.n0 = 1.0;
      break;
  }
  ModelDerivative d;
  d.laws.assign(model.contacts.size(), unit);
  return d;
}

ModelDerivative damping_scale_derivative(const friction::FrictionModel& model) {
  ModelDerivative d;
  d.damping = model.damping;
  return d;
}

ModelDerivative excitation_scale_derivative(const friction::FrictionModel& model) {
  ModelDerivative d;
  d.harmonic_load = model.harmonic_load;
  d.higher_loads = model.higher_loads;
  return d;
}

ModelDerivative frequency_derivative(const friction::FrictionModel& model, double omega) {
  if (!model.nodal_diameters.empty())
    throw std::invalid_argument("harmonic-balance sensitivities: the frequency derivative of a cyclic model");
  ModelDerivative d;
  d.damping = model.damping / omega;
  d.mass = 2.0 * model.mass / omega;
  return d;
}

Eigen::MatrixXd solution_sensitivity(const HarmonicBalance& system, const HbmSolution& solution,
                                     const std::vector<ModelDerivative>& derivatives) {
  return compute(system, solution, derivatives, false).dx;
}

std::vector<Eigen::MatrixXd> response_sensitivity(const HarmonicBalance& system, const HbmSolution& solution,
                                                  const std::vector<ModelDerivative>& derivatives) {
  return compute(system, solution, derivatives, true).dq;
}

Eigen::VectorXd amplitude_sensitivity(const HarmonicBalance& system, const HbmSolution& solution,
                                      const std::vector<ModelDerivative>& derivatives, Eigen::Index dof) {
  if (dof < 0 || dof >= system.model().mass.rows())
    throw std::invalid_argument(fmt::format("sensitivity: DOF {} out of range", dof));
  const std::vector<Eigen::MatrixXd> dq = response_sensitivity(system, solution, derivatives);
  const Eigen::MatrixXd q = system.recover(solution.x, solution.omega);
  const double a = q(dof, 1), b = q(dof, 2), amplitude = std::hypot(a, b);
  if (!(amplitude > 0.0))
    throw std::invalid_argument(fmt::format("sensitivity: DOF {} has zero first-harmonic amplitude", dof));
  Eigen::VectorXd out(static_cast<Index>(dq.size()));
  for (size_t j = 0; j < dq.size(); ++j)
    out[static_cast<Index>(j)] = (a * dq[j](dof, 1) + b * dq[j](dof, 2)) / amplitude;
  return out;
}

}  // namespace bb::hbm
