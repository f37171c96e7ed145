// The model of an hbm analysis assembled once: the linear model (Craig-Bampton, file or matrices),
// the damper and its static pre-solve, the contacts, loads and responses as model DOFs.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "forced/hbm_level.hpp"
#include "forced/linear_model.hpp"
#include "friction/whole_ring.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Index;

// Coordinates of a one-node set.
std::array<double, 2> point_position(const Model& model, const std::string& point) {
  const auto it = model.node_sets.find(point);
  if (it == model.node_sets.end() || it->second.size() != 1)
    throw InputError(
        fmt::format("'analysis.damper': '{}' is not a one-node set of the mesh; give the point's 'position'", point));
  const auto x = model.mesh.coords.row(it->second.front());
  return {x[0], x[1]};
}

// A damper point placed both ways, by a blade point that is a node of the mesh and by a position
// elsewhere: the position would win silently (a reduced model read from a file has no nodes, so
// there it is the only way).
void refuse_contradicted_positions(const Model& model, const DamperSpec& spec) {
  constexpr double kOnNode = 1e-6;  // [m], as model/build_model.cpp places points on nodes
  for (size_t i = 0; i < spec.points.size(); ++i) {
    const DamperPointSpec& p = spec.points[i];
    const auto set = model.node_sets.find(p.point);
    if (!p.position || p.point.empty() || set == model.node_sets.end() || set->second.size() != 1) continue;
    const auto x = model.mesh.coords.row(set->second.front());
    const double distance = std::hypot((*p.position)[0] - x[0], (*p.position)[1] - x[1]);
    if (distance > kOnNode)
      throw InputError(fmt::format(
          "{}: 'analysis.damper.points[{}].position': [{:g}, {:g}] lies {:.3g} m from the node of point '{}' "
          "([{:g}, {:g}]) that the damper moves with; give 'point' alone (the contact at its node) or 'position' "
          "alone (a rigid platform)",
          p.position_at.where(), i, (*p.position)[0], (*p.position)[1], distance, p.point, x[0], x[1]));
  }
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
    c.normal =
        p.left_face ? damper::left_face_normal(spec.left_face_deg) : damper::right_face_normal(spec.right_face_deg);
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

Eigen::RowVectorXd combination_row(const PreparedHbm& p, const ReducedModel& blades,
                                   const std::vector<std::pair<PointDof, double>>& terms, Index n,
                                   const std::string& where) {
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
  for (const auto& [dof, c] : terms) row[dof_index(p, blades, dof, where)] += c;
  return row;
}

// The second tangential row of a damper point of a two-direction law: the platform's z (the planar
// damper holds its own z), zero for a rigid platform.
Eigen::RowVectorXd out_of_plane_row(const ReducedModel& blades, const DamperPointSpec& point, Index n) {
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
  if (point.point.empty()) return row;
  const auto z = blades.index_of(point.point, 2);
  if (!z)
    throw InputError(
        fmt::format("'analysis.damper': point '{}' has no z DOF for the second direction of its law "
                    "(a planar model: write law = \"jenkins\")",
                    point.point));
  row[*z] = 1.0;
  return row;
}

// A law of two directions slips in the plane of a_t and a_t2: a zero or parallel second row leaves
// it a 1D law with a wrong limit.
void require_independent_directions(const Eigen::RowVectorXd& first, const Eigen::RowVectorXd& second,
                                    const HbmContactSpec& c) {
  const double a = first.norm(), b = second.norm();
  const double across = a > 0.0 ? (second - (first.dot(second) / (a * a)) * first).norm() : b;
  if (!(across > 1e-9 * b) || b == 0.0)
    throw InputError(
        fmt::format("{}: 'tangential_2': contact '{}': the second tangential direction is {} the first: "
                    "a {} contact needs two independent directions",
                    c.at.where(), c.name, b == 0.0 ? "zero, not beside" : "parallel to", c.law->name()));
}

// The sector's model replaced by the whole ring: the first sector keeps the DOF and contact
// indices (responses, forces, contact slider ranges), the others are named "<name>@<sector>".
void expand_to_whole_ring(PreparedHbm& p, const HbmCyclicSpec& cyclic) {
  try {
    p.model = friction::whole_ring(p.model, cyclic.sectors);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("{}: [analysis.cyclic] whole: {}", cyclic.at.where(), e.what()));
  }
  const std::vector<std::string> dofs = p.dof_names, contacts = p.contact_names;
  for (int j = 1; j < cyclic.sectors; ++j) {
    for (const std::string& d : dofs) p.dof_names.push_back(fmt::format("{}@{}", d, j));
    for (const std::string& c : contacts) p.contact_names.push_back(fmt::format("{}@{}", c, j));
  }
}

}  // namespace

