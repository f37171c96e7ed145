// Plane-stress benchmarks: element matrices, global assembly and the linear static solve of a
// clamped cantilever up to about one million DOFs. SI units throughout.
//
// Measurement only: nothing here asserts a time. Counters:
//   dofs          number of equations (all nodal DOFs for assembly, free DOFs for the solve)
//   nnz           stored nonzeros of the assembled matrix (both triangles)
//   assembly_s    StaticSolution::assembly_seconds (DOF numbering, assembly, loads, partition)
//   solve_s       StaticSolution::solve_seconds (CHOLMOD analysis + factorization + solve)
//   peak_rss_MiB  getrusage(RUSAGE_SELF).ru_maxrss: the high-water mark of the whole process so
//                 far, so it is the true peak of one case only when that case runs alone
//                 (bench/README.md shows how).
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/static_analysis.hpp"
#include "assembly/assemble.hpp"
#include "assembly/dof_map.hpp"
#include "common/seconds_since.hpp"
#include "fe/plane_stress.hpp"
#include "linalg/spd_factor.hpp"
#include "mesh/mapped_quad.hpp"
#include "model/model.hpp"

namespace {

// ru_maxrss is in KiB on Linux.
double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// Resident set size right now (second field of /proc/self/statm, in pages).
double current_rss_mib() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0.0;
  long total = 0, resident = 0;
  const int read = std::fscanf(f, "%ld %ld", &total, &resident);
  std::fclose(f);
  if (read != 2) return 0.0;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Steel plate, 10 mm thick.
bb::fe::PlaneSection steel() {
  return {.youngs_modulus = 200e9, .poisson_ratio = 0.3, .density = 7850.0, .thickness = 0.01};
}

bb::ElementType element_of(const benchmark::State& state) {
  return state.range(2) == 0 ? bb::ElementType::q4 : bb::ElementType::cst;
}

// A 2 m x 1 m cantilever (2:1 aspect), nx x ny cells, Q4 or CST (two triangles per cell).
bb::Mesh cantilever_mesh(int nx, int ny, bb::ElementType element) {
  bb::MappedQuadSpec spec;
  spec.corners = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(2.0, 0.0), Eigen::Vector2d(2.0, 1.0),
                  Eigen::Vector2d(0.0, 1.0)};
  spec.nx = nx;
  spec.ny = ny;
  spec.element = element;
  spec.diagonal = bb::TriangleDiagonal::alternating;
  return bb::generate_mapped_quad(spec);
}

// The cantilever clamped at x = 0 with a 1 kN downward tip shear at x = 2 m, split as a uniform
// edge traction. generate_mapped_quad numbers nodes row by row: node j * (nx + 1) + i.
bb::Model cantilever_model(int nx, int ny, bb::ElementType element) {
  bb::Model model;
  model.mesh = cantilever_mesh(nx, ny, element);
  model.section = steel();
  std::vector<int> root, tip;
  for (int j = 0; j <= ny; ++j) {
    root.push_back(j * (nx + 1));
    tip.push_back(j * (nx + 1) + nx);
  }
  model.node_sets["root"] = root;
  model.node_sets["tip"] = tip;
  model.constraints.push_back({.set = "root", .directions = {0, 1}, .value = 0.0});
  model.loads.push_back({.set = "tip", .direction = 1, .total = -1000.0, .split = bb::LoadSplit::consistent_edge});
  return model;
}

// ---------------------------------------------------------------------------------------------
// (1) Element matrices. A mildly distorted quadrilateral so that 2x2 Gauss does real work.

const bb::fe::Q4Coords& sample_quad() {
  static const bb::fe::Q4Coords xy = (bb::fe::Q4Coords() << 0.0, 0.0, 1.1, 0.05, 1.0, 0.9, -0.05, 1.0).finished();
  return xy;
}

const bb::fe::CstCoords& sample_triangle() {
  static const bb::fe::CstCoords xy = (bb::fe::CstCoords() << 0.0, 0.0, 1.1, 0.05, 0.1, 0.9).finished();
  return xy;
}

