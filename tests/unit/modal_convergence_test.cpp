// Modal analysis (analysis/modal_analysis, linalg/modal_solver) against beam theory: a plane-
// stress Q4 cantilever converges from above towards the Timoshenko beam frequencies, computed
// here independently from the clamped-free Timoshenko frequency equation (and cross-checked
// with a 1D Timoshenko finite-element beam and with Euler-Bernoulli). Also: mass normalization,
// and the three rigid-body modes of a free plate. Units: SI.
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/modal_analysis.hpp"
#include "assembly/assemble.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "linalg/modal_solver.hpp"
#include "mesh/mapped_quad.hpp"
#include "test_support.hpp"

namespace bb {
namespace {

// A rectangular-section beam; as a 1D Timoshenko beam: A = h t, I = t h^3 / 12, G = E / 2(1 + nu).
struct Beam {
  double length = 10.0, height = 1.0, thickness = 0.1;
  double youngs_modulus = 2.0e11, poisson_ratio = 0.3, density = 7800.0;
  // Cowper's shear coefficient of a rectangle.
  double shear_coefficient() const { return 10.0 * (1 + poisson_ratio) / (12.0 + 11.0 * poisson_ratio); }
  double area() const { return height * thickness; }
  double inertia() const { return thickness * height * height * height / 12.0; }
  double shear_stiffness() const {  // k G A
    return shear_coefficient() * youngs_modulus / (2.0 * (1.0 + poisson_ratio)) * area();
  }
};

// Determinant of the clamped-free boundary conditions for w = C1 cosh(ax) + C2 sinh(ax) +
// C3 cos(bx) + C4 sin(bx) and the matching rotation psi, solving
//   kGA (w'' - psi') + rho A w^2 w = 0,  EI psi'' + kGA (w' - psi) + rho I w^2 psi = 0
// below the second spectrum's cut-off: w(0) = psi(0) = 0, EI psi'(L) = 0, kGA (w'(L) - psi(L)) = 0.
double timoshenko_clamped_free_determinant(const Beam& b, double omega) {
  const double rho = b.density, e = b.youngs_modulus, ei = e * b.inertia(), kga = b.shear_stiffness();
  const double w2 = omega * omega;
  // lambda^2 = mu solves mu^2 + p mu - q0 = 0 with p = w^2 (rho / E + rho A / kGA).
  const double p = w2 * (rho / e + rho * b.area() / kga);
  const double q0 = rho * b.area() * w2 / ei * (1.0 - rho * b.inertia() * w2 / kga);
  const double root = std::sqrt(p * p + 4.0 * q0);
  const double alpha = std::sqrt(2.0 * q0 / (p + root));  // mu = +alpha^2 (no cancellation)
  const double beta = std::sqrt(0.5 * (p + root));        // mu = -beta^2
  const double r = rho * b.area() * w2 / kga;
  const double a = alpha + r / alpha;  // psi / w amplitude ratio of the hyperbolic pair
  const double c = r / beta - beta;    // ... and of the trigonometric pair
  const double l = b.length;
  const double ch = std::cosh(alpha * l), sh = std::sinh(alpha * l), co = std::cos(beta * l), si = std::sin(beta * l);
  Eigen::Matrix4d m;
  m << 1, 0, 1, 0,                                                   // w(0)
      0, a, 0, -c,                                                   // psi(0)
      a * alpha * ch, a * alpha * sh, c * beta * co, c * beta * si,  // psi'(L)
      -sh / alpha, -ch / alpha, -si / beta, co / beta;               // (w'(L) - psi(L)) / r
  return m.determinant();
}

// Lowest n natural frequencies [Hz]: scan for sign changes, then bisect.
std::vector<double> timoshenko_cantilever_frequencies(const Beam& b, int n) {
  std::vector<double> out;
  // Start far below the first root: a twentieth of the Euler-Bernoulli fundamental, which is
  // an upper bound of the Timoshenko one.
  double lo = 0.05 * 3.516 / (b.length * b.length) * std::sqrt(b.youngs_modulus * b.inertia() / (b.density * b.area()));
  double f_lo = timoshenko_clamped_free_determinant(b, lo);
  while (static_cast<int>(out.size()) < n) {
    const double hi = lo * 1.002;
    const double f_hi = timoshenko_clamped_free_determinant(b, hi);
    if ((f_lo < 0) != (f_hi < 0)) {
      double x0 = lo, x1 = hi, g0 = f_lo;
      for (int it = 0; it < 200 && x1 - x0 > 1e-14 * x1; ++it) {
        const double mid = 0.5 * (x0 + x1), gm = timoshenko_clamped_free_determinant(b, mid);
        if ((gm < 0) == (g0 < 0)) {
          x0 = mid;
          g0 = gm;
        } else {
          x1 = mid;
        }
      }
      out.push_back(0.5 * (x0 + x1) / kTwoPi);
    }
    lo = hi;
    f_lo = f_hi;
  }
  return out;
}

// A 1D Timoshenko beam of two-node elements (w, psi linear; one-point shear integration against
// locking; consistent translational and rotary mass), clamped at x = 0. Lowest n frequencies [Hz].
std::vector<double> timoshenko_fe_frequencies(const Beam& b, int n_elements, int n) {
  const int n_dof = 2 * n_elements;  // node 0 clamped
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n_dof + 2, n_dof + 2), m = k;
  const double h = b.length / n_elements, ei = b.youngs_modulus * b.inertia(), kga = b.shear_stiffness();
  const double ra = b.density * b.area(), ri = b.density * b.inertia();
  for (int e = 0; e < n_elements; ++e) {
    Eigen::Matrix4d ke = Eigen::Matrix4d::Zero(), me = Eigen::Matrix4d::Zero();  // (w1, psi1, w2, psi2)
    ke(1, 1) = ke(3, 3) = ei / h;
    ke(1, 3) = ke(3, 1) = -ei / h;
    const Eigen::Vector4d g(-1.0 / h, -0.5, 1.0 / h, -0.5);  // w' - psi at the midpoint
    ke += kga * h * g * g.transpose();
    me(0, 0) = me(2, 2) = ra * h / 3.0;
    me(0, 2) = me(2, 0) = ra * h / 6.0;
    me(1, 1) = me(3, 3) = ri * h / 3.0;
    me(1, 3) = me(3, 1) = ri * h / 6.0;
    k.block<4, 4>(2 * e, 2 * e) += ke;
    m.block<4, 4>(2 * e, 2 * e) += me;
  }
  const Eigen::MatrixXd kf = k.bottomRightCorner(n_dof, n_dof), mf = m.bottomRightCorner(n_dof, n_dof);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(kf, mf);
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(std::sqrt(eig.eigenvalues()[i]) / kTwoPi);
  return out;
}

std::vector<double> euler_bernoulli_cantilever_frequencies(const Beam& b) {
  const double beta_l[] = {1.875104068711961, 4.694091132974175, 7.854757438237613};
  std::vector<double> out;
  for (double bl : beta_l)
    out.push_back(bl * bl / (b.length * b.length) * std::sqrt(b.youngs_modulus * b.inertia() / (b.density * b.area())) /
                  kTwoPi);
  return out;
}

TEST(TimoshenkoReference, FrequencyEquationReducesToEulerBernoulliForASlenderBeam) {
  Beam slender;
  slender.height = 1e-4 * slender.length;  // L / h = 1e4: shear and rotary inertia lower mode 3 by ~1e-7
  const std::vector<double> t = timoshenko_cantilever_frequencies(slender, 3);
  const std::vector<double> eb = euler_bernoulli_cantilever_frequencies(slender);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(t[i] / eb[i], 1.0, 1e-6) << "mode " << i + 1;
    EXPECT_LT(t[i], eb[i]) << "shear and rotary inertia can only lower the frequency";
  }
}

