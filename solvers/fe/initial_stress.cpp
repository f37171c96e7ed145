// Integration-point stresses and geometric stiffness (see the header for the formulas). SI units.
#include "fe/initial_stress.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fe/gauss_abscissae.hpp"

namespace bb::fe {
namespace {

// One integration point of an isoparametric element: physical shape gradients (dim x nodes),
// shape values and the weight times det J.
template <int Dim, int Nodes>
struct PointGradients {
  Eigen::Matrix<double, Dim, Nodes> grad;
  Eigen::Matrix<double, Nodes, 1> shape;
  double weight = 0.0;  // w det J
};

[[noreturn]] void throw_bad_jacobian(const char* element, double det) {
  throw std::domain_error(std::string(element) + " Jacobian determinant " + std::to_string(det) +
                          " <= 0 at an integration point (element inverted, degenerate or misordered)");
}

template <int Dim, int Nodes>
PointGradients<Dim, Nodes> at_point(const Eigen::Matrix<double, Nodes, Dim>& coords,
                                    const Eigen::Matrix<double, Nodes, 1>& shape,
                                    const Eigen::Matrix<double, Dim, Nodes>& dnat, double weight, const char* element) {
  const Eigen::Matrix<double, Dim, Dim> jac = dnat * coords;  // J(i, j) = dx_j / dxi_i
  const double det = jac.determinant();
  if (!(det > 0.0)) throw_bad_jacobian(element, det);
  return {jac.inverse() * dnat, shape, weight * det};
}

// The 2x2 Gauss points of the q4, xi fastest.
std::array<PointGradients<2, 4>, 4> q4_points(const Q4Coords& xy) {
  std::array<PointGradients<2, 4>, 4> out;
  int p = 0;
  for (double eta : {-kG2, kG2}) {
    for (double xi : {-kG2, kG2}) {
      Eigen::Matrix<double, 4, 1> n;
      n << (1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta);
      Eigen::Matrix<double, 2, 4> dn;
      dn << -(1 - eta), (1 - eta), (1 + eta), -(1 + eta), -(1 - xi), -(1 + xi), (1 + xi), (1 - xi);
      out[static_cast<size_t>(p++)] = at_point<2, 4>(xy, 0.25 * n, 0.25 * dn, 1.0, "q4");
    }
  }
  return out;
}

PointGradients<2, 3> cst_point(const CstCoords& xy) {
  Eigen::Matrix<double, 3, 1> n = Eigen::Vector3d::Constant(1.0 / 3.0);
  Eigen::Matrix<double, 2, 3> dn;  // N1 = 1 - xi - eta, N2 = xi, N3 = eta
  dn << -1, 1, 0, -1, 0, 1;
  return at_point<2, 3>(xy, n, dn, 0.5, "cst");
}

std::array<PointGradients<3, 8>, 8> hex8_points(const Hex8Coords& xyz) {
  std::array<PointGradients<3, 8>, 8> out;
  int p = 0;
  for (double zeta : {-kG2, kG2})
    for (double eta : {-kG2, kG2})
      for (double xi : {-kG2, kG2}) {
        Eigen::Matrix<double, 8, 1> n;
        Eigen::Matrix<double, 3, 8> dn;
        hex8_shape_functions(Eigen::Vector3d(xi, eta, zeta), n, dn);
        out[static_cast<size_t>(p++)] = at_point<3, 8>(xyz, n, dn, 1.0, "hex8");
      }
  return out;
}

std::array<PointGradients<3, 20>, 27> hex20_points(const Hex20Coords& xyz) {
  std::array<PointGradients<3, 20>, 27> out;
  const double x[3] = {-kG3, 0.0, kG3}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  int p = 0;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        Eigen::Matrix<double, 20, 1> n;
        Eigen::Matrix<double, 3, 20> dn;
        hex20_shape_functions(Eigen::Vector3d(x[i], x[j], x[k]), n, dn);
        out[static_cast<size_t>(p++)] = at_point<3, 20>(xyz, n, dn, w[i] * w[j] * w[k], "hex20");
      }
  return out;
}

// Engineering strains from a displacement gradient: plane (exx, eyy, gxy), solid Voigt.
template <int Dim, int Nodes>
Eigen::Matrix<double, Dim == 2 ? 3 : 6, 1> strain(const Eigen::Matrix<double, Dim, Nodes>& grad,
                                                  const Eigen::Matrix<double, Dim * Nodes, 1>& u) {
  // h(i, j) = d u_i / d x_j
  const Eigen::Matrix<double, Dim, Dim> h =
      Eigen::Map<const Eigen::Matrix<double, Dim, Nodes>>(u.data()) * grad.transpose();
  Eigen::Matrix<double, Dim == 2 ? 3 : 6, 1> e;
  if constexpr (Dim == 2) {
    e << h(0, 0), h(1, 1), h(0, 1) + h(1, 0);
  } else {
    e << h(0, 0), h(1, 1), h(2, 2), h(0, 1) + h(1, 0), h(1, 2) + h(2, 1), h(2, 0) + h(0, 2);
  }
  return e;
}

Eigen::Matrix2d plane_tensor(const Eigen::Vector3d& s) {
  Eigen::Matrix2d t;
  t << s[0], s[2], s[2], s[1];
  return t;
}

Eigen::Matrix3d solid_tensor(const Eigen::Matrix<double, 6, 1>& s) {
  Eigen::Matrix3d t;
  t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return t;
}

// sum_p w_p det J_p * scale * grad_p^T sigma_p grad_p, expanded to the Dim displacement directions.
template <int Dim, int Nodes, size_t Points, typename Tensor>
Eigen::Matrix<double, Dim * Nodes, Dim * Nodes> geometric_from_points(
    const std::array<PointGradients<Dim, Nodes>, Points>& points, const Tensor& tensor_of_point, double scale) {
  Eigen::Matrix<double, Nodes, Nodes> scalar = Eigen::Matrix<double, Nodes, Nodes>::Zero();
  for (size_t p = 0; p < Points; ++p) {
    const auto& g = points[p].grad;
    scalar.noalias() += (points[p].weight * scale) * (g.transpose() * tensor_of_point(p) * g);
  }
  scalar = 0.5 * (scalar + scalar.transpose()).eval();
  Eigen::Matrix<double, Dim * Nodes, Dim* Nodes> k = Eigen::Matrix<double, Dim * Nodes, Dim * Nodes>::Zero();
  for (int b = 0; b < Nodes; ++b)
    for (int a = 0; a < Nodes; ++a)
      for (int d = 0; d < Dim; ++d) k(Dim * a + d, Dim * b + d) = scalar(a, b);
  return k;
}

// Solid strain-displacement rows of one scalar shape gradient g: Voigt (xx, yy, zz, xy, yz, zx).
Eigen::Matrix<double, 6, 3> solid_b_block(const Eigen::Vector3d& g) {
  Eigen::Matrix<double, 6, 3> b;
  b << g[0], 0, 0, 0, g[1], 0, 0, 0, g[2], g[1], g[0], 0, 0, g[2], g[1], g[2], 0, g[0];
  return b;
}

}  // namespace

