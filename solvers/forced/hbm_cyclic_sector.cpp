// The model of an hbm analysis on one meshed sector of a tuned disk ([analysis.cyclic] with
// Craig-Bampton masters): per nodal diameter the sector reduced with its right face following its
// left one (cyclic/cyclic_reduction.hpp), a point damper in the gap to the next sector, the loads;
// or, with `whole`, the whole disk built from the sector, reduced as one structure with the same
// cut, a damper in every gap and the force of sector j shifted by j 2 pi EO / N (the verification).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <map>

#include "assembly/free_system.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "cyclic/cyclic_boundary.hpp"
#include "cyclic/cyclic_reduction.hpp"
#include "cyclic/whole_disk.hpp"
#include "forced/hbm_level.hpp"
#include "forced/linear_model.hpp"
#include "frf/receptance.hpp"
#include "linalg/dense_eigen.hpp"

namespace bb {
namespace {

using Eigen::Index;
using Complex = std::complex<double>;

const std::vector<int>& node_set(const Model& model, const std::string& name, const std::string& where) {
  const auto it = model.node_sets.find(name);
  if (it == model.node_sets.end() || it->second.empty())
    throw InputError(fmt::format("{}: '{}' is not a node set of the model (or has no node)", where, name));
  return it->second;
}

Eigen::Vector3d position(const Model& model, const std::string& point) {
  return model.mesh.coords.row(node_of_point(model, point)).transpose();
}

// The gap's radial and circumferential directions (in the x-y plane, z the axis), at the middle of
// this sector's `own` point and the next sector's `next` point.
struct GapFrame {
  Eigen::Vector3d radial, circumferential;
};
GapFrame gap_frame(const Model& model, const GapDamperSpec& d, const Eigen::Matrix3d& rotation) {
  const Eigen::Vector3d own = position(model, d.own), next = position(model, d.next);
  // The next sector's seat faces this sector's across the gap: closer, turned into the next
  // sector, than the same point of this sector is.
  if (!((rotation * next - own).norm() < (next - own).norm()))
    throw InputError(fmt::format(
        "{}: 'next' = '{}' is no platform of the neighbour across the gap from 'own' = '{}': turned into the next "
        "sector it lies {:.3g} m from it, farther than the {:.3g} m of this sector's own point (swapped seats?)",
        d.at.where(), d.next, d.own, (rotation * next - own).norm(), (next - own).norm()));
  const Eigen::Vector3d mid = 0.5 * (own + rotation * next);
  Eigen::Vector3d r(mid.x(), mid.y(), 0.0);
  if (!(r.norm() > 0.0)) throw InputError(fmt::format("{}: the gap lies on the axis", d.at.where()));
  r.normalize();
  return {r, Eigen::Vector3d(-r.y(), r.x(), 0.0)};
}

// The complex modal damping of a Hermitian (K, M): C = M Phi diag(2 zeta w_r) Phi^H M, or Rayleigh.
Eigen::MatrixXcd hermitian_damping(const FrfDamping& damping, const Eigen::MatrixXcd& k, const Eigen::MatrixXcd& m) {
  if (damping.kind == FrfDamping::Kind::rayleigh) {
    const RayleighCoefficients c = rayleigh_of(damping);
    return c.alpha * m + c.beta * k;
  }
  const DenseEigen<std::complex<double>> eig = symmetric_eigen(k, m);
  if (!eig.ok) throw SolverError("cyclic sector: the modes of a nodal diameter failed");
  const Eigen::VectorXd w = eig.values.array().max(0.0).sqrt();
  const Eigen::MatrixXcd mp = m * eig.vectors;
  return mp * (2.0 * damping.modal_ratios(w.size()).cwiseProduct(w)).asDiagonal() * mp.adjoint();
}

void refuse_unsupported(const HbmSpec& spec) {
  if (!spec.contacts.empty())
    throw InputError(fmt::format(
        "{}: a meshed cyclic sector takes its contacts from [analysis.gap_damper]; [[analysis.contact]] joins "
        "the DOFs of a lumped model",
        spec.contacts.front().at.where()));
  if (!spec.gap_damper)
    throw InputError(fmt::format("{}: a meshed cyclic sector needs an [analysis.gap_damper]", spec.at.where()));
  if (spec.damping_matrix)
    throw InputError(fmt::format("{}: a meshed sector's damping is modal or Rayleigh", spec.at.where()));
}

// The model index of a named master DOF of the first sector.
Index master_index(const std::map<std::string, Index>& masters, const PointDof& dof, const std::string& where) {
  const auto it = masters.find(dof.name());
  if (it == masters.end())
    throw InputError(fmt::format("{}: {} is not a DOF of the model's master points", where, dof.name()));
  return it->second;
}

// Loads, responses and IP/OOP of the first sector, and the damper of each gap, on a model whose
// sector j's point p DOF d is index(j, p, d), its damper's at damper(j) and damper(j) + 1. `sector`
// gives the gap's geometry.
template <class Index3, class DamperIndex>
void add_dampers_and_loads(PreparedHbm& p, const Model& sector, const HbmSpec& spec, int copies, const Index3& index,
                           const DamperIndex& damper, const std::map<std::string, Index>& first_sector) {
  const int N = spec.cyclic->sectors;
  const double phi = kTwoPi * spec.cyclic->engine_order / N;
  const Eigen::Matrix3d R = sector_rotation(N, 3);
  const GapDamperSpec& g = *spec.gap_damper;
  const GapFrame frame = gap_frame(sector, g, R);
  friction::FrictionModel& m = p.model;
  const Index n = m.mass.rows();
  m.static_load = Eigen::VectorXd::Zero(n);
  m.harmonic_load = Eigen::VectorXcd::Zero(n);
  friction::PointParameters law = g.point;
  law.n0 = 0.0;
  // Every solver sees the face's law as its Jenkins sliders on the same relative motion.
  const std::vector<friction::PointParameters> sliders = friction::parallel_sliders(law, g.distribution.get());
  const double cb = std::cos(g.face_angle_deg * kTwoPi / 360.0), sb = std::sin(g.face_angle_deg * kTwoPi / 360.0);
  const std::string where = spec.at.where() + ": 'analysis'";
  for (const FrfForce& f : spec.forces) master_index(first_sector, f.dof, where + " forces");
  for (const auto& [dof, f] : spec.static_loads) master_index(first_sector, dof, where + " static_loads");
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
  for (int j = 0; j < copies; ++j, turn = R * turn) {
    const Eigen::Vector3d t = turn * frame.circumferential, r = turn * frame.radial;
    const Index dt = damper(j), dr = damper(j) + 1;
    m.static_load[dr] += g.centrifugal_force;
    // The wedge's faces: the own face's normal leans back towards this sector by the face angle,
    // the next face's towards the next sector; t points from this sector to the next.
    const Eigen::Vector3d n_own = cb * r - sb * t, t_own = sb * r + cb * t;
    const Eigen::Vector3d n_next = cb * r + sb * t, t_next = -sb * r + cb * t;
    // u = t_face . (x_damper - x_platform), v = n_face . (x_damper - x_platform) (v > 0 presses),
    // x_damper = damper.t t + damper.r r.
    friction::ContactElement own{law, Eigen::RowVectorXd::Zero(n), Eigen::RowVectorXd::Zero(n)};
    friction::ContactElement next = own;
    const auto damper_terms = [&](friction::ContactElement& e, const Eigen::Vector3d& tf, const Eigen::Vector3d& nf) {
      e.tangential[dt] = tf.dot(t);
      e.tangential[dr] = tf.dot(r);
      e.normal[dt] = nf.dot(t);
      e.normal[dr] = nf.dot(r);
    };
    damper_terms(own, t_own, n_own);
    damper_terms(next, t_next, n_next);
    for (int d = 0; d < 3; ++d) {
      own.tangential[index(j, g.own, d)] -= t_own[d];
      own.normal[index(j, g.own, d)] -= n_own[d];
    }
    if (copies == 1) {  // the next sector's platform: this sector's own DOFs turned by R, shifted by phi
      next.tangential_next = next.normal_next = Eigen::RowVectorXd::Zero(n);
      const Eigen::Vector3d tn = R.transpose() * t_next, nn = R.transpose() * n_next;
      for (int d = 0; d < 3; ++d) {
        next.tangential_next[index(0, g.next, d)] -= tn[d];
        next.normal_next[index(0, g.next, d)] -= nn[d];
      }
      next.next_phase = phi;
    } else {
      for (int d = 0; d < 3; ++d) {
        next.tangential[index((j + 1) % copies, g.next, d)] -= t_next[d];
        next.normal[index((j + 1) % copies, g.next, d)] -= n_next[d];
      }
    }
    const std::string suffix = j == 0 ? "" : fmt::format("@{}", j);
    for (auto [element, name] : {std::pair{own, "own"}, std::pair{next, "next"}})
      for (size_t i = 0; i < sliders.size(); ++i) {
        element.point = sliders[i];
        m.contacts.push_back(element);
        p.contact_names.push_back(sliders.size() == 1 ? name + suffix : fmt::format("{}.{}{}", name, i + 1, suffix));
      }
    // Sector j's loads: the first sector's turned by R^j, its force shifted by j phi.
    const Complex shift = std::polar(1.0, j * phi);
    for (const FrfForce& f : spec.forces)
      for (int d = 0; d < 3; ++d)
        m.harmonic_load[index(j, f.dof.point, d)] +=
            shift * (turn(d, f.dof.direction) * f.amplitude / spec.forces.front().amplitude);
    for (const auto& [dof, f] : spec.static_loads)
      for (int d = 0; d < 3; ++d) m.static_load[index(j, dof.point, d)] += turn(d, dof.direction) * f;
  }
  for (const PointDof& r : spec.responses) {
    p.responses.push_back(master_index(first_sector, r, spec.at.where() + ": 'analysis' responses"));
    p.response_names.push_back(r.name());
  }
  if (spec.ip_oop)
    p.ip_oop.emplace(master_index(first_sector, spec.ip_oop->first, "ip_oop"),
                     master_index(first_sector, spec.ip_oop->second, "ip_oop"));
}

// One sector: per nodal diameter its reduction, the damper's two DOFs after the blade's.
PreparedHbm prepare_sector(const Model& model, const HbmSpec& spec) {
  const HbmCyclicSpec& c = *spec.cyclic;
  const int N = c.sectors;
  const FreeSystem system = assemble_free_system(model);
  const std::string where = c.at.where() + ": [analysis.cyclic]";
  const SectorFaces faces = pair_sector_faces(model.mesh, node_set(model, c.left, where),
                                              node_set(model, c.right, where), N, c.face_tolerance, where);
  const CyclicDofs cyclic = cyclic_dofs(model.mesh, system.dofs, faces, N);
  std::vector<int> masters;
  PreparedHbm p;
  std::map<std::string, Index> first_sector;
  for (const std::string& point : spec.model.masters)
    for (int d = 0; d < 3; ++d) {
      masters.push_back(free_index(model, system, {point, d}));
      first_sector[PointDof{point, d}.name()] = static_cast<Index>(p.dof_names.size());
      p.dof_names.push_back(PointDof{point, d}.name());
    }
  ModalOptions options;
  options.ordering = ordering_for_dimension(3);
  // Nodal diameters the harmonics reach (h EO mod N), reduced once per folded k <= N / 2.
  std::map<int, SectorReduction> folded;
  for (int h = 0; h < N; ++h) {
    const int k = static_cast<int>((static_cast<long long>(h) * c.engine_order) % N), f = std::min(k, N - k);
    if (!folded.count(f))
      folded.emplace(f, cyclic_craig_bampton(system.stiffness, system.mass, cyclic, kTwoPi * f / N, masters,
                                             spec.model.modes_below_hz, spec.model.modes, options));
  }
  const Index nb = static_cast<Index>(masters.size());
  Index nq = 0;
  for (const auto& [k, r] : folded) nq = std::max<Index>(nq, r.mass.rows() - nb);
  for (Index q = 1; q <= nq; ++q) p.dof_names.push_back(fmt::format("mode {}", q));
  p.blade_dofs = static_cast<int>(nb + nq);
  p.dof_names.insert(p.dof_names.end(), {"damper.t", "damper.r"});
  const Index n = nb + nq + 2;
  friction::CyclicLinearModel& linear = p.model.nodal_diameters;
  linear.sectors = N;
  linear.engine_order = c.engine_order;
  linear.diameters.resize(static_cast<size_t>(N));
  for (int k = 0; k < N; ++k) {
    const auto it = folded.find(std::min(k, N - k));
    if (it == folded.end()) continue;
    const SectorReduction& r = it->second;
    const Index size = r.mass.rows();
    friction::NodalDiameterOperators& d = linear.diameters[static_cast<size_t>(k)];
    d.stiffness = d.mass = d.damping = Eigen::MatrixXcd::Zero(n, n);
    d.stiffness.topLeftCorner(size, size) = r.stiffness;
    d.mass.topLeftCorner(size, size) = r.mass;
    d.damping.topLeftCorner(size, size) = hermitian_damping(spec.damping, r.stiffness, r.mass);
    for (Index pad = size; pad < nb + nq; ++pad) d.stiffness(pad, pad) = 1.0;  // a coordinate k lacks
    d.mass(n - 2, n - 2) = d.mass(n - 1, n - 1) = spec.gap_damper->mass;
    if (2 * k > N) {  // -k: the conjugate wave
      d.stiffness = d.stiffness.conjugate().eval();
      d.mass = d.mass.conjugate().eval();
      d.damping = d.damping.conjugate().eval();
    }
  }
  const friction::NodalDiameterOperators& zero = linear.diameters.front();
  p.model.mass = zero.mass.real();
  p.model.stiffness = zero.stiffness.real();
  p.model.damping = zero.damping.real();
  const int k1 = linear.diameter(1);
  const SectorReduction& first = folded.at(std::min(k1, N - k1));
  p.linear_frequencies_hz = symmetric_eigen(first.stiffness, first.mass, false).values.array().max(0.0).sqrt() / kTwoPi;
  add_dampers_and_loads(
      p, model, spec, 1,
      [&](int, const std::string& point, int d) {
        return first_sector.at(PointDof{point, d}.name());
      },
      [&](int) { return n - 2; }, first_sector);
  return p;
}

// The whole disk: N turned copies of the sector, reduced together with the same cut.
PreparedHbm prepare_whole(const Model& model, const HbmSpec& spec, const ModelCacheSettings* cache) {
  const HbmCyclicSpec& c = *spec.cyclic;
  const int N = c.sectors;
  const Model whole = whole_from_sector(model, N, c.face_tolerance);
  RomSpec rom = spec.model;
  rom.masters.clear();
  for (int j = 0; j < N; ++j)
    for (const std::string& point : spec.model.masters) rom.masters.push_back(fmt::format("{}@{}", point, j));
  const FreeSystem system = assemble_free_system(whole);
  PreparedHbm p;
  p.linear = build_reduced_model(whole, system, rom, &p.timing, cache);
  const ReducedModel& blades = p.linear;
  const Index nb = static_cast<Index>(spec.model.masters.size()) * 3, nw = blades.size();
  std::map<std::string, Index> first_sector;
  for (Index i = 0; i < nw; ++i) {
    const std::string name =
        i < nb ? PointDof{spec.model.masters[static_cast<size_t>(i / 3)], static_cast<int>(i % 3)}.name()
               : blades.dofs[static_cast<size_t>(i)].name();
    if (i < nb) first_sector[name] = i;
    p.dof_names.push_back(name);
  }
  for (int j = 0; j < N; ++j)
    for (const char* d : {"damper.t", "damper.r"}) p.dof_names.push_back(j == 0 ? d : fmt::format("{}@{}", d, j));
  p.blade_dofs = static_cast<int>(nw);
  const Index n = nw + 2 * N;
  friction::FrictionModel& m = p.model;
  m.mass = m.stiffness = m.damping = Eigen::MatrixXd::Zero(n, n);
  m.mass.topLeftCorner(nw, nw) = blades.mass;
  m.stiffness.topLeftCorner(nw, nw) = blades.stiffness;
  m.damping.topLeftCorner(nw, nw) = damping_matrix(spec.damping, blades);
  for (Index i = nw; i < n; ++i) m.mass(i, i) = spec.gap_damper->mass;
  p.linear_frequencies_hz =
      symmetric_eigen(blades.stiffness, blades.mass, false).values.array().max(0.0).sqrt() / kTwoPi;
  const Index points = static_cast<Index>(spec.model.masters.size());
  std::map<std::string, Index> point_number;
  for (Index i = 0; i < points; ++i) point_number[spec.model.masters[static_cast<size_t>(i)]] = i;
  add_dampers_and_loads(
      p, model, spec, N,
      [&](int j, const std::string& point, int d) { return (j * points + point_number.at(point)) * 3 + d; },
      [&](int j) { return nw + 2 * j; }, first_sector);
  return p;
}

}  // namespace

PreparedHbm prepare_cyclic_sector(const Model& model, const HbmSpec& spec, const ModelCacheSettings* cache) {
  const auto t0 = std::chrono::steady_clock::now();
  refuse_unsupported(spec);
  PreparedHbm p = spec.cyclic->whole ? prepare_whole(model, spec, cache) : prepare_sector(model, spec);
  try {
    const hbm::HarmonicBalance check(p.model, {});  // sizes, contact laws and a nonsingular non-contact part
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("'analysis': {}", e.what()));
  }
  p.setup_seconds = seconds_since(t0);
  return p;
}

}  // namespace bb
