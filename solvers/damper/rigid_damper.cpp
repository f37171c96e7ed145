#include "damper/rigid_damper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>

#include "common/errors.hpp"

namespace bb::damper {

namespace {

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

// z component of the planar cross product a x b.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

bool finite(const Eigen::Vector2d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

std::string names_of(const RigidDamper& damper, const std::vector<bool>& pick) {
  std::string s;
  for (size_t c = 0; c < damper.contacts.size(); ++c) {
    if (!pick[c]) continue;
    if (!s.empty()) s += ", ";
    s += damper.contacts[c].name;
  }
  return s.empty() ? "none" : s;
}

}  // namespace

Eigen::Vector2d left_face_normal(double beta_left_deg) {
  const double b = radians(beta_left_deg);
  return {std::sin(b), -std::cos(b)};
}

Eigen::Vector2d right_face_normal(double beta_right_deg) {
  const double b = radians(beta_right_deg);
  return {-std::sin(b), -std::cos(b)};
}

void validate(const RigidDamper& damper, int blade_dofs) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("rigid damper: " + what); };
  if (blade_dofs < 0) fail(fmt::format("the number of blade DOFs must be >= 0 (got {})", blade_dofs));
  if (!(std::isfinite(damper.mass) && damper.mass > 0.0))
    fail(fmt::format("mass m must be finite and > 0 (got {})", damper.mass));
  if (!(std::isfinite(damper.inertia) && damper.inertia > 0.0))
    fail(fmt::format("moment of inertia J must be finite and > 0 (got {})", damper.inertia));
  if (damper.contacts.empty()) fail("no contact point: the damper would not be held");
  std::set<std::string> names;
  for (const DamperContact& c : damper.contacts) {
    if (!names.insert(c.name).second) fail(fmt::format("contact name '{}' repeats", c.name));
    if (!finite(c.position)) fail(fmt::format("contact '{}': position is not finite", c.name));
    if (!finite(c.normal) || std::abs(c.normal.norm() - 1.0) > 1e-12)
      fail(fmt::format("contact '{}': normal ({}, {}) is not a unit vector", c.name, c.normal.x(), c.normal.y()));
    const bool rigid = c.blade_x == -1 && c.blade_y == -1;
    const auto in_range = [&](int i) { return i >= 0 && i < blade_dofs; };
    if (!rigid && !(in_range(c.blade_x) && in_range(c.blade_y) && c.blade_x != c.blade_y))
      fail(
          fmt::format("contact '{}': blade DOF indices ({}, {}) must be two distinct indices in [0, {}) or both -1 "
                      "(rigid platform)",
                      c.name, c.blade_x, c.blade_y, blade_dofs));
  }
}

RigidDamper asymmetric_damper(const AsymmetricDamperGeometry& g) {
  for (const double b : {g.beta_left_deg, g.beta_right_deg})
    if (!(b > 0.0 && b < 90.0))
      throw std::invalid_argument(
          fmt::format("asymmetric damper: face angles must lie in (0, 90) degrees (got {})", b));
  const Eigen::Vector2d n_l = left_face_normal(g.beta_left_deg);
  const Eigen::Vector2d along = g.l2 - g.l1;
  if (!(along.norm() > 0.0) || std::abs(along.dot(n_l)) > 1e-9 * along.norm() ||
      along.dot(Eigen::Vector2d(-n_l.y(), n_l.x())) < 0.0)
    throw std::invalid_argument(
        "asymmetric damper: L1 -> L2 must run up the flat face, along (cos beta_L, sin beta_L)");
  RigidDamper d{.mass = g.mass, .inertia = g.inertia, .contacts = {}};
  d.contacts.push_back({"L1", g.l1, n_l, g.l1_x, g.l1_y});
  d.contacts.push_back({"L2", g.l2, n_l, g.l2_x, g.l2_y});
  d.contacts.push_back({"R", g.r, right_face_normal(g.beta_right_deg), g.r_x, g.r_y});
  return d;
}

