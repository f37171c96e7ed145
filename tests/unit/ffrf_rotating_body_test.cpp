// The floating-frame operators of ffrf/rotating_body on a uniform bar rotating about an axis through
// (or off) its root: exact mass properties, the elongation against the closed forms of
//   E u'' + rho Omega^2 (R0 + x + u) = 0   (spin softening)   and   E u'' + rho Omega^2 (R0 + x) = 0,
// u(0) = 0, u'(L) = 0 (x from the root), in 2D (q4) and 3D (hex8i, hex20), with convergence rates;
// the structure of M_p and G; and the input errors. Units: SI.
//
// The closed form without the u term is e.g. Code_Aster's verification note V3.04.104 (rotating bar,
// u = rho w^2 / 2E (x L^2 - x^3 / 3) for R0 = 0); with it, u = C1 sin kx + R0 cos kx - (R0 + x),
// k = Omega sqrt(rho / E), C1 = (1 + R0 k sin kL) / (k cos kL).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "ffrf/rotating_body.hpp"
#include "ffrf/rotating_modes.hpp"
#include "ffrf_test_models.hpp"

namespace bb {
namespace {

// A stocky bar (section 0.3 x 0.3 m): at 1000 rad/s rho Omega^2 L^2 / E = 0.039, so spin softening
// changes the elongation by 1.3 %, while the speed stays below the first bending frequency (1540
// rad/s), above which the spin-softened (unstiffened) body has no stable steady state.
struct Bar {
  double length = 1.0, root_radius = 0.4, e = 2.0e11, rho = 7800.0, section = 0.3;
  double omega = 1000.0;  // [rad/s]
};

double elongation_no_softening(const Bar& b, double x) {
  const double c = b.rho * b.omega * b.omega / b.e, l = b.length;
  return c * (b.root_radius * (l * x - 0.5 * x * x) + (0.5 * l * l * x - x * x * x / 6.0));
}

double elongation_softening(const Bar& b, double x) {
  const double k = b.omega * std::sqrt(b.rho / b.e), r = b.root_radius, l = b.length;
  const double c1 = (1.0 + r * k * std::sin(k * l)) / (k * std::cos(k * l));
  return c1 * std::sin(k * x) + r * std::cos(k * x) - (r + x);
}

// A bar whose root holds only what the 1D bar needs: u_x on the whole root face, plus the rigid
// motions of the section (u_y at the root centre; in 3D u_z there and at one more root node). With
// nu = 0 the section's own centrifugal stretch (along y) then decouples exactly from u_x(x).
Model bar_model(const Bar& bar, ElementType type, int nx) {
  test::BeamSpec b;
  b.length = bar.length;
  b.root_radius = bar.root_radius;
  b.youngs_modulus = bar.e;
  b.density = bar.rho;
  b.width = b.depth = bar.section;
  b.element = type;
  b.nx = nx;
  b.ny = b.nz = 2;
  Model model = test::beam_model(b);
  const int dim = model.mesh.dim;
  Eigen::VectorXd centre = Eigen::VectorXd::Zero(dim), side = Eigen::VectorXd::Zero(dim);
  centre[0] = side[0] = bar.root_radius;
  side[1] = 0.5 * b.width;
  model.node_sets["centre"] = {test::nearest_node(model.mesh, centre)};
  model.node_sets["side"] = {test::nearest_node(model.mesh, side)};
  model.constraints = {{"root", {0}, 0.0}, {"centre", {1}, 0.0}};
  if (dim == 3) {
    model.constraints.push_back({"centre", {2}, 0.0});
    model.constraints.push_back({"side", {2}, 0.0});
  }
  return model;
}

// Largest nodal error of u_x along the bar axis, relative to the tip value of the closed form.
template <typename Exact>
double axial_error(const Model& model, const ffrf::RotatingBody& body, const Eigen::VectorXd& u_free, const Bar& bar,
                   Exact exact) {
  const Eigen::VectorXd u = ffrf::expand_to_global(body, u_free);
  const int dim = model.mesh.dim;
  double worst = 0.0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const double x = model.mesh.coords(n, 0) - bar.root_radius;
    worst = std::max(worst, std::abs(u[n * dim] - exact(x)));
  }
  return worst / std::abs(exact(bar.length));
}

class RotatingBar : public ::testing::TestWithParam<ElementType> {};

TEST_P(RotatingBar, ElongationWithoutSpinSofteningIsExactAtTheNodes) {
  // Linear and quadratic elements with consistent loads are nodally exact for a 1D bar under a
  // polynomial load; f_c = M_p (x - p) is that consistent load, so the nodes must match to round-off.
  const Bar bar;
  const Model model = bar_model(bar, GetParam(), 6);
  const ffrf::RotatingBody body = ffrf::build_rotating_body(model);
  const Eigen::VectorXd u = bar.omega * bar.omega * body.unit_speed_deflection;
  const double err = axial_error(model, body, u, bar, [&](double x) { return elongation_no_softening(bar, x); });
  std::printf("  %s: tip u_x %.6e m, max nodal error %.2e relative\n", std::string(element_name(GetParam())).c_str(),
              elongation_no_softening(bar, bar.length), err);
  EXPECT_LT(err, 1e-9);
}

TEST_P(RotatingBar, ElongationWithSpinSofteningConvergesToTheClosedForm) {
  const Bar bar;
  const bool quadratic = GetParam() == ElementType::hex20;
  double previous = 0.0;
  for (const int nx : {4, 8, 16, 32}) {
    const Model model = bar_model(bar, GetParam(), nx);
    const ffrf::RotatingBody body = ffrf::build_rotating_body(model);
    const ffrf::StaticDeflection s = ffrf::centrifugal_deflection(body, bar.omega, {.stiffening = false});
    const double err =
        axial_error(model, body, s.displacement, bar, [&](double x) { return elongation_softening(bar, x); });
    if (previous > 0.0) {
      const double order = std::log2(previous / err);
      std::printf("  %s nx %2d: max nodal error %.3e relative, observed order %.2f\n",
                  std::string(element_name(GetParam())).c_str(), nx, err, order);
      if (err > 1e-11) {
        EXPECT_GT(order, quadratic ? 3.5 : 1.9);
      }
    }
    previous = err;
    if (nx == 32) {
      EXPECT_LT(err, quadratic ? 1e-8 : 2e-4);
    }
  }
  // Spin softening matters here: the two closed forms differ by several percent at the tip.
  EXPECT_GT(elongation_softening(bar, bar.length) / elongation_no_softening(bar, bar.length) - 1.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Ffrf, RotatingBar, ::testing::Values(ElementType::q4, ElementType::hex8i, ElementType::hex20),
                         [](const auto& param_info) { return std::string(element_name(param_info.param)); });

TEST(FfrfRotatingBody, MassPropertiesOfABoxAreExact) {
  // A box [R0, R0 + L] x [-w/2, w/2] x [-d/2, d/2] about z through the origin:
  // J0 = rho [w d ((R0 + L)^3 - R0^3) / 3 + L d w^3 / 12], first moment rho V (R0 + L/2, 0, 0).
  for (const ElementType type : {ElementType::q4, ElementType::cst, ElementType::hex8, ElementType::hex20}) {
    test::BeamSpec b;
    b.length = 0.3;
    b.root_radius = 0.2;
    b.width = 0.05;
    b.depth = 0.02;
    b.element = type;
    b.nx = 6;
    b.ny = 2;
    b.nz = 2;
    const ffrf::RotatingBody body = ffrf::build_rotating_body(test::beam_model(b));
    const double v = b.length * b.width * b.depth, rho = b.density, r1 = b.root_radius + b.length;
    const double j0 = rho * (b.width * b.depth * (r1 * r1 * r1 - std::pow(b.root_radius, 3)) / 3.0 +
                             b.length * b.depth * std::pow(b.width, 3) / 12.0);
    const auto& mp = body.mass_properties;
    EXPECT_NEAR(mp.mass, rho * v, 1e-12 * rho * v) << element_name(type);
    EXPECT_NEAR(mp.axis_inertia, j0, 1e-12 * j0) << element_name(type);
    EXPECT_NEAR(mp.first_moment[0], rho * v * (b.root_radius + 0.5 * b.length), 1e-12 * rho * v) << element_name(type);
    EXPECT_NEAR(mp.first_moment[1], 0.0, 1e-12 * rho * v) << element_name(type);
  }
}

TEST(FfrfRotatingBody, GyroscopicMatrixIsSkewAndProjectedMassIgnoresTheAxialDirection) {
  test::BeamSpec b;
  b.element = ElementType::hex8;
  b.nx = 4;
  ffrf::RotationAxis axis;
  axis.direction = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  axis.point = Eigen::Vector3d(0.1, -0.2, 0.3);
  const ffrf::RotatingBody body = ffrf::build_rotating_body(test::beam_model(b), axis);
  const Eigen::MatrixXd g(body.gyroscopic), mp(body.projected_mass), m(body.mass);
  EXPECT_LT((g + g.transpose()).norm(), 1e-14 * g.norm());
  EXPECT_LT((mp - mp.transpose()).norm(), 1e-14 * mp.norm());
  // A uniform motion along the axis carries no centrifugal or Coriolis inertia.
  Eigen::VectorXd along = Eigen::VectorXd::Zero(body.n_free());
  for (int i = 0; i < body.n_free(); ++i) along[i] = axis.direction[body.dofs.free_dofs[static_cast<size_t>(i)] % 3];
  EXPECT_LT((mp * along).norm(), 1e-13 * (m * along).norm());
  EXPECT_LT((g * along).norm(), 1e-13 * (m * along).norm());
}

TEST(FfrfRotatingBody, IllPosedInputIsRejectedWithAClearMessage) {
  test::BeamSpec b;
  const Model plane = test::beam_model(b);
  auto expect_input_error = [](auto&& fn, const std::string& needle) {
    try {
      fn();
      ADD_FAILURE() << "expected InputError mentioning '" << needle << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  ffrf::RotationAxis tilted;
  tilted.direction = Eigen::Vector3d(0.0, 0.6, 0.8);
  expect_input_error([&] { (void)ffrf::build_rotating_body(plane, tilted); }, "+z or -z");
  ffrf::RotationAxis long_axis;
  long_axis.direction = Eigen::Vector3d(0.0, 0.0, 2.0);
  expect_input_error([&] { (void)ffrf::build_rotating_body(plane, long_axis); }, "unit vector");
  Model moved = plane;
  moved.constraints[0].value = 1e-3;
  expect_input_error([&] { (void)ffrf::build_rotating_body(moved); }, "clamped");
  Model loose = plane;
  loose.constraints = {{"root", {0}, 0.0}};
  expect_input_error([&] { (void)ffrf::build_rotating_body(loose); }, "do not hold the body");
  Model massless = plane;
  massless.section.density = 0.0;
  expect_input_error([&] { (void)ffrf::build_rotating_body(massless); }, "density");
}

}  // namespace
}  // namespace bb
