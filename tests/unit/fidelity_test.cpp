// The error estimates behind `run --fidelity auto`: Richardson extrapolation with a fitted order,
// and the pairing of two runs' result rows.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "pipeline/run_fidelity.hpp"

namespace bb {
namespace {

TEST(Fidelity, PowerLawErrorRecoversTheErrorOfAnAlgebraicSequence) {
  // e(x) = C x^-p on arithmetic levels (harmonics 3, 5, 7), where a geometric (Aitken) estimate errs.
  for (double p : {0.8, 1.3, 2.0, 4.0}) {
    const auto e = [&](double x) { return 0.05 * std::pow(x, -p); };
    const double estimate = power_law_error({3, 5, 7}, e(3) - e(5), e(5) - e(7));
    EXPECT_NEAR(estimate, e(5), 1e-8 * e(5)) << "p = " << p;
  }
  // Doubling levels (AFT samples): the same law.
  const auto e = [](double x) { return 3.0 / x; };
  EXPECT_NEAR(power_law_error({256, 512, 1024}, e(256) - e(512), e(512) - e(1024)), e(512), 1e-10);
}

TEST(Fidelity, PowerLawErrorIsInfiniteWhenTheDifferencesDoNotConverge) {
  EXPECT_TRUE(std::isinf(power_law_error({1, 2, 3}, 1e-3, 2e-3)));  // growing
  // Equal differences on doubling levels: slower than any power law allows.
  EXPECT_TRUE(std::isinf(power_law_error({1, 2, 4}, 1e-3, 1e-3)));
  EXPECT_TRUE(std::isinf(power_law_error({1, 2, 4}, 1e-3, std::nan(""))));
  EXPECT_EQ(power_law_error({1, 2, 4}, 1e-3, 0.0), 0.0);  // converged exactly
}

TEST(Fidelity, RelativeDifferencePairsRowsByKeyAndNamesAMissingColumn) {
  const ResultTable coarse = table_from_rows("frf_1", {"point", "amp"}, {{1, 1.00}, {2, 2.02}, {3, 5.0}});
  const ResultTable fine = table_from_rows("frf_1", {"point", "amp"}, {{2, 2.0}, {1, 1.0}});
  EXPECT_NEAR(relative_difference(coarse, fine, {"amp"}), 0.01, 1e-12);  // row 3 has no partner
  const ResultTable broken = table_from_rows("frf_1", {"point", "amp"}, {{1, std::nan("")}, {2, 2.0}});
  EXPECT_TRUE(std::isinf(relative_difference(broken, fine, {"amp"})));
  EXPECT_THROW(relative_difference(coarse, fine, {"phase"}), InputError);
  const ResultTable elsewhere = table_from_rows("frf_1", {"point", "amp"}, {{7, 1.0}});
  EXPECT_THROW(relative_difference(coarse, elsewhere, {"amp"}), InputError);
}

TEST(Fidelity, RelativeDifferencePairsSweepRowsByFrequencyNotByPointNumber) {
  // The finer sweep inserted a point at 201 Hz: its point numbers shift, its frequencies do not.
  const ResultTable coarse =
      table_from_rows("frf_1", {"point", "frequency_hz", "amp"}, {{1, 200, 1.0}, {2, 202, 2.0}, {3, 204, 3.0}});
  const ResultTable fine = table_from_rows("frf_1", {"point", "frequency_hz", "amp"},
                                           {{1, 200, 1.0}, {2, 201, 1.5}, {3, 202, 2.0}, {4, 204, 3.03}});
  EXPECT_NEAR(relative_difference(coarse, fine, {"amp"}, "frequency_hz"), 0.03 / 3.03, 1e-12);
  EXPECT_GT(relative_difference(coarse, fine, {"amp"}), 0.3);  // by point number: wrong partners
  EXPECT_THROW(relative_difference(coarse, fine, {"amp"}, "omega"), InputError);
}

}  // namespace
}  // namespace bb