Eigen::Matrix<double, 2, 4> q4_integration_points(const Q4Coords& xy) {
  const auto points = q4_points(xy);
  Eigen::Matrix<double, 2, 4> x;
  for (int p = 0; p < 4; ++p) x.col(p) = xy.transpose() * points[static_cast<size_t>(p)].shape;
  return x;
}

Eigen::Matrix<double, 2, 1> cst_integration_points(const CstCoords& xy) { return xy.colwise().mean().transpose(); }

Eigen::Matrix<double, 3, 8> hex8_integration_points(const Hex8Coords& xyz) {
  const auto points = hex8_points(xyz);
  Eigen::Matrix<double, 3, 8> x;
  for (int p = 0; p < 8; ++p) x.col(p) = xyz.transpose() * points[static_cast<size_t>(p)].shape;
  return x;
}

Eigen::Matrix<double, 3, 27> hex20_integration_points(const Hex20Coords& xyz) {
  const auto points = hex20_points(xyz);
  Eigen::Matrix<double, 3, 27> x;
  for (int p = 0; p < 27; ++p) x.col(p) = xyz.transpose() * points[static_cast<size_t>(p)].shape;
  return x;
}

Q4PointStresses q4_point_stresses(const Q4Coords& xy, const Eigen::Matrix<double, 8, 1>& u,
                                  const PlaneSection& section) {
  const Eigen::Matrix3d d = plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio);
  const auto points = q4_points(xy);
  Q4PointStresses s;
  for (int p = 0; p < 4; ++p) s.col(p) = d * strain<2, 4>(points[static_cast<size_t>(p)].grad, u);
  return s;
}

CstPointStresses cst_point_stresses(const CstCoords& xy, const Eigen::Matrix<double, 6, 1>& u,
                                    const PlaneSection& section) {
  return plane_stress_elasticity(section.youngs_modulus, section.poisson_ratio) * strain<2, 3>(cst_point(xy).grad, u);
}

Hex8PointStresses hex8_point_stresses(const Hex8Coords& xyz, const Eigen::Matrix<double, 24, 1>& u,
                                      const SolidMaterial& material) {
  const Matrix6 d = isotropic_elasticity(material.youngs_modulus, material.poisson_ratio);
  const auto points = hex8_points(xyz);
  Hex8PointStresses s;
  for (int p = 0; p < 8; ++p) s.col(p) = d * strain<3, 8>(points[static_cast<size_t>(p)].grad, u);
  return s;
}

