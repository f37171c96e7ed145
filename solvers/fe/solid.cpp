// 3D solid elements (hex8, hex8 with incompatible modes, hex20). SI units.
//
// How the stiffness is accumulated. For an isotropic material the 3x3 block coupling nodes a and b
// is, with g_a = grad N_a,
//   K_ab = integral of  lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I  dV,
// which is B_a^T D B_b written out (D = isotropic_elasticity). All three terms are linear in the
// single 3x3 integral H_ab = integral of g_a g_b^T dV. Stacking the gradients of all nodes at a
// Gauss point into one column (index 3a + i) scaled by sqrt(w det J) gives a matrix G with one
// column per point, and H = G G^T: one symmetric rank-k product (60 x 27 for hex20) instead of a
// 6 x 60 B^T D B per point: ~6x fewer flops than B^T (D B), and it runs in Eigen's blocked GEMM.
// The consistent mass is the same construction with N_a in place of g_a.
#include "fe/solid.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "fe/gauss_abscissae.hpp"

namespace bb::fe {
namespace {

// Natural coordinates of the nodes, Ansys/CalculiX order (mesh/mesh.hpp).
constexpr double kHex20Nodes[20][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},  // corners 1-4, zeta = -1
    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1},   // corners 5-8, zeta = +1
    {0, -1, -1},  {1, 0, -1},  {0, 1, -1}, {-1, 0, -1},  // 9-12: edges 1-2, 2-3, 3-4, 4-1
    {0, -1, 1},   {1, 0, 1},   {0, 1, 1},  {-1, 0, 1},   // 13-16: edges 5-6, 6-7, 7-8, 8-5
    {-1, -1, 0},  {1, -1, 0},  {1, 1, 0},  {-1, 1, 0},   // 17-20: edges 1-5, 2-6, 3-7, 4-8
};

// Shape functions and their natural derivatives (rows d/dxi, d/deta, d/dzeta) at every Gauss
// point, computed once: the element routines then only form J, invert it and multiply.
template <int Nodes, int Points>
struct GaussTable {
  std::array<Eigen::Matrix<double, 3, Nodes>, Points> dnat;
  std::array<Eigen::Matrix<double, Nodes, 3>, Points> dnat_t;  // transposed, for contiguous dots
  std::array<Eigen::Matrix<double, Nodes, 1>, Points> shape;
  std::array<Eigen::Vector3d, Points> point;  // (xi, eta, zeta)
  std::array<double, Points> weight;
};

using Hex8Table = GaussTable<8, 8>;
using Hex20Table = GaussTable<20, 27>;

void hex8_shape(double xi, double eta, double zeta, Eigen::Matrix<double, 8, 1>& n, Eigen::Matrix<double, 3, 8>& dn) {
  for (int a = 0; a < 8; ++a) {
    const double xa = kHex20Nodes[a][0], ya = kHex20Nodes[a][1], za = kHex20Nodes[a][2];
    const double fx = 1 + xa * xi, fy = 1 + ya * eta, fz = 1 + za * zeta;
    n[a] = 0.125 * fx * fy * fz;
    dn(0, a) = 0.125 * xa * fy * fz;
    dn(1, a) = 0.125 * fx * ya * fz;
    dn(2, a) = 0.125 * fx * fy * za;
  }
}

// Serendipity hexahedron (e.g. Zienkiewicz & Taylor vol. 1, sec. 6.5): corners
// (1/8)(1+xi xi_a)(1+eta eta_a)(1+zeta zeta_a)(xi xi_a + eta eta_a + zeta zeta_a - 2), mid-edge
// nodes (1/4)(1 - s^2)(1 + t t_a)(1 + r r_a) with s the coordinate that is zero at the node.
void hex20_shape(double xi, double eta, double zeta, Eigen::Matrix<double, 20, 1>& n,
                 Eigen::Matrix<double, 3, 20>& dn) {
  const double q[3] = {xi, eta, zeta};
  for (int a = 0; a < 20; ++a) {
    const double* c = kHex20Nodes[a];
    if (a < 8) {
      const double f[3] = {1 + c[0] * xi, 1 + c[1] * eta, 1 + c[2] * zeta};
      const double s = c[0] * xi + c[1] * eta + c[2] * zeta - 2;
      n[a] = 0.125 * f[0] * f[1] * f[2] * s;
      for (int d = 0; d < 3; ++d) {
        const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
        dn(d, a) = 0.125 * c[d] * f[d1] * f[d2] * (s + f[d]);
      }
    } else {
      const int m = c[0] == 0 ? 0 : (c[1] == 0 ? 1 : 2);  // the direction along the edge
      const int m1 = (m + 1) % 3, m2 = (m + 2) % 3;
      const double bubble = 1 - q[m] * q[m];
      const double f1 = 1 + c[m1] * q[m1], f2 = 1 + c[m2] * q[m2];
      n[a] = 0.25 * bubble * f1 * f2;
      dn(m, a) = -0.5 * q[m] * f1 * f2;
      dn(m1, a) = 0.25 * bubble * c[m1] * f2;
      dn(m2, a) = 0.25 * bubble * f1 * c[m2];
    }
  }
}

