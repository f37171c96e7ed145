// The Iwan element (friction/iwan_law) as parallel Jenkins sliders (friction/masing): its
// shares add up to the point's stiffness and slip force, its loop energy converges to Segalman's
// closed form (micro-slip power law of slope chi + 3, macro-slip beyond phi_max), its stiffness
// barely drops while its damping grows, and the law derivatives of the summed AFT follow the chain
// rule through the shares. Loops by the event-resolved AFT, exact for the sliders. Units: SI.
#include "friction/iwan_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "friction/aft.hpp"
#include "friction/masing.hpp"

namespace bb::friction {
namespace {

// A joint at constant normal load: K_T = 1e6 N/m, F_S = mu N0 = 0.5 * 200 = 100 N.
constexpr PointParameters kPoint{.kn = 0.0, .kt = 1.0e6, .mu = 0.5, .n0 = 200.0};

struct Loop {
  double energy = 0.0, stiffness = 0.0, damping = 0.0, peak_force = 0.0;
};

// u = A cos(theta), H = 1 input: the work of T on u is exact from T's first harmonic.
Loop loop(const IwanParameters& p, double amplitude) {
  const IwanDistribution law(p);
  AftOptions o;
  o.samples = 64;
  o.resolve_events = true;
  const Eigen::Vector3d u(0.0, amplitude, 0.0), v = Eigen::Vector3d::Zero();
  const AftResult r = aft_parallel(kPoint, &law, u, v, o);
  EXPECT_TRUE(r.closed);
  Loop out;
  out.energy = cycle_work(r.tangential, u);
  out.stiffness = r.tangential[1] / amplitude;
  out.damping = -r.tangential[2] / amplitude;
  out.peak_force = r.t.cwiseAbs().maxCoeff();
  return out;
}

double phi_max(const IwanParameters& p) { return iwan_density(p, kPoint.kt, kPoint.mu * kPoint.n0).phi_max; }

TEST(IwanLaw, SharesAddUpToThePointsStiffnessAndSlipForceInSlipOrder) {
  for (const IwanParameters p :
       {IwanParameters{-0.5, 0.0, 8}, IwanParameters{-0.9, 0.3, 40}, IwanParameters{0.0, 1.0, 2}}) {
    const std::vector<SliderShare> s = IwanDistribution(p).shares();
    ASSERT_EQ(static_cast<int>(s.size()), p.sliders);
    double stiffness = 0.0, load = 0.0, last_slip = 0.0;
    for (const SliderShare& x : s) {
      stiffness += x.stiffness, load += x.load;
      EXPECT_GT(x.load / x.stiffness, last_slip);  // listed from the first to slip
      last_slip = x.load / x.stiffness;
    }
    EXPECT_NEAR(stiffness, 1.0, 1e-14);
    EXPECT_NEAR(load, 1.0, 1e-14);
    double kt = 0.0, slip = 0.0;
    const IwanDistribution law(p);
    for (const PointParameters& j : parallel_sliders(kPoint, &law)) kt += j.kt, slip += j.mu * j.n0;
    EXPECT_NEAR(kt, kPoint.kt, 1e-8 * kPoint.kt);
    EXPECT_NEAR(slip, kPoint.mu * kPoint.n0, 1e-12 * kPoint.mu * kPoint.n0);
  }
}

// The sliders' loop energy falls on the closed form as the sliders multiply, at second order: four
// times the sliders divide the error by more than 8 (measured 11-40), and 256 sliders are within
// 1e-3 from A = phi_max / 20 up (measured 2.6e-4 and 6.8e-4 there, below 1e-5 in macro-slip).
TEST(IwanLaw, LoopEnergyConvergesToSegalmansClosedFormInMicroAndMacroSlip) {
  for (const double chi : {-0.5, -0.2}) {
    for (const double fraction : {0.05, 0.2, 0.6, 1.5, 3.0}) {
      double previous = 0.0;
      for (const int sliders : {64, 256}) {
        const IwanParameters p{chi, 0.2, sliders};
        const double a = fraction * phi_max(p);
        const double exact = iwan_cycle_energy(iwan_density(p, kPoint.kt, kPoint.mu * kPoint.n0), a);
        const double error = std::abs(loop(p, a).energy / exact - 1.0);
        if (sliders == 256) {
          EXPECT_LT(error, 1e-3) << "chi " << chi << ", A / phi_max " << fraction;
          EXPECT_LT(error, previous / 8.0) << "chi " << chi << ", A / phi_max " << fraction;
        }
        previous = error;
      }
    }
  }
}

TEST(IwanLaw, MicroSlipEnergyGrowsAsAmplitudeToTheChiPlusThree) {
  for (const double chi : {-0.7, -0.5, 0.0}) {
    const IwanParameters p{chi, 0.1, 256};
    const double a1 = 0.1 * phi_max(p), a2 = 0.4 * phi_max(p);
    const double slope = std::log(loop(p, a2).energy / loop(p, a1).energy) / std::log(a2 / a1);
    EXPECT_NEAR(slope, chi + 3.0, 0.01 * (chi + 3.0)) << "chi " << chi;
  }
}

// The joint behaviour a single Jenkins element cannot give: in micro-slip the loss stiffness and the
// loss of stiffness both grow as A^(chi + 1) from zero, so at small amplitude the joint dissipates
// (loss factor over 1 %) with its stiffness within 10 % of K_T, where a Jenkins element of the same
// K_T and F_S would still be stuck and dissipate nothing.
TEST(IwanLaw, MicroSlipDampsWhileTheStiffnessBarelyDrops) {
  const IwanParameters p{-0.5, 0.1, 256};
  const Loop small = loop(p, 0.01 * phi_max(p)), large = loop(p, 0.1 * phi_max(p));
  EXPECT_GT(small.stiffness, 0.9 * kPoint.kt);
  EXPECT_GT(small.damping / small.stiffness, 0.01);
  const double decade = std::log(10.0);
  EXPECT_NEAR(std::log(large.damping / small.damping) / decade, p.chi + 1.0, 0.03);
  EXPECT_NEAR(std::log((kPoint.kt - large.stiffness) / (kPoint.kt - small.stiffness)) / decade, p.chi + 1.0, 0.03);
}

TEST(IwanLaw, BeyondPhiMaxEverySliderSlipsAndTheForceIsMuN) {
  const IwanParameters p{-0.5, 0.2, 32};
  EXPECT_NEAR(loop(p, 3.0 * phi_max(p)).peak_force, kPoint.mu * kPoint.n0, 1e-9 * kPoint.mu * kPoint.n0);
}

// dT/d(kt, mu, n0) of the point: the sliders' derivatives carried through the shares.
TEST(IwanLaw, LawDerivativesOfTheSummedAftMatchCentralDifferences) {
  const IwanDistribution law(IwanParameters{-0.5, 0.2, 16});
  PointParameters point = kPoint;
  point.kn = 2.0e7;  // a varying normal load, so kn and n0 act too
  AftOptions o;
  o.samples = 64;
  o.resolve_events = true;
  o.law_derivatives = true;
  const Eigen::Vector3d u(0.0, 1.5e-4, 0.0), v(2e-6, 1e-6, 0.5e-6);
  const AftResult r = aft_parallel(point, &law, u, v, o);
  o.law_derivatives = false;
  for (const LawParameter k : {law_kn, law_kt, law_mu, law_n0}) {
    const auto field = [&](PointParameters& p) -> double& {
      return k == law_kn ? p.kn : k == law_kt ? p.kt : k == law_mu ? p.mu : p.n0;
    };
    PointParameters up = point, down = point;
    const double h = 1e-6 * field(up);
    field(up) += h, field(down) -= h;
    const Eigen::VectorXd fd =
        (aft_parallel(up, &law, u, v, o).tangential - aft_parallel(down, &law, u, v, o).tangential) / (2.0 * h);
    EXPECT_LT((r.dtangential_dlaw.col(k) - fd).norm(), 1e-5 * fd.norm() + 1e-9) << "parameter " << k;
  }
}

TEST(IwanLaw, RejectsAnExponentOutsideMinusOneToZeroAndTooFewSliders) {
  EXPECT_THROW(validate(IwanParameters{-1.0, 0.0, 8}), std::invalid_argument);
  EXPECT_THROW(validate(IwanParameters{0.1, 0.0, 8}), std::invalid_argument);
  EXPECT_THROW(validate(IwanParameters{-0.5, -0.1, 8}), std::invalid_argument);
  EXPECT_THROW(validate(IwanParameters{-0.5, 0.5, 1}), std::invalid_argument);
  EXPECT_NO_THROW(validate(IwanParameters{-0.5, 0.0, 1}));
  EXPECT_THROW(iwan_density(IwanParameters{}, 1e6, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace bb::friction

namespace bb::friction {
namespace {

// chi and beta are the law's own parameters: a calibration reads them by name and varies them by
// building the same law with one changed, which dissipates as a law built so from the start and
// refuses values outside its domain; a Jenkins point (no distribution) has none.
TEST(IwanLaw, ChiAndBetaAreItsOwnParametersReadAndVariedByName) {
  const IwanDistribution law(IwanParameters{.chi = -0.5, .beta = 0.2, .sliders = 32});
  EXPECT_EQ(law.parameter_names(), (std::vector<std::string>{"chi", "beta"}));
  EXPECT_EQ(law.parameter("chi"), -0.5);
  EXPECT_EQ(law.parameter("beta"), 0.2);
  const auto varied = law.with_parameter("chi", -0.3);
  const IwanDistribution fresh(IwanParameters{.chi = -0.3, .beta = 0.2, .sliders = 32});
  EXPECT_EQ(varied->parameter("chi"), -0.3);
  EXPECT_EQ(varied->parameter("beta"), 0.2);
  ASSERT_EQ(varied->shares().size(), fresh.shares().size());
  for (size_t i = 0; i < fresh.shares().size(); ++i) {
    EXPECT_EQ(varied->shares()[i].stiffness, fresh.shares()[i].stiffness);
    EXPECT_EQ(varied->shares()[i].load, fresh.shares()[i].load);
  }
  EXPECT_EQ(*varied->closed_form_energy(kPoint, 1e-5), *fresh.closed_form_energy(kPoint, 1e-5));
  EXPECT_NE(*varied->closed_form_energy(kPoint, 1e-5), *law.closed_form_energy(kPoint, 1e-5));
  EXPECT_EQ(law.with_parameter("beta", 0.5)->parameter("beta"), 0.5);
  EXPECT_EQ(law.parameter("chi"), -0.5);  // the law itself is unchanged
  EXPECT_THROW((void)law.with_parameter("chi", 0.1), std::invalid_argument);
  EXPECT_THROW((void)law.with_parameter("chi", -1.0), std::invalid_argument);
  EXPECT_THROW((void)law.with_parameter("beta", -0.1), std::invalid_argument);
  try {
    (void)law.parameter("gamma");
    ADD_FAILURE() << "no such parameter";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("chi, beta"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb::friction
