// One Newton iteration of Table XI's condensed harmonic balance against its dense-algebra bound
// (issue 31, point 2). The system: cases/thesis/table11_calibrate_contact.toml (the committed
// 28-DOF reduced blades, the rigid damper, three Jenkins contacts on 9 contact DOFs) with kt and mu
// as identified until 2026-11-28 (8.09e7 N/m, 0.7231), the event-resolved AFT at its automatic samples, H = 3 or 7,
// at the 100 N level near its OOP peak (176.5 Hz), where the contacts stick, slip and the normal
// loads vary. Run from the repository root.
//
// What one iteration of damped_newton costs, in its parts:
//   BM_TableXIIteration       the residual with its Jacobian (3 AFTs, the contact Jacobian's
//                             assembly, L x) and the Newton step
//   BM_TableXIContactForces   the contact forces with their Jacobian alone
//   BM_TableXIStepSolve       the Newton step alone: LU of J, its condition estimate, the solve
//                             (damped_newton's step where J is well conditioned: bb::DenseLU)
//   BM_DenseRate              a dense product of the same size by Eigen (as compiled here)
//   BM_DenseRateBlas          the same product by the BLAS (OpenBLAS, dispatched to this CPU): the
//                             machine's achievable flop rate, which `bound_us` uses
// Counters: `unknowns` n = 9 (2H + 1); `flops` of the iteration's dense algebra, counted: the LU
// (2/3 n^3) and its solve (2 n^2), the contact Jacobian's products (per contact 2 m^2 s^2 with s
// the contact DOFs it moves, m = 2H + 1) and the AFT's closed-form integrals (per contact and state
// run 6 m^2, the motion at every sample 14 m, two periods); `bound_us` = flops at BM_DenseRateBlas's
// rate (the iteration's time over bound_us is the ratio issue 31 asks within 3). Measurement only:
// nothing here asserts a time.
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "analysis/analysis_spec.hpp"
#include "cases/case_spec.hpp"
#include "forced/hbm_level.hpp"
#include "forced/hbm_level_system.hpp"
#include "hbm/harmonic_balance.hpp"
#include "linalg/blas_threads.hpp"
#include "linalg/dense_lu.hpp"
#include "model/build_model.hpp"

extern "C" void dgemm_(const char* ta, const char* tb, const int* m, const int* n, const int* k, const double* alpha,
                       const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
                       const int* ldc);

