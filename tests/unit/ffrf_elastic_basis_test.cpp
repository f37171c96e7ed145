// Elastic bases of ffrf/elastic_basis: the modal basis is mass-orthonormal, keeps exactly the
// selected fixed-interface modes at rest, and with its static correction shapes reproduces the
// static centrifugal deflection of the full model (measured with and without them); ill-posed
// bases are input errors. Units: SI.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/constants.hpp"
#include "common/errors.hpp"
#include "ffrf/elastic_basis.hpp"
#include "ffrf/rotating_modes.hpp"
#include "ffrf_test_models.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {
namespace {

test::BeamSpec blade_like_beam() {
  test::BeamSpec b;
  b.length = 0.15;
  b.width = 0.006;
  b.depth = 0.02;
  b.root_radius = 0.25;
  b.poisson_ratio = 0.3;
  b.element = ElementType::hex8i;
  b.nx = 30;
  b.ny = 1;
  b.nz = 2;
  return b;
}

TEST(FfrfElasticBasis, ModalBasisIsMassOrthonormalAndKeepsTheSelectedModes) {
  const ffrf::RotatingBody body = ffrf::build_rotating_body(test::beam_model(blade_like_beam()));
  ffrf::ElasticBasisOptions o = test::modal_basis(6);
  o.selected_modes = {1, 3, 5};
  const ffrf::ElasticBasis basis = ffrf::make_elastic_basis(body, o);
  const ModalSolution ref = lowest_modes(body.stiffness, body.mass, {.n_modes = 6});
  ASSERT_EQ(basis.mode_numbers, (std::vector<int>{1, 3, 5}));
  EXPECT_EQ(basis.size(), 3 + basis.static_shapes);
  EXPECT_GE(basis.static_shapes, 3);  // f_c, f_alpha and gravity shapes not spanned by 3 modes
  for (int i = 0; i < 3; ++i) {
    const double f = std::sqrt(ref.eigenvalues[2 * i]) / kTwoPi;
    EXPECT_NEAR(basis.frequencies_hz[i], f, 1e-8 * f);
  }
  const Eigen::MatrixXd mr = basis.shapes.transpose() * (body.mass * basis.shapes);
  EXPECT_LT((mr - Eigen::MatrixXd::Identity(mr.rows(), mr.cols())).norm(), 1e-10);
}

// (K + s W^2 K_s1 - W^2 M_p) u = W^2 f_c solved in the basis (Rayleigh-Ritz) against the full model.
double static_error(const ffrf::RotatingBody& body, const ffrf::ElasticBasis& basis, double w, bool stiffening) {
  const ffrf::ProjectedBody p = ffrf::project(body, basis);
  const double s = stiffening ? 1.0 : 0.0;
  const Eigen::MatrixXd op =
      p.stiffness.to_dense() + w * w * (s * p.geometric_stiffness.to_dense() - p.projected_mass.to_dense());
  const Eigen::VectorXd eta = op.ldlt().solve(w * w * p.centrifugal_load);
  const Eigen::VectorXd full = ffrf::centrifugal_deflection(body, w, {.stiffening = stiffening}).displacement;
  return (ffrf::to_free_dofs(basis, eta) - full).norm() / full.norm();
}

TEST(FfrfElasticBasis, StaticCorrectionShapesRecoverTheCentrifugalDeflection) {
  const ffrf::RotatingBody body = ffrf::build_rotating_body(test::beam_model(blade_like_beam()));
  const ffrf::ElasticBasis plain = ffrf::make_elastic_basis(body, test::modal_basis(8, false));
  const ffrf::ElasticBasis corrected = ffrf::make_elastic_basis(body, test::modal_basis(8, true));
  const double w1 = kTwoPi * plain.frequencies_hz[0];
  for (const bool stiffening : {false, true}) {
    const double e_plain = static_error(body, plain, 0.5 * w1, stiffening);
    const double e_corrected = static_error(body, corrected, 0.5 * w1, stiffening);
    std::printf("  stiffening %d, Omega = omega_1 / 2: static deflection error 8 modes %.2e, with static shapes %.2e\n",
                stiffening, e_plain, e_corrected);
    EXPECT_LT(e_corrected, 0.05 * e_plain);
    EXPECT_LT(e_corrected, 1e-3);
  }
  // Without rotation the static shapes are exact: K q = f_c solved in the basis.
  EXPECT_LT(static_error(body, corrected, 1e-3, false), 1e-9);
}

TEST(FfrfElasticBasis, IllPosedBasesAreInputErrorsThatSayWhatToChange) {
  test::BeamSpec b = blade_like_beam();
  b.nx = 2;
  const ffrf::RotatingBody body = ffrf::build_rotating_body(test::beam_model(b));
  auto expect_error = [&](const ffrf::ElasticBasisOptions& o, const std::string& needle) {
    try {
      (void)ffrf::make_elastic_basis(body, o);
      ADD_FAILURE() << "expected InputError mentioning " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_error(test::modal_basis(body.n_free() + 1), "larger than the body's");
  expect_error(test::modal_basis(0), "n_modes >= 1");
  ffrf::ElasticBasisOptions bad_pick = test::modal_basis(4);
  bad_pick.selected_modes = {2, 5};
  expect_error(bad_pick, "selected mode 5");
  ffrf::ElasticBasisOptions nodal_with_modes;
  nodal_with_modes.n_modes = 3;
  expect_error(nodal_with_modes, "modal basis");
  // As many modes as free DOFs is allowed (the dense eigensolver takes over).
  EXPECT_EQ(ffrf::make_elastic_basis(body, test::modal_basis(body.n_free(), false)).size(), body.n_free());
}

}  // namespace
}  // namespace bb
