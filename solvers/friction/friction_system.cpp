#include "friction/friction_system.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace bb::friction {

using Index = Eigen::Index;
using Complex = std::complex<double>;

namespace {

template <class Fail>
void validate_nodal_diameters(FrictionModel& m, const Fail& fail, bool cyclic_allowed) {
  CyclicLinearModel& c = m.nodal_diameters;
  if (c.empty()) return;
  if (!cyclic_allowed)
    fail("the model's linear part is one sector of a cyclic structure: only the harmonic balance solves it");
  const Index n = m.mass.rows();
  if (c.sectors < 2 || static_cast<int>(c.diameters.size()) != c.sectors || c.engine_order < 0)
    fail("a cyclic linear model needs N >= 2 sectors, one entry per nodal diameter 0..N-1 and EO >= 0");
  for (int h = 1, seen = 0; seen < c.sectors; ++h, ++seen) {  // every k some harmonic reaches
    NodalDiameterOperators& d = c.diameters[static_cast<size_t>(c.diameter(h))];
    if (d.damping.size() == 0) d.damping = Eigen::MatrixXcd::Zero(n, n);
    for (const Eigen::MatrixXcd* a : {&d.mass, &d.damping, &d.stiffness})
      if (a->rows() != n || a->cols() != n || !a->allFinite())
        fail(fmt::format("nodal diameter {}: M, C and K must be finite and {} x {}", c.diameter(h), n, n));
  }
}

}  // namespace

Eigen::MatrixXcd dynamic_stiffness(const FrictionModel& m, int harmonic, double hw) {
  if (harmonic >= 1 && !m.nodal_diameters.empty()) {
    const NodalDiameterOperators& d = m.nodal_diameters.of_harmonic(harmonic);
    return d.stiffness + Complex(0.0, hw) * d.damping - (hw * hw) * d.mass;
  }
  const Index n = m.mass.rows();
  Eigen::MatrixXcd d(n, n);
  const bool damped = m.damping.size() > 0;
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j)
      d(i, j) = Complex(m.stiffness(i, j) - hw * hw * m.mass(i, j), damped ? hw * m.damping(i, j) : 0.0);
  return d;
}

Eigen::VectorXcd excitation_at(const FrictionModel& m, int harmonic) {
  if (harmonic == 1) return m.harmonic_load.size() > 0 ? m.harmonic_load : Eigen::VectorXcd::Zero(m.mass.rows());
  const auto k = static_cast<size_t>(harmonic - 2);
  if (harmonic < 2 || k >= m.higher_loads.size() || m.higher_loads[k].size() == 0)
    return Eigen::VectorXcd::Zero(m.mass.rows());
  return m.higher_loads[k];
}

void scale_excitation(FrictionModel& m, double factor) {
  m.harmonic_load *= factor;
  for (Eigen::VectorXcd& f : m.higher_loads) f *= factor;
}