namespace {

using Eigen::Index;

constexpr double kForce = 100.0;        // [N]
constexpr double kFrequencyHz = 176.5;  // near the 100 N level's OOP peak

struct TableXI {
  bb::PreparedHbm prepared;
  bb::HbmSpec spec;
};

const TableXI& table_xi() {
  static const TableXI t = [] {
    const std::filesystem::path file = "cases/thesis/table11_calibrate_contact.toml";
    toml::table root = bb::read_case_table(file);
    toml::table& analysis = *root["analysis"].as_table();
    analysis.insert_or_assign("aft", "events");
    analysis.erase("time_samples");
    toml::table& damper = *analysis["damper"].as_table();
    damper.insert_or_assign("kt", 8.09e7);
    damper.insert_or_assign("mu", 0.7231);
    const bb::CaseSpec c = bb::parse_case_table(root, file);
    TableXI out;
    out.spec = std::get<bb::HbmSpec>(c.analysis);
    out.prepared = bb::prepare_hbm(bb::build_model(c.model), out.spec);
    return out;
  }();
  return t;
}

// The system at H and a converged solution at the benchmark's frequency: the level swept over
// the band as a case sweeps it, then solved at the frequency from the nearest point of its path
// (so that it lies on the branch the sweep follows).
struct Point {
  bb::hbm::HarmonicBalance system;
  bb::hbm::HarmonicBalance::Linear linear;
  Eigen::VectorXd x;
};

Point converged_point(int harmonics) {
  const TableXI& t = table_xi();
  bb::hbm::HarmonicBalance system = bb::level_system(t.prepared, t.spec, kForce, harmonics, 0);
  const double omega = 2 * std::numbers::pi * kFrequencyHz;
  const bb::HbmLevel level = bb::sweep_hbm_level(t.prepared, t.spec, kForce, harmonics);
  const bb::hbm::HbmSolution s = bb::hbm::solve_at_frequency(system, omega, bb::nearest_point(level.path, omega).x);
  if (!s.converged) throw std::runtime_error("Table XI at 100 N did not converge at the benchmark's frequency");
  auto linear = system.condense(omega);
  if (!linear) throw std::runtime_error("singular condensation");
  return {std::move(system), std::move(*linear), s.x};
}

// Counted flops of one iteration (see the header).
double iteration_flops(const bb::hbm::HarmonicBalance& s) {
  const double n = static_cast<double>(s.unknowns());
  const double m = 2.0 * s.options().harmonics + 1.0;
  const double samples = s.aft_options().samples;
  double flops = 2.0 / 3.0 * n * n * n + 2.0 * n * n + 2.0 * n * n;  // LU, solve, L x
  for (const bb::friction::ContactElement& e : s.model().contacts) {
    double support = 0.0;
    for (Index i = 0; i < e.tangential.size(); ++i) support += e.tangential[i] != 0.0 || e.normal[i] != 0.0;
    flops += 2.0 * m * m * support * support;  // the contact Jacobian's assembly
    flops += 2.0 * samples * 14.0 * m;         // the motion at the samples, two periods
    flops += 4.0 * 6.0 * m * m;                // integrals over about four state runs
  }
  return flops;
}

// C = A B by the BLAS.
void blas_product(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, Eigen::MatrixXd& c) {
  bb::use_one_thread_per_factorization();  // one core, as the sweeps run
  const int n = static_cast<int>(a.rows());
  const double one = 1.0, zero = 0.0;
  dgemm_("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
}

// The rate of the BLAS's dense product of the iteration's size [flop/s], one per process.
double dense_rate(Index n) {
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n), b = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd c(n, n);
  int reps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < 0.2) {
    blas_product(a, b, c);
    benchmark::DoNotOptimize(c.data());
    ++reps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return 2.0 * static_cast<double>(n * n * n) * reps / elapsed;
}

void report(benchmark::State& state, const bb::hbm::HarmonicBalance& s) {
  const double flops = iteration_flops(s);
  const double bound = flops / dense_rate(s.unknowns());
  state.counters["unknowns"] = static_cast<double>(s.unknowns());
  state.counters["samples"] = s.aft_options().samples;
  state.counters["flops"] = flops;
  state.counters["bound_us"] = 1e6 * bound;
}

// damped_newton's step where J is well conditioned: partial-pivot LU, its condition estimate, solve.
void newton_step(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residual) {
  const bb::DenseLU lu(jacobian);
  benchmark::DoNotOptimize(lu.rcond());
  Eigen::VectorXd step = lu.solve(-residual);
  benchmark::DoNotOptimize(step.data());
}

void BM_TableXIIteration(benchmark::State& state) {
  const Point p = converged_point(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const bb::hbm::HarmonicBalance::Residual r = p.system.residual(p.linear, p.x);
    newton_step(p.linear.operator_ + r.forces.jacobian, r.residual);
  }
  report(state, p.system);
}
BENCHMARK(BM_TableXIIteration)->ArgName("H")->Arg(3)->Arg(7)->Arg(13)->Unit(benchmark::kMicrosecond);

void BM_TableXIContactForces(benchmark::State& state) {
  const Point p = converged_point(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(p.system.contact_forces(p.x));
}
BENCHMARK(BM_TableXIContactForces)->ArgName("H")->Arg(3)->Arg(7)->Arg(13)->Unit(benchmark::kMicrosecond);

void BM_TableXIStepSolve(benchmark::State& state) {
  const Point p = converged_point(static_cast<int>(state.range(0)));
  const bb::hbm::HarmonicBalance::Residual r = p.system.residual(p.linear, p.x);
  const Eigen::MatrixXd jacobian = p.linear.operator_ + r.forces.jacobian;
  for (auto _ : state) newton_step(jacobian, r.residual);
}
BENCHMARK(BM_TableXIStepSolve)->ArgName("H")->Arg(3)->Arg(7)->Arg(13)->Unit(benchmark::kMicrosecond);

void BM_DenseRate(benchmark::State& state) {
  const Index n = state.range(0);
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n), b = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd c(n, n);
  for (auto _ : state) {
    c.noalias() = a * b;
    benchmark::DoNotOptimize(c.data());
  }
  state.counters["flop_rate"] =
      benchmark::Counter(2.0 * static_cast<double>(n * n * n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DenseRate)->ArgName("n")->Arg(63)->Arg(135)->Arg(243)->Unit(benchmark::kMicrosecond);

void BM_DenseRateBlas(benchmark::State& state) {
  const Index n = state.range(0);
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n), b = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd c(n, n);
  for (auto _ : state) {
    blas_product(a, b, c);
    benchmark::DoNotOptimize(c.data());
  }
  state.counters["flop_rate"] =
      benchmark::Counter(2.0 * static_cast<double>(n * n * n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DenseRateBlas)->ArgName("n")->Arg(63)->Arg(135)->Arg(243)->Unit(benchmark::kMicrosecond);

}  // namespace
