// The frf analysis on a small plane-stress cantilever (steel, 1.0 x 0.1 m, 24 x 4 Q4, clamped at
// x = 0): the full mesh by modal superposition against a dense direct solve, Craig-Bampton models
// against the full mesh, reciprocity, and a reduced model written and read back.
#include "analysis/frf_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "analysis/modal_analysis.hpp"
#include "cases/case_spec.hpp"
#include "frf/receptance.hpp"
#include "model/build_model.hpp"
#include "reduction/reduced_model_io.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

constexpr const char* kCase = R"(
[case]
name = "frf_cantilever"
[material]
E = 2.1e11
nu = 0.3
rho = 7800.0
[section]
thickness = 0.01
[mesh]
kind = "mapped_quad"
element = "q4"
corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.1], [0.0, 0.1]]
nx = 24
ny = 4
[sets.clamp]
x = 0.0
[sets.tip]
x = 1.0
y = 0.0
[sets.mid]
x = 0.5
y = 0.1
[[bc]]
set = "clamp"
dofs = ["x", "y"]
[analysis]
type = "frf"
frequency_hz = [5.0, 400.0]
step_hz = 5.0
)";

class FrfAnalysis : public test::TempFolderTest {
 protected:
  CaseSpec parse(const std::string& analysis) { return parse_case_file(write(std::string(kCase) + analysis)); }
};

// Dense direct reference: (K + i w C - w^2 M) x = f with Rayleigh C, at the free DOFs.
std::complex<double> dense_direct(const FreeSystem& s, const RayleighCoefficients& c, double f_hz, int out, int in) {
  const Eigen::MatrixXd k(s.stiffness), m(s.mass);
  const Eigen::MatrixXd damping = c.alpha * m + c.beta * k;
  Eigen::VectorXcd force = Eigen::VectorXcd::Zero(k.rows());
  force[in] = 1.0;
  return direct_response(k, damping, m, 2 * std::numbers::pi * f_hz, force)[out];
}

int free_dof(const Model& model, const FreeSystem& s, const std::string& set, int direction) {
  return s.dofs.equation[static_cast<size_t>(model.node_sets.at(set).front() * 2 + direction)];
}

TEST_F(FrfAnalysis, FullMeshSuperpositionWithResidualMatchesTheDenseDirectSolve) {
  // Rayleigh damping is proportional, so eq 3.32 with zeta_r = alpha / 2 w_r + beta w_r / 2 over
  // every mode is exact; over 8 modes the residual flexibility stands in for the rest.
  const std::string analysis = R"(
rayleigh = { frequency_hz = [20.0, 300.0], zeta = [0.02, 0.02] }
full_modes = 8
forces = [{ dof = "tip.y", amplitude = 1.0 }]
responses = ["mid.y", "tip.y"]
)";
  const CaseSpec with = parse(analysis + "residual_flexibility = true\n");
  const CaseSpec without = parse(analysis + "residual_flexibility = false\n");
  const Model model = build_model(with.model);
  const FreeSystem s = assemble_free_system(model);
  const auto full = prepare_frf(model, std::get<FrfSpec>(with.analysis));
  const auto truncated = prepare_frf(model, std::get<FrfSpec>(without.analysis));
  const RayleighCoefficients c = fit_rayleigh(2 * std::numbers::pi * 20.0, 0.02, 2 * std::numbers::pi * 300.0, 0.02);
  for (double f : {5.0, 40.0, 150.0, 390.0}) {
    const auto exact = dense_direct(s, c, f, free_dof(model, s, "mid", 1), free_dof(model, s, "tip", 1));
    const double e_with = std::abs(frf_respond(*full, 0, f)[0] / exact - 1.0);
    const double e_without = std::abs(frf_respond(*truncated, 0, f)[0] / exact - 1.0);
    EXPECT_LT(e_with, 2e-3) << f << " Hz";
    EXPECT_LT(e_with, 0.2 * e_without) << f << " Hz: the residual must help";
  }
}

