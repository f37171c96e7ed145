#include "contact/surface_contact.hpp"

#include <cmath>
#include <stdexcept>

#include "fe/face_shape.hpp"
#include "fe/gauss_abscissae.hpp"

namespace bb {
namespace {

template <int N, int G>
void add_points(const Mesh& mesh, int pair, const ContactFacetPair& f, const double (&x)[G], const double (&w)[G],
                std::vector<ContactPoint>& out) {
  Eigen::Matrix<double, N, 3> xyz;
  for (int a = 0; a < N; ++a) xyz.row(a) = mesh.coords.row(f.contact[static_cast<size_t>(a)]);
  const size_t first = out.size();
  double facet_area = 0.0;
  for (int j = 0; j < G; ++j)
    for (int i = 0; i < G; ++i) {
      Eigen::Matrix<double, N, 1> n;
      Eigen::Matrix<double, 2, N> dn;
      fe::face_shape<N>(x[i], x[j], n, dn);
      const Eigen::Matrix<double, 2, 3> tangents = dn * xyz;
      const Eigen::Vector3d area = tangents.row(0).transpose().cross(tangents.row(1).transpose());
      ContactPoint p;
      p.pair = pair;
      p.position = xyz.transpose() * n;
      p.normal = area.normalized();
      p.area = w[i] * w[j] * area.norm();
      p.facet = &f;
      p.shape = n;
      facet_area += p.area;
      out.push_back(std::move(p));
    }
  for (size_t k = first; k < out.size(); ++k) out[k].facet_size = std::sqrt(facet_area);
}

// Columns of the DOFs a point couples: target nodes (+N), then contact nodes (-N).
template <typename Fn>
void for_each_dof(const ContactPoint& p, Fn&& fn) {
  const auto n = static_cast<size_t>(p.shape.size());
  for (size_t a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) {
      fn(p.facet->target[a] * 3 + d, d, p.shape[static_cast<Eigen::Index>(a)]);
      fn(p.facet->contact[a] * 3 + d, d, -p.shape[static_cast<Eigen::Index>(a)]);
    }
}

}  // namespace

std::vector<ContactPoint> contact_points(const Mesh& mesh, const std::vector<ContactPair>& pairs) {
  if (mesh.dim != 3 && !pairs.empty()) throw std::invalid_argument("contact_points: contact needs a solid mesh");
  static constexpr double x2[2] = {-fe::kG2, fe::kG2}, w2[2] = {1.0, 1.0};
  static constexpr double x3[3] = {-fe::kG3, 0.0, fe::kG3}, w3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  std::vector<ContactPoint> points;
  for (size_t p = 0; p < pairs.size(); ++p)
    for (const ContactFacetPair& f : pairs[p].facets) {
      if (f.contact.size() == 4)
        add_points<4, 2>(mesh, static_cast<int>(p), f, x2, w2, points);
      else if (f.contact.size() == 8)
        add_points<8, 3>(mesh, static_cast<int>(p), f, x3, w3, points);
      else
        throw std::invalid_argument("contact_points: a contact facet must have 4 or 8 nodes");
    }
  return points;
}

Eigen::Vector3d relative_displacement(const ContactPoint& p, const Eigen::VectorXd& u) {
  Eigen::Vector3d du = Eigen::Vector3d::Zero();
  for_each_dof(p, [&](int dof, int d, double n) { du[d] += n * u[dof]; });
  return du;
}

Eigen::SparseMatrix<double> contact_stiffness(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                                              const ContactPenalty& penalty, int n_dofs) {
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<int, double>> g[3];  // per direction: (dof, +-N)
  for (size_t k = 0; k < points.size(); ++k) {
    if (!closed[k]) continue;
    const ContactPoint& p = points[k];
    const auto ki = static_cast<Eigen::Index>(k);
    const Eigen::Matrix3d nn = p.normal * p.normal.transpose();
    const Eigen::Matrix3d c =
        p.area * (penalty.normal[ki] * nn + penalty.tangential[ki] * (Eigen::Matrix3d::Identity() - nn));
    for (auto& v : g) v.clear();
    for_each_dof(p, [&](int dof, int d, double n) { g[d].emplace_back(dof, n); });
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        if (c(a, b) == 0.0) continue;
        for (const auto& [ra, na] : g[a])
          for (const auto& [rb, nb] : g[b]) triplets.emplace_back(ra, rb, c(a, b) * na * nb);
      }
  }
  Eigen::SparseMatrix<double> k(n_dofs, n_dofs);
  k.setFromTriplets(triplets.begin(), triplets.end());
  return k;
}

Eigen::VectorXd initial_gap_force(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                                  const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap, int n_dofs) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_dofs);
  for (size_t k = 0; k < points.size(); ++k) {
    const auto ki = static_cast<Eigen::Index>(k);
    if (!closed[k] || initial_gap[ki] == 0.0) continue;
    const ContactPoint& p = points[k];
    const double s = -p.area * penalty.normal[ki] * initial_gap[ki];
    for_each_dof(p, [&](int dof, int d, double n) { f[dof] += s * n * p.normal[d]; });
  }
  return f;
}

// Exponents beyond this overflow; a trial state that reaches it is rejected by the line search.
constexpr double kMaxExponent = 700.0;

double normal_pressure(double kn, double roughness, double gap) {
  if (roughness <= 0) return -kn * gap;
  return kn * roughness * std::expm1(std::min(-gap / roughness, kMaxExponent));
}

double normal_tangent(double kn, double roughness, double gap) {
  if (roughness <= 0) return kn;
  return kn * std::exp(std::min(-gap / roughness, kMaxExponent));
}

double normal_energy(double kn, double roughness, double gap) {
  if (roughness <= 0) return 0.5 * kn * gap * gap;
  const double x = -gap / roughness;
  if (x > kMaxExponent) return INFINITY;
  return kn * roughness * (roughness * std::expm1(x) + gap);
}

PointMotion point_motion(const ContactPoint& p, double initial_gap, const Eigen::VectorXd& u) {
  const Eigen::Vector3d du = relative_displacement(p, u);
  const double normal = p.normal.dot(du);
  return {initial_gap + normal, du - normal * p.normal};
}

double contact_energy(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                      const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap, const Eigen::VectorXd& u) {
  double e = 0.0;
  for (size_t k = 0; k < points.size(); ++k) {
    if (!closed[k]) continue;
    const auto ki = static_cast<Eigen::Index>(k);
    const PointMotion m = point_motion(points[k], initial_gap[ki], u);
    e += points[k].area * (normal_energy(penalty.normal[ki], penalty.roughness, m.gap) +
                           0.5 * penalty.tangential[ki] * m.slip.squaredNorm());
  }
  return e;
}

Eigen::VectorXd contact_force(const std::vector<ContactPoint>& points, const std::vector<char>& closed,
                              const ContactPenalty& penalty, const Eigen::VectorXd& initial_gap,
                              const Eigen::VectorXd& u) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
  for (size_t k = 0; k < points.size(); ++k) {
    if (!closed[k]) continue;
    const auto ki = static_cast<Eigen::Index>(k);
    const ContactPoint& p = points[k];
    const PointMotion m = point_motion(p, initial_gap[ki], u);
    // Traction on the target: +p n (pushed away along n) and -kt slip.
    const Eigen::Vector3d t = p.area * (normal_pressure(penalty.normal[ki], penalty.roughness, m.gap) * p.normal -
                                        penalty.tangential[ki] * m.slip);
    for_each_dof(p, [&](int dof, int d, double n) { f[dof] += n * t[d]; });
  }
  return f;
}

}  // namespace bb
