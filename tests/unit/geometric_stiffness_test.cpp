// Integration-point stresses and initial-stress (geometric) stiffness of fe/initial_stress, for every
// element type: the stress patch test (a linear displacement field gives D eps exactly at every point,
// distorted shapes included), symmetry, rigid translations in the null space, the exact energy of an
// infinitesimal rotation under a uniform stress, the discrete taut-string spectrum of a bar under
// uniform tension, and Euler's buckling load of a clamped-free column. Units: SI.
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "assembly/assemble.hpp"
#include "assembly/dof_map.hpp"
#include "common/constants.hpp"
#include "fe/initial_stress.hpp"
#include "ffrf/body_assembly.hpp"
#include "ffrf_test_models.hpp"
#include "solid_test_support.hpp"

namespace bb {
namespace {

// One element of any type: coordinates, stresses of a nodal displacement, K_sigma of point stresses.
struct ElementCase {
  std::string name;
  int dim = 2, nodes = 4, points = 4;
  Eigen::MatrixXd xyz;
  double volume = 0.0;  // [m^3] (2D: area x thickness)
  std::function<Eigen::MatrixXd(const Eigen::VectorXd&)> stresses;
  std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)> geometric;
  Eigen::MatrixXd elasticity;
};

void PrintTo(const ElementCase& c, std::ostream* os) { *os << c.name; }

const fe::PlaneSection kSection{.youngs_modulus = 2.0e11, .poisson_ratio = 0.3, .density = 7800.0, .thickness = 0.02};
const fe::SolidMaterial kSolid{2.0e11, 0.3, 7800.0};

double polygon_area(const Eigen::MatrixXd& xy) {
  double a = 0.0;
  for (Eigen::Index i = 0; i < xy.rows(); ++i) {
    const Eigen::Index j = (i + 1) % xy.rows();
    a += xy(i, 0) * xy(j, 1) - xy(j, 0) * xy(i, 1);
  }
  return 0.5 * a;
}

fe::Hex8Coords distorted_hex8() {
  fe::Hex8Coords xyz = 0.5 * (test::hex20_natural_nodes().topRows<8>().array() + 1.0);
  fe::Hex8Coords perturbation;
  perturbation << 0.08, -0.11, 0.05, -0.12, 0.07, -0.09, 0.13, 0.10, 0.06, -0.06, -0.14, 0.11,  //
      0.10, 0.04, -0.13, -0.09, 0.12, 0.14, 0.05, -0.08, -0.07, 0.14, 0.09, -0.12;
  return xyz + perturbation;
}

std::vector<ElementCase> element_cases() {
  std::vector<ElementCase> out;
  fe::Q4Coords q4;
  q4 << 0.0, 0.0, 1.1, 0.1, 1.3, 0.9, -0.1, 0.7;
  out.push_back({"Q4", 2, 4, 4, q4, polygon_area(q4) * kSection.thickness,
                 [q4](const Eigen::VectorXd& u) { return Eigen::MatrixXd(fe::q4_point_stresses(q4, u, kSection)); },
                 [q4](const Eigen::MatrixXd& s) {
                   return Eigen::MatrixXd(fe::q4_geometric_stiffness(q4, s, kSection.thickness));
                 },
                 fe::plane_stress_elasticity(kSection.youngs_modulus, kSection.poisson_ratio)});
  fe::CstCoords cst;
  cst << 0.1, 0.0, 1.2, 0.3, 0.4, 0.9;
  out.push_back({"Cst", 2, 3, 1, cst, polygon_area(cst) * kSection.thickness,
                 [cst](const Eigen::VectorXd& u) { return Eigen::MatrixXd(fe::cst_point_stresses(cst, u, kSection)); },
                 [cst](const Eigen::MatrixXd& s) {
                   return Eigen::MatrixXd(fe::cst_geometric_stiffness(cst, s, kSection.thickness));
                 },
                 fe::plane_stress_elasticity(kSection.youngs_modulus, kSection.poisson_ratio)});
  const fe::Hex8Coords h8 = distorted_hex8();
  const Eigen::MatrixXd d3 = fe::isotropic_elasticity(kSolid.youngs_modulus, kSolid.poisson_ratio);
  auto hex8_k = [h8](const Eigen::MatrixXd& s) { return Eigen::MatrixXd(fe::hex8_geometric_stiffness(h8, s)); };
  out.push_back({"Hex8", 3, 8, 8, h8, fe::hex8_volume(h8),
                 [h8](const Eigen::VectorXd& u) { return Eigen::MatrixXd(fe::hex8_point_stresses(h8, u, kSolid)); },
                 hex8_k, d3});
  out.push_back(
      {"Hex8Incompatible", 3, 8, 8, h8, fe::hex8_volume(h8),
       [h8](const Eigen::VectorXd& u) { return Eigen::MatrixXd(fe::hex8_incompatible_point_stresses(h8, u, kSolid)); },
       hex8_k, d3});
  fe::Hex20Coords h20 = test::hex20_from_corners(h8);
  h20.row(8) += Eigen::RowVector3d(0.03, -0.02, 0.04);  // one curved edge
  h20.row(17) += Eigen::RowVector3d(-0.02, 0.03, 0.01);
  out.push_back({"Hex20", 3, 20, 27, h20, fe::hex20_volume(h20),
                 [h20](const Eigen::VectorXd& u) { return Eigen::MatrixXd(fe::hex20_point_stresses(h20, u, kSolid)); },
                 [h20](const Eigen::MatrixXd& s) { return Eigen::MatrixXd(fe::hex20_geometric_stiffness(h20, s)); },
                 d3});
  return out;
}

class ElementStress : public ::testing::TestWithParam<ElementCase> {};

// Nodal values of u(x) = u0 + A x and the engineering strain of A.
Eigen::VectorXd linear_field(const Eigen::MatrixXd& xyz, const Eigen::MatrixXd& a, const Eigen::VectorXd& u0) {
  const auto dim = xyz.cols();
  Eigen::VectorXd u(xyz.rows() * dim);
  for (Eigen::Index n = 0; n < xyz.rows(); ++n) u.segment(n * dim, dim) = u0 + a * xyz.row(n).transpose();
  return u;
}

Eigen::VectorXd engineering_strain(const Eigen::MatrixXd& a) {
  if (a.rows() == 2) return Eigen::Vector3d(a(0, 0), a(1, 1), a(0, 1) + a(1, 0));
  Eigen::VectorXd e(6);
  e << a(0, 0), a(1, 1), a(2, 2), a(0, 1) + a(1, 0), a(1, 2) + a(2, 1), a(2, 0) + a(0, 2);
  return e;
}

TEST_P(ElementStress, LinearDisplacementFieldGivesTheConstantStressAtEveryPoint) {
  const ElementCase& c = GetParam();
  Eigen::MatrixXd a(c.dim, c.dim);
  if (c.dim == 2)
    a << 1.3e-4, -0.7e-4, 2.1e-4, -0.4e-4;
  else
    a << 1.3e-4, -0.7e-4, 0.5e-4, 2.1e-4, -0.4e-4, 0.9e-4, -1.1e-4, 0.6e-4, 0.8e-4;
  const Eigen::VectorXd u0 = Eigen::VectorXd::LinSpaced(c.dim, 1e-3, 3e-3);
  const Eigen::MatrixXd s = c.stresses(linear_field(c.xyz, a, u0));
  const Eigen::VectorXd expected = c.elasticity * engineering_strain(a);
  ASSERT_EQ(s.cols(), c.points);
  for (Eigen::Index p = 0; p < s.cols(); ++p)
    EXPECT_LT((s.col(p) - expected).norm(), 1e-9 * expected.norm()) << "point " << p;
}

// A uniform stress at every point, Voigt or plane order.
Eigen::MatrixXd uniform_stress(const ElementCase& c, const Eigen::VectorXd& s) { return s.replicate(1, c.points); }

Eigen::VectorXd some_stress(int dim) {
  if (dim == 2) return Eigen::Vector3d(3.0e6, -1.2e6, 0.8e6);
  Eigen::VectorXd s(6);
  s << 3.0e6, -1.2e6, 0.5e6, 0.8e6, -0.6e6, 0.3e6;
  return s;
}

TEST_P(ElementStress, GeometricStiffnessIsSymmetricForAVaryingStressField) {
  const ElementCase& c = GetParam();
  Eigen::MatrixXd s = Eigen::MatrixXd::Random(c.dim == 2 ? 3 : 6, c.points) * 1e6;
  const Eigen::MatrixXd k = c.geometric(s);
  EXPECT_LT((k - k.transpose()).norm(), 1e-14 * k.norm());
}

TEST_P(ElementStress, RigidTranslationsAreNotStiffened) {
  const ElementCase& c = GetParam();
  const Eigen::MatrixXd k = c.geometric(Eigen::MatrixXd::Random(c.dim == 2 ? 3 : 6, c.points) * 1e6);
  for (int d = 0; d < c.dim; ++d) {
    Eigen::VectorXd t = Eigen::VectorXd::Zero(c.dim * c.nodes);
    for (int n = 0; n < c.nodes; ++n) t[c.dim * n + d] = 1.0;
    EXPECT_LT((k * t).norm(), 1e-12 * k.norm()) << "direction " << d;
  }
}

// u = w x (x - x0): grad u = W (skew), so 1/2 sum_i grad(u_i)^T sigma grad(u_i) = 1/2 tr(W sigma W^T)
// = 1/2 (|w|^2 tr(sigma) - w^T sigma w) per unit volume, exactly (constant gradients).
TEST_P(ElementStress, InfinitesimalRotationEnergyIsTheTraceFormulaTimesTheVolume) {
  const ElementCase& c = GetParam();
  const Eigen::VectorXd s = some_stress(c.dim);
  const Eigen::MatrixXd k = c.geometric(uniform_stress(c, s));
  Eigen::Vector3d w = c.dim == 2 ? Eigen::Vector3d(0, 0, 1e-3) : Eigen::Vector3d(0.4e-3, -0.7e-3, 1.0e-3);
  Eigen::Matrix3d sigma;
  if (c.dim == 2)
    sigma << s[0], s[2], 0, s[2], s[1], 0, 0, 0, 0;
  else
    sigma << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  Eigen::VectorXd u(c.dim * c.nodes);
  for (int n = 0; n < c.nodes; ++n) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x.head(c.dim) = c.xyz.row(n).transpose();
    u.segment(c.dim * n, c.dim) = w.cross(x - Eigen::Vector3d(0.3, 0.2, 0.1)).head(c.dim);
  }
  const double expected = 0.5 * c.volume * (w.squaredNorm() * sigma.trace() - w.dot(sigma * w));
  EXPECT_NEAR(0.5 * u.dot(k * u), expected, 1e-10 * std::abs(expected));
}