void validate_model(FrictionModel& m, const std::string& who, bool cyclic_allowed, bool two_directions_allowed) {
  const Index n = m.mass.rows();
  const auto fail = [&who](const std::string& what) { throw std::invalid_argument(fmt::format("{}: {}", who, what)); };
  if (n == 0 || m.mass.cols() != n || m.stiffness.rows() != n || m.stiffness.cols() != n)
    fail("M and K must be square and of the same non-zero size");
  if (m.damping.size() == 0) m.damping = Eigen::MatrixXd::Zero(n, n);
  if (m.damping.rows() != n || m.damping.cols() != n) fail("C must be empty or of the size of M");
  if (!m.mass.allFinite() || !m.stiffness.allFinite() || !m.damping.allFinite()) fail("M, C and K must be finite");
  if (m.static_load.size() == 0) m.static_load = Eigen::VectorXd::Zero(n);
  if (m.harmonic_load.size() == 0) m.harmonic_load = Eigen::VectorXcd::Zero(n);
  if (m.static_load.size() != n || m.harmonic_load.size() != n)
    fail(fmt::format("loads must have {} entries (one per DOF)", n));
  if (!m.static_load.allFinite() || !m.harmonic_load.allFinite()) fail("loads must be finite");
  for (size_t k = 0; k < m.higher_loads.size(); ++k) {
    Eigen::VectorXcd& f = m.higher_loads[k];
    if (f.size() == 0) f = Eigen::VectorXcd::Zero(n);
    if (f.size() != n || !f.allFinite())
      fail(fmt::format("the load of harmonic {} must have {} finite entries", k + 2, n));
  }
  if (!m.higher_loads.empty() && !m.nodal_diameters.empty())
    fail("a cyclic sector takes a load of harmonic 1 only (an engine order's travelling wave)");
  validate_nodal_diameters(m, fail, cyclic_allowed);
  for (size_t k = 0; k < m.contacts.size(); ++k) {
    ContactElement& e = m.contacts[k];
    if (e.cyclic()) {
      if (!cyclic_allowed)
        fail(
            fmt::format("contact {} joins the next sector of a cyclic structure: only the harmonic balance solves "
                        "it (a travelling wave is periodic, not a time history of one sector)",
                        k));
      if (e.tangential_next.size() == 0) e.tangential_next = Eigen::RowVectorXd::Zero(n);
      if (e.normal_next.size() == 0) e.normal_next = Eigen::RowVectorXd::Zero(n);
      if (e.tangential_next.size() != n || e.normal_next.size() != n || !e.tangential_next.allFinite() ||
          !e.normal_next.allFinite() || !std::isfinite(e.next_phase))
        fail(fmt::format("contact {}: the next sector's rows must have {} finite entries, the phase be finite", k, n));
    }
    try {
      friction::validate(e.point);
    } catch (const std::invalid_argument& error) {
      fail(fmt::format("contact {}: {}", k, error.what()));
    }
    if (!e.law) fail(fmt::format("contact {}: no friction law", k));
    if (e.law->directions() == 2) {
      if (!two_directions_allowed)
        fail(
            fmt::format("contact {}: the {} law acts along two tangential directions; only the harmonic balance "
                        "solves it (the time integration keeps one slider coordinate per contact)",
                        k, e.law->name()));
      if (e.tangential_2.size() != n || !e.tangential_2.allFinite())
        fail(fmt::format("contact {}: the {} law needs a second tangential row a_t2 of {} finite entries", k,
                         e.law->name(), n));
      if (e.cyclic()) fail(fmt::format("contact {}: a {} contact cannot join the next sector", k, e.law->name()));
    } else if (e.tangential_2.size() != 0) {
      fail(fmt::format("contact {}: a second tangential row needs a law of two directions, not {}", k, e.law->name()));
    }
    if (e.tangential.size() != n || e.normal.size() != n)
      fail(fmt::format("contact {}: a_t and a_n must have {} entries (one per DOF)", k, n));
    if (!e.tangential.allFinite() || !e.normal.allFinite() || !std::isfinite(e.tangential_offset))
      fail(fmt::format("contact {}: a_t, a_n and the tangential offset must be finite", k));
  }
}

Eigen::MatrixXd stuck_stiffness(const FrictionModel& model) {
  Eigen::MatrixXd k = model.stiffness;
  for (const ContactElement& c : model.contacts) {
    k += c.point.kn * c.normal.transpose() * c.normal + c.point.kt * c.tangential.transpose() * c.tangential;
    if (c.tangential_2.size() != 0) k += c.point.kt * c.tangential_2.transpose() * c.tangential_2;
  }
  return k;
}