const Hex8Table& hex8_table() {
  static const Hex8Table table = [] {
    Hex8Table t{};
    int p = 0;
    for (double zeta : {-kG2, kG2})
      for (double eta : {-kG2, kG2})
        for (double xi : {-kG2, kG2}) {
          hex8_shape(xi, eta, zeta, t.shape[p], t.dnat[p]);
          t.dnat_t[p] = t.dnat[p].transpose();
          t.point[p] = Eigen::Vector3d(xi, eta, zeta);
          t.weight[p] = 1.0;
          ++p;
        }
    return t;
  }();
  return table;
}

const Hex20Table& hex20_table() {
  static const Hex20Table table = [] {
    Hex20Table t{};
    const double x[3] = {-kG3, 0.0, kG3}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    int p = 0;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          hex20_shape(x[i], x[j], x[k], t.shape[p], t.dnat[p]);
          t.dnat_t[p] = t.dnat[p].transpose();
          t.point[p] = Eigen::Vector3d(x[i], x[j], x[k]);
          t.weight[p] = w[i] * w[j] * w[k];
          ++p;
        }
    return t;
  }();
  return table;
}

[[noreturn]] void throw_bad_jacobian(const char* element, double det, const Eigen::Vector3d& at) {
  std::ostringstream msg;
  msg.precision(6);
  msg << element << " Jacobian determinant " << det << " <= 0 at natural point (" << at[0] << ", " << at[1] << ", "
      << at[2] << "): element inverted, degenerate or nodes not in Ansys/CalculiX order";
  throw std::domain_error(msg.str());
}

// J(i, j) = dx_j / dxi_i, so that grad N = J^-1 dN/dxi. Written as nine contiguous dot products
// (and lazy products below): Eigen's default would send these 3 x 20 x 3 and 3 x 3 x 20 products
// through its blocked GEMM, whose packing costs more than the arithmetic at these sizes.
template <int Nodes>
Eigen::Matrix3d jacobian_checked(const Eigen::Matrix<double, Nodes, 3>& dnat_t,
                                 const Eigen::Matrix<double, Nodes, 3>& xyz, const char* element,
                                 const Eigen::Vector3d& at, double& det) {
  Eigen::Matrix3d jac;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) jac(i, j) = dnat_t.col(i).dot(xyz.col(j));
  det = jac.determinant();
  if (!(det > 0.0)) throw_bad_jacobian(element, det, at);
  return jac;
}

// K from H = G G^T (see the file comment). Only the lower triangle of H is read; K is built as
// lower blocks and mirrored, so it is symmetric by construction.
template <int Dofs>
Eigen::Matrix<double, Dofs, Dofs> isotropic_from_gradient_products(const Eigen::Matrix<double, Dofs, Dofs>& h,
                                                                   double lambda, double mu) {
  constexpr int kNodes = Dofs / 3;
  Eigen::Matrix<double, Dofs, Dofs> k;
  for (int b = 0; b < kNodes; ++b) {
    for (int a = b; a < kNodes; ++a) {
      Eigen::Matrix3d hab;
      if (a == b) {
        hab = h.template block<3, 3>(3 * a, 3 * a).template selfadjointView<Eigen::Lower>();
      } else {
        hab = h.template block<3, 3>(3 * a, 3 * b);
      }
      Eigen::Matrix3d kab = lambda * hab + mu * hab.transpose();
      kab.diagonal().array() += mu * hab.trace();
      k.template block<3, 3>(3 * a, 3 * b) = kab;
      if (a != b) k.template block<3, 3>(3 * b, 3 * a) = kab.transpose();
    }
  }
  return k;
}

struct Lame {
  double lambda;
  double mu;
};