INSTANTIATE_TEST_SUITE_P(GeometricStiffness, ElementStress, ::testing::ValuesIn(element_cases()),
                         [](const auto& param_info) { return param_info.param.name; });

// ---- Assembled: the string and the column ----

// K_sigma and M of a beam model under the uniform uniaxial stress of u = eps (x, -nu y, -nu z).
struct Assembled {
  Eigen::MatrixXd k, m, kg;  // all DOFs
};

Assembled assembled_under_uniform_stress(const Model& model, double sigma_xx) {
  const Mesh& mesh = model.mesh;
  const double eps = sigma_xx / model.section.youngs_modulus, nu = model.section.poisson_ratio;
  Eigen::VectorXd u(mesh.n_nodes() * mesh.dim);
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    u[n * mesh.dim] = eps * mesh.coords(n, 0);
    for (int d = 1; d < mesh.dim; ++d) u[n * mesh.dim + d] = -nu * eps * mesh.coords(n, d);
  }
  Assembled a;
  a.kg = Eigen::MatrixXd(ffrf::assemble_geometric_stiffness(mesh, model.section, u));
  a.m = Eigen::MatrixXd(ffrf::assemble_inertia(mesh, model.section, Eigen::Vector3d::UnitZ()).mass);
  a.k = Eigen::MatrixXd(assemble(mesh, model.section, {.stiffness = true, .mass = false}).stiffness);
  return a;
}