std::pair<int, int> platform_dofs(const ReducedModel& blades, const std::string& label) {
  const std::optional<int> x = blades.index_of(label, 0), y = blades.index_of(label, 1);
  if (!x || !y)
    throw InputError(
        fmt::format("damper: the blade reduced model has no DOF {}.{}: the platform contact point must "
                    "be a master node with x and y translations",
                    label, x ? "y" : "x"));
  return {*x, *y};
}

Eigen::Vector2d damper_point_displacement(const Eigen::Vector3d& damper_dofs, const Eigen::Vector2d& r) {
  return {damper_dofs.x() - damper_dofs.z() * r.y(), damper_dofs.y() + damper_dofs.z() * r.x()};
}

ContactKinematics contact_kinematics(const RigidDamper& damper, int blade_dofs) {
  validate(damper, blade_dofs);
  const Eigen::Index nc = static_cast<Eigen::Index>(damper.contacts.size());
  const Eigen::Index nq = blade_dofs + 3;
  ContactKinematics k{Eigen::MatrixXd::Zero(nc, nq), Eigen::MatrixXd::Zero(nc, nq)};
  for (Eigen::Index c = 0; c < nc; ++c) {
    const DamperContact& p = damper.contacts[static_cast<size_t>(c)];
    const Eigen::Vector2d t = p.tangent();
    for (int row = 0; row < 2; ++row) {
      const Eigen::Vector2d e = row == 0 ? t : p.normal;
      auto a = row == 0 ? k.tangential.row(c) : k.normal.row(c);
      if (p.blade_x >= 0) {  // + e . d_blade
        a(p.blade_x) += e.x();
        a(p.blade_y) += e.y();
      }
      // - e . (x - theta r_y, y + theta r_x)
      a(damper_x(blade_dofs)) -= e.x();
      a(damper_y(blade_dofs)) -= e.y();
      a(damper_theta(blade_dofs)) -= cross(p.position, e);
    }
  }
  return k;
}

Eigen::Matrix<double, 3, Eigen::Dynamic> contact_force_to_damper(const RigidDamper& damper) {
  // B does not involve the blades: check the body and its contacts, whatever the blade indices.
  int blade_dofs = 0;
  for (const DamperContact& c : damper.contacts) blade_dofs = std::max({blade_dofs, c.blade_x + 1, c.blade_y + 1});
  validate(damper, blade_dofs);
  const Eigen::Index nc = static_cast<Eigen::Index>(damper.contacts.size());
  Eigen::Matrix<double, 3, Eigen::Dynamic> b(3, 2 * nc);
  for (Eigen::Index c = 0; c < nc; ++c) {
    const DamperContact& p = damper.contacts[static_cast<size_t>(c)];
    const Eigen::Vector2d t = p.tangent();
    b.col(2 * c) << t.x(), t.y(), cross(p.position, t);
    b.col(2 * c + 1) << p.normal.x(), p.normal.y(), cross(p.position, p.normal);
  }
  return b;
}

CoupledSystem assemble_coupled_system(const Eigen::MatrixXd& blade_mass, const Eigen::MatrixXd& blade_stiffness,
                                      const RigidDamper& damper) {
  if (blade_mass.rows() != blade_mass.cols() || blade_stiffness.rows() != blade_stiffness.cols() ||
      blade_mass.rows() != blade_stiffness.rows())
    throw std::invalid_argument(
        fmt::format("coupled system: blade M ({} x {}) and K ({} x {}) must be square, same size", blade_mass.rows(),
                    blade_mass.cols(), blade_stiffness.rows(), blade_stiffness.cols()));
  const int n = static_cast<int>(blade_mass.rows());
  validate(damper, n);
  CoupledSystem s{Eigen::MatrixXd::Zero(n + 3, n + 3), Eigen::MatrixXd::Zero(n + 3, n + 3), n};
  s.mass.topLeftCorner(n, n) = blade_mass;
  s.stiffness.topLeftCorner(n, n) = blade_stiffness;
  s.mass(damper_x(n), damper_x(n)) = damper.mass;
  s.mass(damper_y(n), damper_y(n)) = damper.mass;
  s.mass(damper_theta(n), damper_theta(n)) = damper.inertia;
  return s;
}