TEST(TimoshenkoReference, OneDimensionalFeBeamReducesToEulerBernoulliForASlenderBeam) {
  Beam slender;
  slender.height = 1e-3 * slender.length;
  const std::vector<double> fe = timoshenko_fe_frequencies(slender, 200, 3);
  const std::vector<double> eb = euler_bernoulli_cantilever_frequencies(slender);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(fe[i] / eb[i], 1.0, 5e-4) << "mode " << i + 1;
}

TEST(TimoshenkoReference, FrequencyEquationAgreesWithOneDimensionalFeBeamForADeepBeam) {
  // L / h = 10: shear lowers the third bending frequency by ~10 %, so this checks the shear terms.
  const Beam deep;
  const std::vector<double> exact = timoshenko_cantilever_frequencies(deep, 3);
  const std::vector<double> fe = timoshenko_fe_frequencies(deep, 300, 3);
  const std::vector<double> eb = euler_bernoulli_cantilever_frequencies(deep);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(fe[i] / exact[i], 1.0, 1e-4) << "mode " << i + 1;
    EXPECT_LT(exact[i], eb[i]);
  }
  EXPECT_LT(exact[2] / eb[2], 0.95) << "shear must matter for mode 3 at L/h = 10";
}

Mesh cantilever_mesh(const Beam& b, int nx, int ny, ElementType type = ElementType::q4) {
  MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(b.length, 0), Eigen::Vector2d(b.length, b.height),
                  Eigen::Vector2d(0, b.height)};
  spec.nx = nx;
  spec.ny = ny;
  spec.element = type;
  spec.numbering = NodeNumbering::rows;
  return generate_mapped_quad(spec);
}

