// Stress recovery (assembly/stress_recovery) on the Table VI article (cases/thesis/table06_glued_modal
// model: 6144 hex20, 31 301 nodes, 88 548 free DOFs): Gauss-point stresses of every element,
// extrapolation to its 20 nodes, nodal averages, the elements' scatter, and the nodal_stresses
// table (invariants, principal stresses). The displacement field is a smooth made-up one (bending
// plus twist plus stretch): the cost does not depend on the values. Run from the repository root,
// since the case is read from cases/.
//
// Measurement only: nothing here asserts a time. Counters: elements, nodes.
#include <benchmark/benchmark.h>

#include <cmath>

#include "analysis/stress_tables.hpp"
#include "assembly/stress_recovery.hpp"
#include "cases/case_spec.hpp"
#include "model/build_model.hpp"

namespace {

struct StressScene {
  bb::Model model;
  Eigen::MatrixXd displacements;
};

const StressScene& stress_scene() {
  static const StressScene s = [] {
    StressScene out;
    out.model = bb::build_model(bb::parse_case_file("cases/thesis/table06_glued_modal.toml").model);
    const Eigen::MatrixXd& x = out.model.mesh.coords;
    out.displacements.resize(x.rows(), 3);
    for (Eigen::Index n = 0; n < x.rows(); ++n)
      out.displacements.row(n) << 1e-4 * std::sin(20 * x(n, 1)) + 1e-5 * x(n, 2), 2e-5 * x(n, 0) * x(n, 1),
          3e-4 * x(n, 1) * x(n, 1) - 1e-4 * x(n, 0) * x(n, 1);
    return out;
  }();
  return s;
}

void BM_StressRecoveryTableVI(benchmark::State& state) {
  const StressScene& s = stress_scene();
  for (auto _ : state) benchmark::DoNotOptimize(bb::recover_stresses(s.model.mesh, s.model.section, s.displacements));
  state.counters["elements"] = s.model.mesh.n_elements();
  state.counters["nodes"] = s.model.mesh.n_nodes();
}

// What a static run adds after the solve: the recovery plus the nodal_stresses and nodal_strains tables.
void BM_StressRecoveryAndTablesTableVI(benchmark::State& state) {
  const StressScene& s = stress_scene();
  for (auto _ : state) {
    const bb::StressField f = bb::recover_stresses(s.model.mesh, s.model.section, s.displacements);
    benchmark::DoNotOptimize(bb::nodal_stress_table("nodal_stresses", s.model.mesh, f));
    benchmark::DoNotOptimize(bb::nodal_strain_table("nodal_strains", s.model.mesh, f, s.model.section));
  }
  state.counters["elements"] = s.model.mesh.n_elements();
}

BENCHMARK(BM_StressRecoveryTableVI)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StressRecoveryAndTablesTableVI)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