// Bubbles P_k = 1 - xi_k^2 with Taylor's correction, exactly as hex8_incompatible_stiffness
// (fe/solid.cpp): grad P_k = (det J0 / det J) J0^-1 dP_k/dxi; amplitudes condensed from K alone.
Hex8PointStresses hex8_incompatible_point_stresses(const Hex8Coords& xyz, const Eigen::Matrix<double, 24, 1>& u,
                                                   const SolidMaterial& material) {
  const Matrix6 d = isotropic_elasticity(material.youngs_modulus, material.poisson_ratio);
  const auto points = hex8_points(xyz);
  Eigen::Matrix<double, 8, 1> n0;
  Eigen::Matrix<double, 3, 8> dn0;
  hex8_shape_functions(Eigen::Vector3d::Zero(), n0, dn0);
  const Eigen::Matrix3d jac0 = dn0 * xyz;
  const double det0 = jac0.determinant();
  if (!(det0 > 0.0)) throw_bad_jacobian("hex8 incompatible", det0);
  const Eigen::Matrix3d jac0_inv = jac0.inverse();

  std::array<Eigen::Matrix<double, 6, 9>, 8> bubble_b;
  Eigen::Matrix<double, 9, 9> kaa = Eigen::Matrix<double, 9, 9>::Zero();
  Eigen::Matrix<double, 9, 1> kau_u = Eigen::Matrix<double, 9, 1>::Zero();
  int p = 0;
  for (double zeta : {-kG2, kG2})
    for (double eta : {-kG2, kG2})
      for (double xi : {-kG2, kG2}) {
        const auto& pt = points[static_cast<size_t>(p)];
        const double det = pt.weight;  // unit Gauss weight: w det J = det J
        const Eigen::Vector3d nat(xi, eta, zeta);
        auto& bb = bubble_b[static_cast<size_t>(p)];
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3d g = (det0 / det) * jac0_inv.col(k) * (-2.0 * nat[k]);
          bb.block<6, 3>(0, 3 * k) = solid_b_block(g);
        }
        kaa.noalias() += det * bb.transpose() * d * bb;
        kau_u.noalias() += det * bb.transpose() * (d * strain<3, 8>(pt.grad, u));
        ++p;
      }
  const Eigen::LLT<Eigen::Matrix<double, 9, 9>> llt(kaa);
  if (llt.info() != Eigen::Success)
    throw std::domain_error("hex8 incompatible: bubble stiffness not positive definite (degenerate element)");
  const Eigen::Matrix<double, 9, 1> alpha = -llt.solve(kau_u);
  Hex8PointStresses s;
  for (int q = 0; q < 8; ++q) {
    const auto uq = static_cast<size_t>(q);
    s.col(q) = d * (strain<3, 8>(points[uq].grad, u) + bubble_b[uq] * alpha);
  }
  return s;
}

Hex20PointStresses hex20_point_stresses(const Hex20Coords& xyz, const Eigen::Matrix<double, 60, 1>& u,
                                        const SolidMaterial& material) {
  const Matrix6 d = isotropic_elasticity(material.youngs_modulus, material.poisson_ratio);
  const auto points = hex20_points(xyz);
  Hex20PointStresses s;
  for (int p = 0; p < 27; ++p) s.col(p) = d * strain<3, 20>(points[static_cast<size_t>(p)].grad, u);
  return s;
}

Matrix8 q4_geometric_stiffness(const Q4Coords& xy, const Q4PointStresses& stress, double thickness) {
  return geometric_from_points<2, 4, 4>(
      q4_points(xy), [&](size_t p) { return plane_tensor(stress.col(static_cast<Eigen::Index>(p))); }, thickness);
}

Matrix6 cst_geometric_stiffness(const CstCoords& xy, const CstPointStresses& stress, double thickness) {
  const std::array<PointGradients<2, 3>, 1> points{cst_point(xy)};
  return geometric_from_points<2, 3, 1>(
      points, [&](size_t) { return plane_tensor(stress.col(0)); }, thickness);
}

Matrix24 hex8_geometric_stiffness(const Hex8Coords& xyz, const Hex8PointStresses& stress) {
  return geometric_from_points<3, 8, 8>(
      hex8_points(xyz), [&](size_t p) { return solid_tensor(stress.col(static_cast<Eigen::Index>(p))); }, 1.0);
}

Matrix60 hex20_geometric_stiffness(const Hex20Coords& xyz, const Hex20PointStresses& stress) {
  return geometric_from_points<3, 20, 27>(
      hex20_points(xyz), [&](size_t p) { return solid_tensor(stress.col(static_cast<Eigen::Index>(p))); }, 1.0);
}

}  // namespace bb::fe
