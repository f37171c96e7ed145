// Linear forced-response sweeps of the Tables VII-VIII scene (cases/thesis/table08_linear_frf.toml):
// 2001 frequencies, 170-190 Hz, on the full mesh (modal superposition of 24 modes + residual
// flexibility) and on the 28-DOF Craig-Bampton model (direct solve of D(w), or its own modes).
// The models are prepared once (about a minute: modes, residual, reduction); the benchmarks time
// the sweeps only. Run from the repository root, since the case is read from cases/.
//
// Measurement only: nothing here asserts a time. Counters:
//   frequencies   points in the sweep (time per frequency = Time / frequencies)
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>

#include "analysis/frf_analysis.hpp"
#include "cases/case_spec.hpp"
#include "frf/sweep.hpp"
#include "model/build_model.hpp"

namespace {

struct Scene {
  bb::CaseSpec spec;
  bb::Model model;
  std::shared_ptr<const bb::PreparedFrf> prepared;
  std::vector<double> grid;
};

// The case's models plus the same reduction answered by its own modes instead of D(w).
const Scene& scene() {
  static const Scene s = [] {
    Scene out;
    out.spec = bb::parse_case_file("cases/thesis/table08_linear_frf.toml");
    bb::RomSpec modal = std::get<bb::FrfSpec>(out.spec.analysis).roms.front();
    modal.name = "rom_modal";
    modal.method = bb::RomSpec::Method::modal;
    std::get<bb::FrfSpec>(out.spec.analysis).roms.push_back(modal);
    out.model = bb::build_model(out.spec.model);
    std::fprintf(stderr, "preparing the Table VIII models (modes, residual flexibility, two reductions)...\n");
    out.prepared = bb::prepare_frf(out.model, std::get<bb::FrfSpec>(out.spec.analysis));
    const bb::FrfSpec& f = std::get<bb::FrfSpec>(out.spec.analysis);
    out.grid = bb::fixed_grid(f.f_min, f.f_max, f.step);
    return out;
  }();
  return s;
}

void sweep_model(benchmark::State& state, size_t curve) {
  const Scene& s = scene();
  for (auto _ : state) {
    for (double f : s.grid) benchmark::DoNotOptimize(bb::frf_respond(*s.prepared, curve, f));
  }
  state.counters["frequencies"] = static_cast<double>(s.grid.size());
  state.SetLabel(bb::frf_curves(*s.prepared).at(curve).model);
}

void BM_FrfSweepFullMesh(benchmark::State& state) { sweep_model(state, 0); }
void BM_FrfSweepRomDirect(benchmark::State& state) { sweep_model(state, 1); }
void BM_FrfSweepRomModal(benchmark::State& state) { sweep_model(state, 2); }

BENCHMARK(BM_FrfSweepFullMesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrfSweepRomDirect)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrfSweepRomModal)->Unit(benchmark::kMillisecond);

}  // namespace
