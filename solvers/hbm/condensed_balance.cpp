#include "hbm/condensed_balance.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <complex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "hbm/cyclic_shift.hpp"

namespace bb::hbm {

namespace {

using Index = Eigen::Index;
using Complex = std::complex<double>;

friction::FrictionModel validated(friction::FrictionModel model) {
  friction::validate_model(model, "harmonic balance", true, true);
  return model;
}

// The loads of harmonic h on all DOFs: f_static at h = 0, the excitation's harmonic h above.
Eigen::VectorXcd harmonic_load(const friction::FrictionModel& m, int h) {
  if (h == 0) return m.static_load.cast<Complex>();
  return friction::excitation_at(m, h);
}

// The Jacobian of a contact of two tangential directions, g = A^T [T_1; T_2; N] with the rows
// A = [a_t; a_t2; a_n] on its support: dg_(j,i)/dx_(l,p) = sum_ab A_ai dF_a,j/dy_b,l A_bp, the law's
// stacked derivatives dF/dy over y = [u_1; u_2; v].
void add_two_direction_jacobian(const friction::ContactElement& element, const friction::AftResult& r, Index nc,
                                Index m, Eigen::MatrixXd& jacobian) {
  Eigen::Matrix<double, 3, Eigen::Dynamic> rows(3, nc);
  rows << element.tangential, element.tangential_2, element.normal;
  std::vector<Index> support;
  for (Index i = 0; i < nc; ++i)
    if (rows.col(i).cwiseAbs().maxCoeff() > 0.0) support.push_back(i);
  Eigen::Matrix3d block;
  for (Index j = 0; j < m; ++j)
    for (Index l = 0; l < m; ++l) {
      block << r.dtangential_du(j, l), r.dtangential_du(j, m + l), r.dtangential_dv(j, l), r.dtangential_du(m + j, l),
          r.dtangential_du(m + j, m + l), r.dtangential_dv(m + j, l), 0.0, 0.0, r.dnormal_dv(j, l);
      if (block.isZero(0.0)) continue;
      for (const Index p : support) {
        const Eigen::Vector3d column = block * rows.col(p);
        for (const Index i : support) jacobian(j * nc + i, l * nc + p) += rows.col(i).dot(column);
      }
    }
}

}  // namespace

HarmonicBalance::HarmonicBalance(friction::FrictionModel model, HbmOptions options)
    : model_(validated(std::move(model))), options_(options), system_(model_) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("harmonic balance: " + what); };
  if (model_.contacts.empty()) fail("at least one contact element is required (use the linear FRF otherwise)");
  if (options_.harmonics < 1) fail("at least one harmonic");
  if (options_.max_iterations < 1 || options_.max_backtracks < 0 || !(options_.tolerance > 0.0))
    fail("max_iterations >= 1, max_backtracks >= 0 and tolerance > 0");
  if (contact_dofs().empty()) fail("every contact has zero a_t and a_n: no contact DOF");

  // The static condensation needs K_oo invertible: the model with its contact DOFs clamped must be
  // held. We do not add ground springs to make it so; the model must be fixed instead.
  if (!other_dofs().empty()) {
    const Eigen::MatrixXd koo = model_.stiffness(other_dofs(), other_dofs());
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(koo);
    if (lu.rank() < koo.rows() || lu.rcond() < kSingularRcond)
      fail(
          fmt::format("K restricted to the {} non-contact DOFs is singular (rank {}): the model with its contact DOFs "
                      "clamped has a rigid-body mode. Constrain it (boundary conditions) or list those DOFs in a "
                      "contact; no ground spring is added",
                      koo.rows(), lu.rank()));
  }

  aft_ = options_.aft;
  // Sampled: 16 samples per coefficient keep the error at the peaks near 1e-3. Events: the samples
  // only bracket the transitions, the integration is exact.
  if (aft_.samples == 0)
    aft_.samples = aft_.resolve_events ? std::max(32, 4 * (2 * options_.harmonics + 1))
                                       : std::max(64, 16 * (2 * options_.harmonics + 1));
  if (aft_.samples < 2 * options_.harmonics + 1) fail("aft.samples must be >= 2H + 1");

  for (const friction::ContactElement& e : system_.contacts_on_c())
    cyclic_gaps_.push_back(
        e.cyclic() ? CyclicGap{cyclic_gap_operator(e.tangential, e.tangential_next, e.next_phase, options_.harmonics),
                               cyclic_gap_operator(e.normal, e.normal_next, e.next_phase, options_.harmonics)}
                   : CyclicGap{});

  static_.emplace(system_.condense(friction::dynamic_stiffness(model_, 0, 0.0)));
  // Modal superposition needs one real basis for every harmonic: not a cyclic sector's per-diameter operators.
  if (model_.nodal_diameters.empty()) modal_ = ModalBasis::of(model_, contact_dofs(), other_dofs());

  double preload = 0.0;
  for (const friction::ContactElement& e : model_.contacts) preload += (1.0 + e.point.mu) * e.point.n0;
  force_scale_ = model_.static_load.norm() + model_.harmonic_load.norm() + preload;
  for (const Eigen::VectorXcd& f : model_.higher_loads) force_scale_ += f.norm();
}