Eigen::MatrixXcd stuck_stiffness(const FrictionModel& model, int harmonic) {
  Eigen::MatrixXcd k = harmonic >= 1 && !model.nodal_diameters.empty()
                           ? model.nodal_diameters.of_harmonic(harmonic).stiffness
                           : Eigen::MatrixXcd(model.stiffness.cast<Complex>());
  for (const ContactElement& c : model.contacts) {
    const Complex shift = std::polar(1.0, harmonic * c.next_phase);
    auto row = [&](const Eigen::RowVectorXd& own, const Eigen::RowVectorXd& next) {
      Eigen::RowVectorXcd g = own.cast<Complex>();
      if (c.cyclic()) g += shift * next.cast<Complex>();
      return g;
    };
    const Eigen::RowVectorXcd gt = row(c.tangential, c.tangential_next), gn = row(c.normal, c.normal_next);
    k += c.point.kn * gn.adjoint() * gn + c.point.kt * gt.adjoint() * gt;
    if (c.tangential_2.size() != 0) k += c.point.kt * (c.tangential_2.transpose() * c.tangential_2).cast<Complex>();
  }
  return k;
}

template <class Scalar>
Condensation<Scalar>::Condensation(const Matrix& a, const std::vector<Index>& contact_dofs,
                                   const std::vector<Index>& other_dofs)
    : contact_dofs_(contact_dofs), other_dofs_(other_dofs), other_(static_cast<Index>(other_dofs.size())) {
  const Matrix a_cc = a(contact_dofs_, contact_dofs_);
  if (other_ == 0) {
    reduced_ = a_cc;
    return;
  }
  a_co_ = a(contact_dofs_, other_dofs_);
  lu_oo_.compute(a(other_dofs_, other_dofs_));
  rcond_ = lu_oo_.rcond();
  // No contact DOFs: no static modes (and no empty right-hand side, on which Eigen's triangular
  // solve would bind a reference to a null pointer).
  static_modes_ =
      contact_dofs_.empty() ? Matrix(other_, 0) : Matrix(lu_oo_.solve(Matrix(a(other_dofs_, contact_dofs_))));
  reduced_ = a_cc - a_co_ * static_modes_;
}

template <class Scalar>
typename Condensation<Scalar>::Load Condensation<Scalar>::condense(const Vector& f) const {
  Load load;
  if (other_ == 0) {
    load.contact = f(contact_dofs_);
    return load;
  }
  load.other = lu_oo_.solve(Vector(f(other_dofs_)));
  load.contact = Vector(f(contact_dofs_)) - a_co_ * load.other;
  return load;
}

template <class Scalar>
typename Condensation<Scalar>::Vector Condensation<Scalar>::recover(const Load& load, const Vector& x_c) const {
  if (other_ == 0) return Vector();
  return load.other - static_modes_ * x_c;
}

template class Condensation<double>;
template class Condensation<std::complex<double>>;

FrictionSystem::FrictionSystem(const FrictionModel& model) {
  const Index n = model.mass.rows();
  std::vector<bool> touched(static_cast<size_t>(n), false);
  for (const ContactElement& e : model.contacts)
    for (Index i = 0; i < n; ++i)
      if (e.tangential[i] != 0.0 || e.normal[i] != 0.0 || (e.tangential_2.size() != 0 && e.tangential_2[i] != 0.0) ||
          (e.cyclic() && (e.tangential_next[i] != 0.0 || e.normal_next[i] != 0.0)))
        touched[static_cast<size_t>(i)] = true;
  for (Index i = 0; i < n; ++i) (touched[static_cast<size_t>(i)] ? contact_dofs_ : other_dofs_).push_back(i);
  contacts_on_c_ = model.contacts;
  for (ContactElement& e : contacts_on_c_) {
    e.tangential = Eigen::RowVectorXd(e.tangential(contact_dofs_));
    e.normal = Eigen::RowVectorXd(e.normal(contact_dofs_));
    if (e.tangential_2.size() != 0) e.tangential_2 = Eigen::RowVectorXd(e.tangential_2(contact_dofs_));
    if (e.cyclic()) {
      e.tangential_next = Eigen::RowVectorXd(e.tangential_next(contact_dofs_));
      e.normal_next = Eigen::RowVectorXd(e.normal_next(contact_dofs_));
    }
  }
}

}  // namespace bb::friction