Eigen::VectorXd centrifugal_load(int blade_dofs, double cf) {
  if (blade_dofs < 0 || !std::isfinite(cf))
    throw std::invalid_argument(
        fmt::format("centrifugal load: need blade_dofs >= 0 and a finite CF (got {}, {})", blade_dofs, cf));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(blade_dofs + 3);
  f(damper_y(blade_dofs)) = cf;
  return f;
}

namespace {

// One active set: the mixed system [K A^T; A -I/kn] [q; N] = [f; 0] over the closed contacts.
// Returns false when the (equilibrated) matrix is singular or the solution does not satisfy it.
bool solve_active_set(const Eigen::MatrixXd& k, const Eigen::MatrixXd& a, double kn, const Eigen::VectorXd& f,
                      Eigen::VectorXd& q, Eigen::VectorXd& n) {
  const Eigen::Index nq = k.rows(), ns = a.rows(), size = nq + ns;
  Eigen::MatrixXd m(size, size);
  m.topLeftCorner(nq, nq) = k;
  m.topRightCorner(nq, ns) = a.transpose();
  m.bottomLeftCorner(ns, nq) = a;
  m.bottomRightCorner(ns, ns) = -Eigen::MatrixXd::Identity(ns, ns) / kn;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  rhs.head(nq) = f;
  // Symmetric equilibration: rows and columns mix N, N/m, N m/rad, 1/kn; scale each to max 1.
  Eigen::VectorXd s(size);
  for (Eigen::Index i = 0; i < size; ++i) {
    const double mx = m.row(i).cwiseAbs().maxCoeff();
    if (!(mx > 0.0)) return false;  // a DOF nothing holds
    s(i) = 1.0 / std::sqrt(mx);
  }
  const Eigen::MatrixXd ms = s.asDiagonal() * m * s.asDiagonal();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(ms);
  lu.setThreshold(1e-13);
  if (!lu.isInvertible()) return false;
  Eigen::VectorXd z = s.asDiagonal() * lu.solve(s.asDiagonal() * rhs);
  z += s.asDiagonal() * lu.solve(s.asDiagonal() * (rhs - m * z));  // one step of iterative refinement
  if (!z.allFinite()) return false;
  // Backward check, row by row against the size of the terms that meet in that row.
  const Eigen::VectorXd r = (s.asDiagonal() * (rhs - m * z)).cwiseAbs();
  const Eigen::VectorXd scale = (s.asDiagonal() * (m.cwiseAbs() * z.cwiseAbs() + rhs.cwiseAbs())).cwiseAbs();
  for (Eigen::Index i = 0; i < size; ++i)
    if (r(i) > 1e-8 * scale(i) + 1e-300) return false;
  q = z.head(nq);
  n = z.tail(ns);
  return true;
}

}  // namespace