TEST_F(FrfAnalysis, CraigBamptonConvergesToTheFullMeshAsModesAreAdded) {
  const CaseSpec spec = parse(R"(
modal_damping = 0.01
full_modes = 12
forces = [{ dof = "tip.y", amplitude = 1.0 }]
responses = ["tip.y"]
[[analysis.rom]]
name = "m2"
masters = ["tip", "mid"]
modes = 2
[[analysis.rom]]
name = "m6"
masters = ["tip", "mid"]
modes = 6
[[analysis.rom]]
name = "m20"
masters = ["tip", "mid"]
modes = 20
)");
  const Model model = build_model(spec.model);
  const FrfOutcome o = run_frf(model, std::get<FrfSpec>(spec.analysis));
  const Eigen::VectorXd& full = o.full_modal->frequencies_hz;
  double previous = INFINITY;
  for (const RomOutcome& rom : o.roms) {
    double worst = 0.0;
    for (Eigen::Index k = 0; k < 4; ++k) {
      EXPECT_GE(rom.frequencies_hz[k], full[k] * (1 - 1e-9))
          << rom.name << " mode " << k + 1 << ": CB bounds from above";
      worst = std::max(worst, rom.frequencies_hz[k] / full[k] - 1.0);
    }
    EXPECT_LT(worst, previous) << rom.name;
    previous = worst;
  }
  EXPECT_LT(previous, 1e-4);  // 20 modes: 1.1e-5 measured
  // The first resonance peak of every reduced model against the full mesh's.
  const double f_full = o.tables.at("peaks_full").values(0, 1);
  EXPECT_NEAR(o.tables.at("peaks_m20").values(0, 1) / f_full, 1.0, 1e-5);
}

TEST_F(FrfAnalysis, TransferReceptancesAreReciprocalOnFullAndReducedModels) {
  const std::string rom = R"(
[[analysis.rom]]
name = "rom"
masters = ["tip", "mid"]
modes = 4
method = "direct"
)";
  const CaseSpec ab = parse(
      "modal_damping = 0.02\nfull_modes = 6\nforces = [{ dof = \"tip.y\", amplitude = 1.0 }]\nresponses = "
      "[\"mid.x\"]\n" +
      rom);
  const CaseSpec ba = parse(
      "modal_damping = 0.02\nfull_modes = 6\nforces = [{ dof = \"mid.x\", amplitude = 1.0 }]\nresponses = "
      "[\"tip.y\"]\n" +
      rom);
  const Model model = build_model(ab.model);
  const auto p_ab = prepare_frf(model, std::get<FrfSpec>(ab.analysis));
  const auto p_ba = prepare_frf(model, std::get<FrfSpec>(ba.analysis));
  for (size_t curve : {0u, 1u})
    for (double f : {10.0, 85.0, 333.0}) {
      const std::complex<double> h_ab = frf_respond(*p_ab, curve, f)[0], h_ba = frf_respond(*p_ba, curve, f)[0];
      EXPECT_LT(std::abs(h_ab - h_ba), 1e-9 * std::abs(h_ab)) << "curve " << curve << " at " << f << " Hz";
    }
}

TEST_F(FrfAnalysis, ReducedModelWrittenAndReadBackRespondsIdentically) {
  const std::string analysis = R"(
modal_damping = 0.01
full_model = false
forces = [{ dof = "tip.y", amplitude = 3.0 }]
responses = ["tip.y", "mid.x"]
[[analysis.rom]]
name = "rom"
method = "direct"
)";
  const CaseSpec built = parse(analysis + "masters = [\"tip\", \"mid\"]\nmodes = 5\n");
  const Model model = build_model(built.model);
  const FrfOutcome first = run_frf(model, std::get<FrfSpec>(built.analysis));
  write_reduced_model(first.roms.front().model, dir_ / "rom.toml");
  const CaseSpec read = parse(analysis + "file = \"rom.toml\"\n");
  const FrfOutcome second = run_frf(model, std::get<FrfSpec>(read.analysis));
  ASSERT_EQ(first.sweep.response.rows(), second.sweep.response.rows());
  EXPECT_EQ((first.sweep.response - second.sweep.response).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace bb