template <typename Fn, typename Coords>
void run_element(benchmark::State& state, Fn fn, const Coords& xy) {
  const bb::fe::PlaneSection section = steel();
  for (auto _ : state) {
    auto ke = fn(xy, section);
    benchmark::DoNotOptimize(ke.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Q4Stiffness(benchmark::State& state) { run_element(state, bb::fe::q4_stiffness, sample_quad()); }
void BM_Q4ConsistentMass(benchmark::State& state) { run_element(state, bb::fe::q4_consistent_mass, sample_quad()); }
void BM_CstStiffness(benchmark::State& state) { run_element(state, bb::fe::cst_stiffness, sample_triangle()); }
void BM_CstConsistentMass(benchmark::State& state) {
  run_element(state, bb::fe::cst_consistent_mass, sample_triangle());
}

BENCHMARK(BM_Q4Stiffness);
BENCHMARK(BM_Q4ConsistentMass);
BENCHMARK(BM_CstStiffness);
BENCHMARK(BM_CstConsistentMass);

// ---------------------------------------------------------------------------------------------
// (2) Global stiffness assembly (bb::assemble, stiffness only). Args: nx, ny, element (0 = Q4,
// 1 = CST). 2 (nx + 1)(ny + 1) nodal DOFs: ny = 16, 50, 158, 500 give about 1e3 .. 1e6.

void BM_AssembleStiffness(benchmark::State& state) {
  const int nx = static_cast<int>(state.range(0)), ny = static_cast<int>(state.range(1));
  const bb::Mesh mesh = cantilever_mesh(nx, ny, element_of(state));
  const bb::fe::PlaneSection section = steel();
  Eigen::Index nnz = 0;
  for (auto _ : state) {
    const bb::GlobalMatrices g = bb::assemble(mesh, section, {.stiffness = true, .mass = false});
    nnz = g.stiffness.nonZeros();
    benchmark::DoNotOptimize(g.stiffness.valuePtr());
  }
  state.counters["dofs"] = static_cast<double>(mesh.n_nodes() * mesh.dim);
  state.counters["nnz"] = static_cast<double>(nnz);
  state.counters["peak_rss_MiB"] = peak_rss_mib();
  state.SetItemsProcessed(state.iterations() * mesh.n_elements());
}

BENCHMARK(BM_AssembleStiffness)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({32, 16, 0})
    ->Args({100, 50, 0})
    ->Args({316, 158, 0})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AssembleStiffness)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({1000, 500, 0})
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------------
// (3) Static solve (bb::solve_static) of the clamped cantilever. Args: nx, ny, element.
// Free DOFs = 2 nx (ny + 1): ny = 16, 50, 158, 500 give 1 088, 10 200, 100 488, 1 002 000.

void BM_StaticSolve(benchmark::State& state) {
  const int nx = static_cast<int>(state.range(0)), ny = static_cast<int>(state.range(1));
  const bb::Model model = cantilever_model(nx, ny, element_of(state));
  double assembly = 0.0, solve = 0.0, residual = 0.0;
  int free_dofs = 0;
  for (auto _ : state) {
    const bb::StaticSolution sol = bb::solve_static(model);
    assembly += sol.assembly_seconds;
    solve += sol.solve_seconds;
    residual = sol.relative_residual;
    free_dofs = sol.n_free_dofs;
    benchmark::DoNotOptimize(sol.displacements.data());
  }
  state.counters["dofs"] = free_dofs;
  state.counters["assembly_s"] = benchmark::Counter(assembly, benchmark::Counter::kAvgIterations);
  state.counters["solve_s"] = benchmark::Counter(solve, benchmark::Counter::kAvgIterations);
  state.counters["rel_residual"] = residual;
  state.counters["peak_rss_MiB"] = peak_rss_mib();
}

BENCHMARK(BM_StaticSolve)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({32, 16, 0})
    ->Args({100, 50, 0})
    ->Args({32, 16, 1})
    ->Args({100, 50, 1})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StaticSolve)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({316, 158, 0})
    ->Args({316, 158, 1})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StaticSolve)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({1000, 500, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------------
// (4) Where the static solve spends its time and memory: the steps of bb::solve_static done one
// by one through the public API, with the time of each (t_*, seconds) and the resident set
// right after it (rss_*_MiB, everything earlier still alive, as inside solve_static).

void BM_StaticSolvePhases(benchmark::State& state) {
  const int nx = static_cast<int>(state.range(0)), ny = static_cast<int>(state.range(1));
  const bb::Model model = cantilever_model(nx, ny, element_of(state));
  const double rss_model = current_rss_mib();
  double t_dofs = 0, t_assemble = 0, t_loads = 0, t_partition = 0, t_factorize = 0, t_solve = 0;
  double rss_assemble = 0, rss_partition = 0, rss_factorize = 0;
  double nnz_full = 0, nnz_ff = 0;
  for (auto _ : state) {
    auto t0 = std::chrono::steady_clock::now();
    const bb::DofMap dofs = bb::number_dofs(model);
    t_dofs += bb::seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    const bb::GlobalMatrices global = bb::assemble(model.mesh, model.section, {.stiffness = true, .mass = false});
    t_assemble += bb::seconds_since(t0);
    rss_assemble = current_rss_mib();

    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd f = bb::load_vector(model);
    t_loads += bb::seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    const bb::Partitioned k = bb::partition(global.stiffness, dofs);
    t_partition += bb::seconds_since(t0);
    rss_partition = current_rss_mib();

    Eigen::VectorXd rhs(dofs.n_free);
    for (int i = 0; i < dofs.n_free; ++i) rhs[i] = f[dofs.free_dofs[i]];

    t0 = std::chrono::steady_clock::now();
    bb::SpdFactorization factor;
    const bb::FactorStatus status = factor.factorize(k.ff);
    t_factorize += bb::seconds_since(t0);
    rss_factorize = current_rss_mib();
    if (!status.ok) {
      state.SkipWithError(status.message.c_str());
      break;
    }

    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd u = factor.solve(rhs);
    t_solve += bb::seconds_since(t0);
    benchmark::DoNotOptimize(u.data());
    nnz_full = static_cast<double>(global.stiffness.nonZeros());
    nnz_ff = static_cast<double>(k.ff.nonZeros());
  }
  const auto avg = [](double v) { return benchmark::Counter(v, benchmark::Counter::kAvgIterations); };
  state.counters["t_dofs"] = avg(t_dofs);
  state.counters["t_assemble"] = avg(t_assemble);
  state.counters["t_loads"] = avg(t_loads);
  state.counters["t_partition"] = avg(t_partition);
  state.counters["t_factorize"] = avg(t_factorize);
  state.counters["t_solve"] = avg(t_solve);
  state.counters["nnz_K"] = nnz_full;
  state.counters["nnz_Kff"] = nnz_ff;
  state.counters["rss_model_MiB"] = rss_model;
  state.counters["rss_assembled_MiB"] = rss_assemble;
  state.counters["rss_partitioned_MiB"] = rss_partition;
  state.counters["rss_factorized_MiB"] = rss_factorize;
  state.counters["peak_rss_MiB"] = peak_rss_mib();
}

BENCHMARK(BM_StaticSolvePhases)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({316, 158, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StaticSolvePhases)
    ->ArgNames({"nx", "ny", "cst"})
    ->Args({1000, 500, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
