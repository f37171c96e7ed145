// The friction laws through their one interface (friction/friction_law.hpp): one AFT evaluation
// with its Jacobian of the Jenkins law (the interface's call against friction::aft_jenkins itself:
// the price of the indirection) and of the 2D contact with coupled slip, on the stick-slip motion of
// bench_hbm.cpp's BM_AftJenkins (u of 1e-5 m, three times the slip distance, under a varying normal
// load that never opens), the coupled law driven along an ellipse (the same u along x, half of it a
// quarter period later along y). Measurement only: nothing here asserts a time.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "friction/coupled_slip.hpp"

namespace {

const bb::friction::PointParameters kPoint{.kn = 1e6, .kt = 1e6, .mu = 0.3, .n0 = 10.0};

struct Motion {
  Eigen::VectorXd u, v;  // u: one direction's coefficients, v: the normal's
};

Motion stick_slip(int harmonics) {
  const Eigen::Index m = bb::friction::harmonic_size(harmonics);
  Motion s{Eigen::VectorXd::Zero(m), Eigen::VectorXd::Zero(m)};
  s.u[1] = 1e-5;
  s.v[0] = 2e-5;
  s.v[2] = 5e-6;
  for (int h = 2; h <= harmonics; ++h) s.u[2 * h - 1] = 1e-6 / h, s.v[2 * h] = 5e-7 / h;
  return s;
}

bb::friction::AftOptions options_for(Eigen::Index m) { return {.samples = std::max(64, 16 * static_cast<int>(m))}; }

void BM_LawJenkinsAft(benchmark::State& state) {
  const Motion s = stick_slip(static_cast<int>(state.range(0)));
  const bb::friction::AftOptions options = options_for(s.u.size());
  const bb::friction::FrictionLaw& law = *bb::friction::jenkins_law();
  for (auto _ : state) benchmark::DoNotOptimize(law.harmonics(kPoint, s.u, s.v, options));
}
BENCHMARK(BM_LawJenkinsAft)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMicrosecond);

void BM_LawCoupledSlipAft(benchmark::State& state) {
  const Motion s = stick_slip(static_cast<int>(state.range(0)));
  const Eigen::Index m = s.u.size();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * m);
  u.head(m) = s.u;
  u[m + 2] = 0.5 * s.u[1];  // y: half the x amplitude, a quarter period later
  const bb::friction::AftOptions options = options_for(m);
  const bb::friction::FrictionLaw& law = *bb::friction::coupled_slip_law();
  for (auto _ : state) benchmark::DoNotOptimize(law.harmonics(kPoint, u, s.v, options));
}
BENCHMARK(BM_LawCoupledSlipAft)->ArgName("H")->Arg(1)->Arg(5)->Unit(benchmark::kMicrosecond);

}  // namespace