Index HarmonicBalance::unknowns() const {
  return static_cast<Index>(contact_dofs().size()) * friction::harmonic_size(options_.harmonics);
}

template <class Use>
void HarmonicBalance::with_condensation(int h, double omega, const Use& use) const {
  if (h == 0) {
    use(*static_);
  } else if (modal_ && omega > 0.0) {
    use(modal_->at(h * omega));
  } else {
    use(system_.condense(friction::dynamic_stiffness(model_, h, h * omega)));
  }
}

std::optional<HarmonicBalance::Linear> HarmonicBalance::condense(double omega) const {
  const Index nc = static_cast<Index>(contact_dofs().size());
  Linear linear{Eigen::MatrixXd::Zero(unknowns(), unknowns()), Eigen::VectorXd::Zero(unknowns())};
  bool singular = false;
  for (int h = 0; h <= options_.harmonics && !singular; ++h) {
    with_condensation(h, omega, [&](const auto& d) {
      if (!(d.rcond() >= kSingularRcond)) {
        singular = true;
        return;
      }
      const Eigen::MatrixXcd& reduced = d.reduced();
      const Eigen::VectorXcd load = d.condense(harmonic_load(model_, h)).contact;
      if (h == 0) {
        linear.operator_.topLeftCorner(nc, nc) = reduced.real();
        linear.load.head(nc) = load.real();
        return;
      }
      // (A + iB)(a - ib) = (Aa + Bb) + i(Ba - Ab) = F: rows a: [A B], rows b: [-B A], load (Re F, -Im F).
      const Index a = (2 * h - 1) * nc, b = 2 * h * nc;
      linear.operator_.block(a, a, nc, nc) = reduced.real();
      linear.operator_.block(a, b, nc, nc) = reduced.imag();
      linear.operator_.block(b, a, nc, nc) = -reduced.imag();
      linear.operator_.block(b, b, nc, nc) = reduced.real();
      linear.load.segment(a, nc) = load.real();
      linear.load.segment(b, nc) = -load.imag();
    });
  }
  if (singular || !linear.operator_.allFinite() || !linear.load.allFinite()) return std::nullopt;
  return linear;
}