Model clamped_cantilever(const Beam& b, int nx, int ny) {
  Model model;
  model.mesh = cantilever_mesh(b, nx, ny);
  model.section = {b.youngs_modulus, b.poisson_ratio, b.density, b.thickness};
  std::vector<int> clamp;
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    if (model.mesh.coords(n, 0) < 1e-9) clamp.push_back(n);
  model.node_sets["clamp"] = clamp;
  model.constraints = {{"clamp", {0, 1}, 0.0}};
  return model;
}

// Share of a mode's squared amplitude that is flexural (uy symmetric and ux antisymmetric about the
// mid-plane y = h / 2). The mesh is symmetric, so modes are purely flexural or purely extensional.
double flexural_share(const Eigen::MatrixXd& shape, int nx, int ny) {
  double flexural = 0.0, total = 0.0;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int n = j * (nx + 1) + i, mirror = (ny - j) * (nx + 1) + i;  // rows numbering
      const double ux_anti = 0.5 * (shape(n, 0) - shape(mirror, 0)), uy_sym = 0.5 * (shape(n, 1) + shape(mirror, 1));
      flexural += ux_anti * ux_anti + uy_sym * uy_sym;
      total += shape(n, 0) * shape(n, 0) + shape(n, 1) * shape(n, 1);
    }
  return flexural / total;
}

std::vector<double> bending_frequencies(const Beam& b, int nx, int ny, int n_bending) {
  ModalOptions options;
  options.n_modes = 7;
  const ModalResult r = solve_modal(clamped_cantilever(b, nx, ny), options);
  std::vector<double> out;
  for (int k = 0; k < r.frequencies_hz.size() && static_cast<int>(out.size()) < n_bending; ++k) {
    const double share = flexural_share(r.shapes[static_cast<size_t>(k)], nx, ny);
    EXPECT_TRUE(share > 1 - 1e-8 || share < 1e-8) << "mode " << k + 1 << " mixes bending and stretching: " << share;
    if (share > 0.5) out.push_back(r.frequencies_hz[k]);
  }
  EXPECT_EQ(static_cast<int>(out.size()), n_bending) << "mesh " << nx << "x" << ny;
  return out;
}

TEST(Q4CantileverModes, BendingFrequenciesDecreaseMonotonicallyWithRefinementTowardsTimoshenko) {
  // Rayleigh-Ritz: conforming elements with consistent mass give upper bounds, and nested meshes
  // nested trial spaces, so each bending frequency falls with every refinement.
  const Beam beam;
  const std::vector<double> reference = timoshenko_cantilever_frequencies(beam, 3);
  std::vector<std::vector<double>> levels;
  for (int level : {1, 2, 4, 8}) levels.push_back(bending_frequencies(beam, 20 * level, 2 * level, 3));
  for (int mode = 0; mode < 3; ++mode) {
    std::vector<double> error;
    for (size_t l = 0; l < levels.size(); ++l) {
      ASSERT_EQ(levels[l].size(), 3u);
      error.push_back((levels[l][mode] - reference[mode]) / reference[mode]);
      if (l == 0) continue;
      EXPECT_LT(levels[l][mode], levels[l - 1][mode]) << "mode " << mode + 1 << " level " << l;
      EXPECT_LT(std::abs(error[l]), std::abs(error[l - 1])) << "mode " << mode + 1 << " level " << l;
    }
    EXPECT_LT(std::abs(error.back()), 0.01) << "bending mode " << mode + 1 << ": " << levels.back()[mode]
                                            << " Hz vs Timoshenko " << reference[mode] << " Hz";
  }
}