// A taut string under tension sigma0 A, both ends fixed: linear elements with consistent mass have
// lambda_n = (6 / h^2)(1 - cos k h)/(2 + cos k h) sigma0 / rho, k = n pi / L, exactly. The stressed
// bar's K_sigma and M, restricted to transverse motions uniform over the section (each station one
// DOF), must reproduce that spectrum to round-off, and so converge to (n pi / L)^2 sigma0 / rho.
TEST(GeometricStiffness, UniformTensionGivesTheDiscreteTautStringSpectrum) {
  for (const ElementType type : {ElementType::q4, ElementType::hex8, ElementType::hex20}) {
    test::BeamSpec b;
    b.length = 2.0;
    b.element = type;
    b.nx = 12;
    const Model model = test::beam_model(b);
    const double sigma0 = 5.0e6;
    const Assembled a = assembled_under_uniform_stress(model, sigma0);
    const Mesh& mesh = model.mesh;
    // Stations: distinct x of the nodes; T maps station w to u_y of every node at that x.
    std::vector<double> xs;
    for (int n = 0; n < mesh.n_nodes(); ++n) xs.push_back(mesh.coords(n, 0));
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end(), [](double p, double q) { return std::abs(p - q) < 1e-12; }), xs.end());
    const auto inner = static_cast<Eigen::Index>(xs.size()) - 2;  // both ends fixed
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(a.k.rows(), inner);
    for (int n = 0; n < mesh.n_nodes(); ++n)
      for (Eigen::Index i = 0; i < inner; ++i)
        if (std::abs(mesh.coords(n, 0) - xs[static_cast<size_t>(i + 1)]) < 1e-12) t(n * mesh.dim + 1, i) = 1.0;
    const Eigen::MatrixXd kr = t.transpose() * a.kg * t, mr = t.transpose() * a.m * t;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(kr, mr);
    const double rho = model.section.density, c2 = sigma0 / rho, len = b.length;
    // hex20 and q4 stations are not equally spaced for hex20 (mid nodes): compare hex20 to the continuum.
    for (int n = 1; n <= 3; ++n) {
      const double k = n * kPi / len, exact = k * k * c2, got = eig.eigenvalues()[n - 1];
      if (type != ElementType::hex20) {
        const double h = len / b.nx;
        const double discrete = 6.0 / (h * h) * (1.0 - std::cos(k * h)) / (2.0 + std::cos(k * h)) * c2;
        EXPECT_NEAR(got, discrete, 1e-9 * discrete) << element_name(type) << " mode " << n;
      } else {
        EXPECT_NEAR(got, exact, 1e-3 * exact) << element_name(type) << " mode " << n;  // measured 5e-4
      }
      std::printf("  %-5s string mode %d: lambda %.8e, continuum %.8e (rel %.2e)\n",
                  std::string(element_name(type)).c_str(), n, got, exact, got / exact - 1.0);
    }
  }
}