HarmonicBalance::ContactForces HarmonicBalance::contact_forces(const Eigen::VectorXd& x, bool with_jacobian) const {
  const Index nc = static_cast<Index>(contact_dofs().size());
  const Index m = friction::harmonic_size(options_.harmonics);
  // Column j of the nc x m matrix is harmonic coefficient j of every contact DOF.
  const Eigen::Map<const Eigen::MatrixXd> coefficients(x.data(), nc, m);
  ContactForces out{Eigen::VectorXd::Zero(unknowns()), Eigen::MatrixXd(), {}, true};
  Eigen::Map<Eigen::MatrixXd> force(out.force.data(), nc, m);
  for (size_t k = 0; k < system_.contacts_on_c().size(); ++k) {
    const friction::ContactElement& element = system_.contacts_on_c()[k];
    if (element.cyclic()) {
      // Dense gap operators: the shift couples the cosine and sine of every harmonic.
      const Eigen::MatrixXd &gt = cyclic_gaps_[k].tangential, &gn = cyclic_gaps_[k].normal;
      Eigen::VectorXd u = gt * x;
      u[0] -= element.tangential_offset;
      friction::AftResult r = element.law->harmonics(element.point, u, gn * x, aft_);
      out.closed = out.closed && r.closed;
      out.force += gt.transpose() * r.tangential + gn.transpose() * r.normal;
      out.contacts.push_back(std::move(r));
      continue;
    }
    const Eigen::RowVectorXd& at = element.tangential;
    const Eigen::RowVectorXd& an = element.normal;
    const bool two = element.tangential_2.size() != 0;
    Eigen::VectorXd u(two ? 2 * m : m);
    u.head(m) = (at * coefficients).transpose();
    if (two) u.tail(m) = (element.tangential_2 * coefficients).transpose();
    const Eigen::VectorXd v = (an * coefficients).transpose();
    u[0] -= element.tangential_offset;
    friction::AftResult r = element.law->harmonics(element.point, u, v, aft_);
    out.closed = out.closed && r.closed;
    // g = a_t^T T + a_t2^T T_2 + a_n^T N, per coefficient.
    force += at.transpose() * r.tangential.head(m).transpose() + an.transpose() * r.normal.transpose();
    if (two) force += element.tangential_2.transpose() * r.tangential.tail(m).transpose();
    out.contacts.push_back(std::move(r));
  }
  if (with_jacobian) out.jacobian = contact_jacobian(out.contacts);
  return out;
}

Eigen::MatrixXd HarmonicBalance::contact_jacobian(const std::vector<friction::AftResult>& contacts) const {
  const Index nc = static_cast<Index>(contact_dofs().size());
  const Index m = friction::harmonic_size(options_.harmonics);
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(unknowns(), unknowns());
  for (size_t k = 0; k < system_.contacts_on_c().size() && k < contacts.size(); ++k) {
    const friction::ContactElement& element = system_.contacts_on_c()[k];
    const friction::AftResult& r = contacts[k];
    if (element.cyclic()) {
      const Eigen::MatrixXd &gt = cyclic_gaps_[k].tangential, &gn = cyclic_gaps_[k].normal;
      jacobian.noalias() += gt.transpose() * (r.dtangential_du * gt + r.dtangential_dv * gn);
      jacobian.noalias() += gn.transpose() * (r.dnormal_dv * gn);
      continue;
    }
    if (element.tangential_2.size() != 0) {
      add_two_direction_jacobian(element, r, nc, m, jacobian);
      continue;
    }
    const Eigen::RowVectorXd& at = element.tangential;
    const Eigen::RowVectorXd& an = element.normal;
    // dg_(j,i)/dx_(l,p) = at_i (dT/du_jl at_p + dT/dv_jl an_p) + an_i dN/dv_jl an_p, only on the
    // few contact DOFs the element moves (its support): a damper contact moves 4-5 of Table XI's 9.
    std::vector<Index> support;
    for (Index i = 0; i < nc; ++i)
      if (at[i] != 0.0 || an[i] != 0.0) support.push_back(i);
    for (Index j = 0; j < m; ++j)
      for (Index l = 0; l < m; ++l) {
        const double tu = r.dtangential_du(j, l), tv = r.dtangential_dv(j, l), nv = r.dnormal_dv(j, l);
        if (tu == 0.0 && tv == 0.0 && nv == 0.0) continue;
        for (const Index p : support) {
          const double dp_t = tu * at[p] + tv * an[p], dp_n = nv * an[p];
          for (const Index i : support) jacobian(j * nc + i, l * nc + p) += at[i] * dp_t + an[i] * dp_n;
        }
      }
  }
  return jacobian;
}