Lame lame(double e, double nu) { return {e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))}; }

// Gauss-integrated stiffness of an isoparametric hexahedron with the table's rule.
template <int Nodes, int Points>
Eigen::Matrix<double, 3 * Nodes, 3 * Nodes> hex_stiffness(const GaussTable<Nodes, Points>& table,
                                                          const Eigen::Matrix<double, Nodes, 3>& xyz,
                                                          const SolidMaterial& material, const char* element) {
  constexpr int kDofs = 3 * Nodes;
  Eigen::Matrix<double, kDofs, Points> g;  // column p: sqrt(w det J) grad N, index 3a + i
  for (int p = 0; p < Points; ++p) {
    double det = 0.0;
    const Eigen::Matrix3d jac = jacobian_checked<Nodes>(table.dnat_t[p], xyz, element, table.point[p], det);
    Eigen::Map<Eigen::Matrix<double, 3, Nodes>> grad(g.col(p).data());
    grad.noalias() = jac.inverse().lazyProduct(table.dnat[p]);
    grad *= std::sqrt(table.weight[p] * det);
  }
  Eigen::Matrix<double, kDofs, kDofs> h = Eigen::Matrix<double, kDofs, kDofs>::Zero();
  h.template selfadjointView<Eigen::Lower>().rankUpdate(g);
  const Lame l = lame(material.youngs_modulus, material.poisson_ratio);
  return isotropic_from_gradient_products<kDofs>(h, l.lambda, l.mu);
}

// rho * integral of N N^T, expanded to the three directions (no coupling between directions).
template <int Nodes, int Points>
Eigen::Matrix<double, 3 * Nodes, 3 * Nodes> hex_consistent_mass(const GaussTable<Nodes, Points>& table,
                                                                const Eigen::Matrix<double, Nodes, 3>& xyz,
                                                                const SolidMaterial& material, const char* element) {
  Eigen::Matrix<double, Nodes, Points> n;  // column p: sqrt(rho w det J) N
  for (int p = 0; p < Points; ++p) {
    double det = 0.0;
    jacobian_checked<Nodes>(table.dnat_t[p], xyz, element, table.point[p], det);
    n.col(p) = table.shape[p] * std::sqrt(material.density * table.weight[p] * det);
  }
  Eigen::Matrix<double, Nodes, Nodes> scalar = Eigen::Matrix<double, Nodes, Nodes>::Zero();
  scalar.template selfadjointView<Eigen::Lower>().rankUpdate(n);
  scalar = scalar.template selfadjointView<Eigen::Lower>();
  Eigen::Matrix<double, 3 * Nodes, 3 * Nodes> m;
  m.setZero();
  for (int b = 0; b < Nodes; ++b)
    for (int a = 0; a < Nodes; ++a)
      for (int d = 0; d < 3; ++d) m(3 * a + d, 3 * b + d) = scalar(a, b);
  return m;
}

template <int Nodes, int Points>
double hex_volume(const GaussTable<Nodes, Points>& table, const Eigen::Matrix<double, Nodes, 3>& xyz,
                  const char* element) {
  double volume = 0.0;
  for (int p = 0; p < Points; ++p) {
    double det = 0.0;
    jacobian_checked<Nodes>(table.dnat_t[p], xyz, element, table.point[p], det);
    volume += table.weight[p] * det;
  }
  return volume;
}

}  // namespace

Matrix6 isotropic_elasticity(double youngs_modulus, double poisson_ratio) {
  const Lame l = lame(youngs_modulus, poisson_ratio);
  Matrix6 d = Matrix6::Zero();
  d.topLeftCorner<3, 3>().setConstant(l.lambda);
  d.topLeftCorner<3, 3>().diagonal().array() += 2 * l.mu;
  d.bottomRightCorner<3, 3>().diagonal().setConstant(l.mu);
  return d;
}

Matrix24 hex8_stiffness(const Hex8Coords& xyz, const SolidMaterial& material) {
  return hex_stiffness(hex8_table(), xyz, material, "hex8");
}