TEST(ModalSolution, ShapesAreMassNormalizedAndDiagonalizeTheStiffness) {
  const Beam beam;
  const Model model = clamped_cantilever(beam, 40, 4);
  ModalOptions options;
  options.n_modes = 5;
  const ModalResult r = solve_modal(model, options);
  const GlobalMatrices g = assemble(model.mesh, model.section);
  Eigen::MatrixXd phi(2 * model.mesh.n_nodes(), options.n_modes);
  for (int k = 0; k < options.n_modes; ++k) {
    const Eigen::MatrixXd& s = r.shapes[static_cast<size_t>(k)];
    for (int n = 0; n < model.mesh.n_nodes(); ++n) phi.block<2, 1>(2 * n, k) = s.row(n).transpose();
    for (int n : model.node_sets.at("clamp")) EXPECT_EQ(s.row(n).norm(), 0.0);
  }
  const Eigen::MatrixXd modal_mass = phi.transpose() * (g.mass * phi);
  const Eigen::MatrixXd modal_stiffness = phi.transpose() * (g.stiffness * phi);
  EXPECT_LE((modal_mass - Eigen::MatrixXd::Identity(options.n_modes, options.n_modes)).norm(), 1e-8);
  const Eigen::VectorXd omega2 = (kTwoPi * r.frequencies_hz).array().square();
  EXPECT_LE((modal_stiffness - Eigen::MatrixXd(omega2.asDiagonal())).norm(), 1e-8 * omega2.maxCoeff());
  for (int k = 1; k < options.n_modes; ++k) EXPECT_GE(r.frequencies_hz[k], r.frequencies_hz[k - 1]);
  EXPECT_LT(r.max_residual, 1e-8);
}

class FreeFreePlate : public ::testing::TestWithParam<ElementType> {};

TEST_P(FreeFreePlate, HasThreeRigidBodyModesBeforeTheFirstElasticOne) {
  Beam plate;
  plate.length = 4.0;
  const Mesh mesh = cantilever_mesh(plate, 16, 4, GetParam());
  const fe::PlaneSection sec{plate.youngs_modulus, plate.poisson_ratio, plate.density, plate.thickness};
  const GlobalMatrices g = assemble(mesh, sec);
  ModalOptions options;
  options.n_modes = 5;
  const ModalSolution sol = lowest_modes(g.stiffness, g.mass, options);
  const Eigen::VectorXd& lambda = sol.eigenvalues;
  ASSERT_GT(lambda[3], 0.0);
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(lambda[i]), 1e-8 * lambda[3]) << "mode " << i + 1;
  EXPECT_LT(lambda[3], lambda[4] * (1 + 1e-12));
  // The first elastic mode of a free-free beam is above 0.8 x its Euler-Bernoulli value
  // (beta L = 4.7300) and below it (shear, rotary inertia): a real frequency, not a stray zero.
  const double eb = 4.730040744862704 * 4.730040744862704 / (plate.length * plate.length) *
                    std::sqrt(plate.youngs_modulus * plate.inertia() / (plate.density * plate.area()));
  EXPECT_GT(std::sqrt(lambda[3]), 0.8 * eb);
  EXPECT_LT(std::sqrt(lambda[3]), 1.2 * eb);
  // The three zero modes span exactly the rigid motions: each rigid vector equals its M-orthogonal
  // projection on them.
  const Eigen::MatrixXd phi = sol.shapes.leftCols(3);
  const Eigen::MatrixXd r = test::rigid_body_modes(mesh.coords);
  for (int c = 0; c < 3; ++c) {
    const Eigen::VectorXd projected = phi * (phi.transpose() * (g.mass * r.col(c)));
    EXPECT_LE((projected - r.col(c)).norm(), 1e-6 * r.col(c).norm()) << "rigid motion " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(Modal, FreeFreePlate, ::testing::Values(ElementType::q4, ElementType::cst),
                         [](const ::testing::TestParamInfo<ElementType>& p) {
                           return p.param == ElementType::q4 ? std::string("Q4") : std::string("Cst");
                         });

TEST(ModalSolution, AskingForAsManyModesAsFreeDofsIsRejected) {
  const Beam beam;
  const Model model = clamped_cantilever(beam, 1, 1);  // 2 free nodes, 4 free DOFs
  ModalOptions options;
  options.n_modes = 4;
  EXPECT_THROW(solve_modal(model, options), InputError);  // a case error: 'analysis.modes'
  // One level down, the eigensolver itself refuses (Lanczos needs n_modes < n).
  const GlobalMatrices g = assemble(model.mesh, model.section);  // 8 DOFs, unconstrained
  options.n_modes = 8;
  EXPECT_THROW(lowest_modes(g.stiffness, g.mass, options), SolverError);
}

}  // namespace
}  // namespace bb