DamperStaticState solve_damper_static(const Eigen::MatrixXd& blade_stiffness, const RigidDamper& damper,
                                      const Eigen::VectorXd& load, const DamperStaticOptions& options) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument("damper static solve: " + what); };
  if (blade_stiffness.rows() != blade_stiffness.cols()) bad("the blade stiffness must be square");
  const int nb = static_cast<int>(blade_stiffness.rows());
  validate(damper, nb);
  const Eigen::Index nq = nb + 3;
  if (load.size() != nq) bad(fmt::format("the load has {} entries, the model {} (blade DOFs + 3)", load.size(), nq));
  if (!load.allFinite() || !blade_stiffness.allFinite()) bad("the load and the blade stiffness must be finite");
  if (!(std::isfinite(options.kn) && options.kn > 0.0))
    bad(fmt::format("kn must be finite and > 0 (got {})", options.kn));
  if (options.max_iterations < 1) bad("max_iterations must be >= 1");
  if (!(options.opening_tolerance >= 0.0)) bad("opening_tolerance must be >= 0");

  const size_t nc = damper.contacts.size();
  const ContactKinematics kin = contact_kinematics(damper, nb);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(nq, nq);
  k.topLeftCorner(nb, nb) = blade_stiffness;
  const double f_scale = load.norm();

  DamperStaticState st;
  st.q = Eigen::VectorXd::Zero(nq);
  st.normal_preload = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nc));
  st.normal_displacement = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nc));
  st.open.assign(nc, false);  // start with every contact closed

  const auto fail = [&](std::string why) {
    st.q.setZero();
    st.damper.setZero();
    st.normal_preload.setZero();
    st.normal_displacement.setZero();
    st.converged = false;
    st.failure = std::move(why);
    return st;
  };

  for (int it = 1; it <= options.max_iterations; ++it) {
    st.iterations = it;
    std::vector<Eigen::Index> closed;
    for (size_t c = 0; c < nc; ++c)
      if (!st.open[c]) closed.push_back(static_cast<Eigen::Index>(c));
    if (closed.empty())
      return fail(
          fmt::format("the load pulls the damper away from the platforms: every contact opens ({}); "
                      "no static state in contact (is CF = {} N pressing, along +y?)",
                      names_of(damper, st.open), load(damper_y(nb))));
    Eigen::MatrixXd a(static_cast<Eigen::Index>(closed.size()), nq);
    for (size_t i = 0; i < closed.size(); ++i) a.row(static_cast<Eigen::Index>(i)) = kin.normal.row(closed[i]);
    // The damper has no stiffness of its own: the closed contacts must fix its three DOFs.
    Eigen::FullPivHouseholderQR<Eigen::MatrixXd> qr(a.rightCols(3));
    qr.setThreshold(1e-10);
    if (qr.rank() < 3)
      return fail(
          fmt::format("with contacts {} open, the closed ones ({}) leave the damper a mechanism: they "
                      "cannot balance the load (CF too far off the contact lines, or faces at angles "
                      "that cannot hold it)",
                      names_of(damper, st.open), names_of(damper, [&] {
                        std::vector<bool> c(nc);
                        for (size_t j = 0; j < nc; ++j) c[j] = !st.open[j];
                        return c;
                      }())));
    Eigen::VectorXd q, n;
    if (!solve_active_set(k, a, options.kn, load, q, n))
      return fail(
          "the coupled static system is singular or ill-conditioned (is the blade stiffness positive "
          "definite, i.e. are the blades clamped?)");

    const Eigen::VectorXd v = kin.normal * q;
    std::vector<bool> next = st.open;
    Eigen::VectorXd normal = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nc));
    for (size_t i = 0; i < closed.size(); ++i) normal(closed[i]) = n(static_cast<Eigen::Index>(i));
    for (size_t c = 0; c < nc; ++c) {
      const Eigen::Index ci = static_cast<Eigen::Index>(c);
      if (!st.open[c] && normal(ci) < -options.opening_tolerance * f_scale) next[c] = true;
      if (st.open[c] && v(ci) > options.opening_tolerance * f_scale / options.kn) next[c] = false;
    }
    if (next == st.open) {
      st.q = q;
      st.damper = q.tail(3);
      st.normal_preload = normal.cwiseMax(0.0);
      st.normal_displacement = v;
      const Eigen::Matrix<double, 3, Eigen::Dynamic> b = contact_force_to_damper(damper);
      Eigen::VectorXd forces = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * nc));
      for (size_t c = 0; c < nc; ++c)
        forces(static_cast<Eigen::Index>(2 * c + 1)) = st.normal_preload(static_cast<Eigen::Index>(c));
      const Eigen::Vector3d r = load.tail(3) + b * forces;
      st.force_residual = r.head(2).norm();
      st.moment_residual = std::abs(r(2));
      st.converged = true;
      st.failure.clear();
      return st;
    }
    st.open = next;
  }
  return fail(fmt::format("the active set did not settle in {} iterations (last open: {})", options.max_iterations,
                          names_of(damper, st.open)));
}

}  // namespace bb::damper