// Wilson, Taylor, Doherty & Ghaboussi (1973) incompatible modes P = (1 - xi^2, 1 - eta^2,
// 1 - zeta^2), one amplitude per mode and direction (9 internal DOFs), with Taylor, Beresford &
// Wilson (1976): grad P uses the centre Jacobian J0 and is scaled by det J0 / det J. The weighted
// bubble gradient w det J grad P = w det J0 J0^-1 dP/dxi is then odd in xi, eta or zeta, so its
// Gauss sum vanishes: a constant stress does no work on the bubbles, and the patch test passes on
// any shape. The bubbles are treated as three extra "nodes" of the gradient product and condensed.
Matrix24 hex8_incompatible_stiffness(const Hex8Coords& xyz, const SolidMaterial& material) {
  const Hex8Table& table = hex8_table();
  static const Eigen::Matrix<double, 8, 3> centre_dnat_t = [] {
    Eigen::Matrix<double, 8, 1> n;
    Eigen::Matrix<double, 3, 8> dn;
    hex8_shape(0.0, 0.0, 0.0, n, dn);
    return Eigen::Matrix<double, 8, 3>(dn.transpose());
  }();
  double det0 = 0.0;
  const Eigen::Matrix3d jac0_inv =
      jacobian_checked<8>(centre_dnat_t, xyz, "hex8 incompatible", Eigen::Vector3d::Zero(), det0).inverse();

  Eigen::Matrix<double, 33, 8> g;  // rows 0-23 nodes, 24-32 bubbles; column p: Gauss point p
  for (int p = 0; p < 8; ++p) {
    double det = 0.0;
    const Eigen::Matrix3d jac = jacobian_checked<8>(table.dnat_t[p], xyz, "hex8 incompatible", table.point[p], det);
    const double root = std::sqrt(table.weight[p] * det);
    Eigen::Map<Eigen::Matrix<double, 3, 8>> grad(g.col(p).data());
    grad.noalias() = jac.inverse().lazyProduct(table.dnat[p]);
    grad *= root;
    // dP_k/dxi_k = -2 xi_k (diagonal); columns are the three bubbles.
    const Eigen::Matrix3d dbubble = (-2.0 * table.point[p]).asDiagonal();
    Eigen::Map<Eigen::Matrix3d> bubble(g.col(p).data() + 24);
    bubble.noalias() = jac0_inv * dbubble;
    bubble *= root * det0 / det;
  }
  Eigen::Matrix<double, 33, 33> h = Eigen::Matrix<double, 33, 33>::Zero();
  h.selfadjointView<Eigen::Lower>().rankUpdate(g);
  const Lame l = lame(material.youngs_modulus, material.poisson_ratio);
  const Eigen::Matrix<double, 33, 33> full = isotropic_from_gradient_products<33>(h, l.lambda, l.mu);

  const Eigen::Matrix<double, 9, 9> kaa = full.bottomRightCorner<9, 9>();
  const Eigen::Matrix<double, 9, 24> kau = full.bottomLeftCorner<9, 24>();
  const Eigen::LLT<Eigen::Matrix<double, 9, 9>> llt(kaa);
  if (llt.info() != Eigen::Success) {
    throw std::domain_error("hex8 incompatible: bubble stiffness not positive definite (degenerate element)");
  }
  Matrix24 k = full.topLeftCorner<24, 24>();
  k.noalias() -= kau.transpose() * llt.solve(kau);
  return 0.5 * (k + k.transpose());  // the condensation is symmetric only up to round-off
}

Matrix24 hex8_consistent_mass(const Hex8Coords& xyz, const SolidMaterial& material) {
  return hex_consistent_mass(hex8_table(), xyz, material, "hex8");
}

Matrix60 hex20_stiffness(const Hex20Coords& xyz, const SolidMaterial& material) {
  return hex_stiffness(hex20_table(), xyz, material, "hex20");
}

Matrix60 hex20_consistent_mass(const Hex20Coords& xyz, const SolidMaterial& material) {
  return hex_consistent_mass(hex20_table(), xyz, material, "hex20");
}

void hex8_shape_functions(const Eigen::Vector3d& natural, Eigen::Matrix<double, 8, 1>& n,
                          Eigen::Matrix<double, 3, 8>& dn) {
  hex8_shape(natural[0], natural[1], natural[2], n, dn);
}

void hex20_shape_functions(const Eigen::Vector3d& natural, Eigen::Matrix<double, 20, 1>& n,
                           Eigen::Matrix<double, 3, 20>& dn) {
  hex20_shape(natural[0], natural[1], natural[2], n, dn);
}

double hex8_volume(const Hex8Coords& xyz) { return hex_volume(hex8_table(), xyz, "hex8"); }

double hex20_volume(const Hex20Coords& xyz) { return hex_volume(hex20_table(), xyz, "hex20"); }

}  // namespace bb::fe