PreparedHbm prepare_hbm(const Model& model, const HbmSpec& spec, const ModelCacheSettings* cache) {
  if (spec.cyclic && !spec.model.masters.empty()) return prepare_cyclic_sector(model, spec, cache);
  const auto t0 = Clock::now();
  PreparedHbm p;
  FreeSystem system;
  if (spec.damper) refuse_contradicted_positions(model, *spec.damper);  // before the reduction
  if (!spec.model.masters.empty()) system = assemble_free_system(model);
  p.linear = build_reduced_model(model, system, spec.model, &p.timing, cache);
  const ReducedModel& blades = p.linear;
  p.blade_dofs = blades.size();
  for (const ReducedDof& d : blades.dofs) p.dof_names.push_back(d.name());
  {
    p.linear_frequencies_hz =
        symmetric_eigen(blades.stiffness, blades.mass, false).values.array().max(0.0).sqrt() / kTwoPi;
  }
  const Eigen::MatrixXd blade_damping =
      spec.damping_matrix ? *spec.damping_matrix : damping_matrix(spec.damping, blades);
  friction::FrictionModel& m = p.model;
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
  for (const auto& [dof, f] : spec.static_loads)
    m.static_load[dof_index(p, blades, dof, in_analysis + " static_loads")] += f;
  if (spec.damper) {
    const damper::ContactKinematics kin = damper::contact_kinematics(*p.damper, p.blade_dofs);
    friction::PointParameters law = spec.damper->point;
    law.n0 = 0.0;  // contacts just touch at q = 0; CF loads them through the static balance
    for (size_t c = 0; c < p.damper->contacts.size(); ++c) {
      friction::ContactElement element{law, kin.tangential.row(static_cast<Index>(c)),
                                       kin.normal.row(static_cast<Index>(c))};
      element.law = spec.damper->law;
      if (element.law->directions() == 2) element.tangential_2 = out_of_plane_row(blades, spec.damper->points[c], n);
      m.contacts.push_back(std::move(element));
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
    for (friction::ContactElement& c : m.contacts) c.tangential_offset = c.tangential.dot(p.damper_static->q);
  }
  for (const HbmContactSpec& c : spec.contacts) {
    const std::string where = fmt::format("{}: contact '{}'", c.at.where(), c.name);
    const Eigen::RowVectorXd tangential = combination_row(p, blades, c.tangential, n, where);
    const Eigen::RowVectorXd normal =
        c.normal.empty() ? Eigen::RowVectorXd::Zero(n) : combination_row(p, blades, c.normal, n, where);
    // Every solver sees the law as its Jenkins sliders on the same relative motion.
    const std::vector<friction::PointParameters> sliders = friction::parallel_sliders(c.point, c.distribution.get());
    p.contact_sliders.push_back({m.contacts.size(), m.contacts.size() + sliders.size()});
    friction::ContactElement element{{}, tangential, normal};
    element.law = c.law;
    if (!c.tangential_2.empty()) {
      element.tangential_2 = combination_row(p, blades, c.tangential_2, n, where);
      require_independent_directions(tangential, element.tangential_2, c);
    }
    if (spec.cyclic) {
      element.tangential_next = combination_row(p, blades, c.tangential_next, n, where);
      element.normal_next = combination_row(p, blades, c.normal_next, n, where);
      element.next_phase = kTwoPi * spec.cyclic->engine_order / spec.cyclic->sectors;
    }
    for (size_t i = 0; i < sliders.size(); ++i) {
      element.point = sliders[i];
      element.law = friction::slider_law(c.law, i);
      m.contacts.push_back(element);
      p.contact_names.push_back(sliders.size() == 1 ? c.name : fmt::format("{}.{}", c.name, i + 1));
    }
  }
  m.harmonic_load = Eigen::VectorXcd::Zero(n);
  for (const FrfForce& f : spec.forces)
    m.harmonic_load[dof_index(p, blades, f.dof, in_analysis + " forces")] +=
        f.amplitude / spec.forces.front().amplitude;
  if (spec.base_motion) {  // -M r a_b per m/s^2 of harmonic 1 (forced/base_motion_spec.hpp)
    const Eigen::VectorXd r =
        combination_row(p, blades, spec.base_motion->influence, n, in_analysis + " base_motion influence").transpose();
    const Eigen::VectorXd inertia = -(m.mass * r);
    for (const BaseHarmonic& h : spec.base_motion->harmonics) {
      const Eigen::VectorXcd load =
          inertia.cast<std::complex<double>>() * std::polar(h.ratio, h.phase_deg * kRadPerDeg);
      if (h.order == 1) {
        m.harmonic_load = load;
      } else {
        m.higher_loads.resize(static_cast<size_t>(h.order - 1));
        m.higher_loads[static_cast<size_t>(h.order - 2)] = load;
      }
    }
  }
  for (const PointDof& r : spec.responses) {
    p.responses.push_back(dof_index(p, blades, r, in_analysis + " responses"));
    p.response_names.push_back(r.name());
  }
  if (spec.ip_oop)
    p.ip_oop.emplace(dof_index(p, blades, spec.ip_oop->first, in_analysis + " ip_oop"),
                     dof_index(p, blades, spec.ip_oop->second, in_analysis + " ip_oop"));
  if (spec.cyclic && spec.cyclic->whole) expand_to_whole_ring(p, *spec.cyclic);
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

}  // namespace bb