// Buckling of a clamped-free column under uniform compression: the lowest lambda of
// K phi = lambda (-K_sigma(unit compression)) phi on the free DOFs is P_cr / A. Reference: Euler,
// P_E = pi^2 E I / (4 L^2), with Engesser's shear correction P_cr = P_E / (1 + P_E / (k G A)),
// k = 5/6 (Timoshenko & Gere, Theory of Elastic Stability, sec. 2.17): -0.12 % here.
double buckling_ratio(ElementType type, int nx, int ny, int nz, double& engesser) {
  test::BeamSpec b;
  b.length = 1.0;
  b.width = 0.05;  // y: the weaker direction (depth 0.08 along z)
  b.depth = 0.08;
  // nu = 0: with nu > 0 the fully clamped root face restrains the Poisson contraction, a singular
  // corner effect that converges only at first order (hex8i 10/20/80 elements: +1.1/+0.4/+0.1 %).
  b.poisson_ratio = 0.0;
  b.element = type;
  b.nx = nx;
  b.ny = ny;
  b.nz = nz;
  const Model model = test::beam_model(b);
  const DofMap dofs = number_dofs(model);
  const Assembled a = assembled_under_uniform_stress(model, -1.0);
  Eigen::MatrixXd kff(dofs.n_free, dofs.n_free), gff(dofs.n_free, dofs.n_free);
  for (int i = 0; i < dofs.n_free; ++i)
    for (int j = 0; j < dofs.n_free; ++j) {
      kff(i, j) = a.k(dofs.free_dofs[static_cast<size_t>(i)], dofs.free_dofs[static_cast<size_t>(j)]);
      gff(i, j) = -a.kg(dofs.free_dofs[static_cast<size_t>(i)], dofs.free_dofs[static_cast<size_t>(j)]);
    }
  // -K_sigma is only semi-definite: solve G phi = mu K phi (K > 0), lambda_min = 1 / mu_max.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(gff, kff);
  const double lambda = 1.0 / eig.eigenvalues().maxCoeff();
  const double inertia = b.depth * std::pow(b.width, 3) / 12.0, area = b.width * b.depth;
  const double p_euler = kPi * kPi * b.youngs_modulus * inertia / (4.0 * b.length * b.length);
  const double shear = 5.0 / 6.0 * b.youngs_modulus / 2.0 * area;  // k G A, nu = 0
  engesser = 1.0 / (1.0 + p_euler / shear);
  return lambda * area / p_euler;
}

TEST(GeometricStiffness, ClampedColumnBucklesAtTheEulerLoad) {
  struct Row {
    ElementType type;
    int nx, ny, nz;
    double tolerance;  // on |P_cr(FE) / P_cr(Engesser) - 1|: measured (printed) + margin
  };
  // q4 (2D, plane stress, the width in the plane) locks in shear: 12 % too stiff with 40x2 square
  // elements, 3 % with 80x4, which is why the slender rotating tests use hex8i or hex20.
  for (const Row& r : {Row{ElementType::hex8i, 20, 1, 1, 2e-3}, Row{ElementType::hex8i, 80, 1, 1, 1e-3},
                       Row{ElementType::hex20, 10, 1, 1, 1e-3}, Row{ElementType::hex20, 20, 1, 1, 1e-3},
                       Row{ElementType::q4, 80, 4, 1, 0.04}}) {
    double engesser = 0.0;
    const double ratio = buckling_ratio(r.type, r.nx, r.ny, r.nz, engesser);
    std::printf("  %-5s %2dx%dx%d: P_cr(FE) / P_Euler = %.5f (Engesser %.5f): %+.2e\n",
                std::string(element_name(r.type)).c_str(), r.nx, r.ny, r.nz, ratio, engesser, ratio / engesser - 1);
    EXPECT_NEAR(ratio / engesser, 1.0, r.tolerance) << element_name(r.type);
  }
}

}  // namespace
}  // namespace bb