HarmonicBalance::Residual HarmonicBalance::residual(const Linear& linear, const Eigen::VectorXd& x,
                                                    bool with_jacobian) const {
  Residual r;
  if (!x.allFinite()) return r;
  r.forces = contact_forces(x, with_jacobian);
  r.residual = linear.operator_ * x + r.forces.force - linear.load;
  r.ok = r.residual.allFinite() && r.forces.closed;
  if (r.ok) r.norm = r.residual.norm();
  return r;
}

Eigen::MatrixXd HarmonicBalance::recover(const Eigen::VectorXd& x, double omega) const {
  const Index n = model_.mass.rows(), nc = static_cast<Index>(contact_dofs().size());
  const Index m = friction::harmonic_size(options_.harmonics);
  if (x.size() != unknowns()) throw std::invalid_argument("harmonic balance: x has the wrong size");
  Eigen::MatrixXd q = Eigen::MatrixXd::Zero(n, m);
  const Eigen::Map<const Eigen::MatrixXd> xc(x.data(), nc, m);
  for (Index i = 0; i < nc; ++i) q.row(contact_dofs()[static_cast<size_t>(i)]) = xc.row(i);
  if (other_dofs().empty()) return q;
  for (int h = 0; h <= options_.harmonics; ++h) {
    with_condensation(h, omega, [&](const auto& d) {
      if (!(d.rcond() >= kSingularRcond))
        throw SolverError(fmt::format("harmonic balance: D_oo singular at harmonic {}, omega = {} rad/s", h, omega));
      const Eigen::VectorXcd qc =
          h == 0
              ? Eigen::VectorXcd(xc.col(0).cast<Complex>())
              : Eigen::VectorXcd(xc.col(2 * h - 1).cast<Complex>() - Complex(0.0, 1.0) * xc.col(2 * h).cast<Complex>());
      const Eigen::VectorXcd qo = d.recover(d.condense(harmonic_load(model_, h)), qc);
      for (size_t i = 0; i < other_dofs().size(); ++i) {
        const Index dof = other_dofs()[i];
        if (h == 0) {
          q(dof, 0) = qo[static_cast<Index>(i)].real();
        } else {
          q(dof, 2 * h - 1) = qo[static_cast<Index>(i)].real();
          q(dof, 2 * h) = -qo[static_cast<Index>(i)].imag();
        }
      }
    });
  }
  return q;
}

std::optional<Eigen::VectorXd> HarmonicBalance::linearized(double omega, bool stuck) const {
  const auto linear = condense(omega);
  if (!linear) return std::nullopt;
  const Index nc = static_cast<Index>(contact_dofs().size());
  const Index m = friction::harmonic_size(options_.harmonics);
  Eigen::MatrixXd springs = Eigen::MatrixXd::Zero(nc, nc);
  Eigen::VectorXd preload = Eigen::VectorXd::Zero(nc);
  Eigen::MatrixXd a = linear->operator_;
  Eigen::VectorXd b = linear->load;
  for (size_t k = 0; k < system_.contacts_on_c().size(); ++k) {
    const friction::ContactElement& element = system_.contacts_on_c()[k];
    const friction::PointParameters& law = element.point;
    if (element.cyclic()) {
      const Eigen::MatrixXd &gt = cyclic_gaps_[k].tangential, &gn = cyclic_gaps_[k].normal;
      a += law.kn * gn.transpose() * gn;
      b -= law.n0 * gn.row(0).transpose();
      if (stuck) {
        a += law.kt * gt.transpose() * gt;
        b += law.kt * element.tangential_offset * gt.row(0).transpose();
      }
      continue;
    }
    springs += law.kn * element.normal.transpose() * element.normal;
    preload += law.n0 * element.normal.transpose();
    if (stuck) {
      springs += law.kt * element.tangential.transpose() * element.tangential;
      preload -= law.kt * element.tangential_offset * element.tangential.transpose();
    }
  }
  for (Index j = 0; j < m; ++j) a.block(j * nc, j * nc, nc, nc) += springs;
  b.head(nc) -= preload;
  const Eigen::VectorXd x = a.fullPivLu().solve(b);
  if (!x.allFinite()) return std::nullopt;
  return x;
}

}  // namespace bb::hbm
