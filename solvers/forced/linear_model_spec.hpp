// The linear model of a forced-response case and its loads: forces and responses at points,
// damping (modal or Rayleigh), and a reduced model (Craig-Bampton on master points, a reduced-model
// file, or matrices written in the case). Shared by the linear (analysis/frf_spec.hpp) and the
// nonlinear (forced/hbm_spec.hpp) forced response.
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "linalg/modal_solver.hpp"
#include "model/model.hpp"
#include "reduction/reduced_model.hpp"

namespace bb {

struct PointDof {
  std::string point;
  Direction direction = 0;
  std::string name() const { return point + '.' + "xyz"[direction]; }
};

struct FrfForce {
  PointDof dof;
  double amplitude = 0.0;  // [N], harmonic, zero phase
};

struct FrfDamping {
  enum class Kind { modal, rayleigh } kind = Kind::modal;
  double zeta = 0.0;  // modal: the same ratio for every mode
  // modal, when not empty: the ratios of the lowest modes in ascending frequency, as a modal test
  // gives them; the modes above the last take its ratio.
  std::vector<double> mode_zetas;
  std::array<double, 2> rayleigh_hz{};  // rayleigh: zeta fitted at two frequencies (eqs 3.37-3.39)
  std::array<double, 2> rayleigh_zeta{};

  // modal: the ratios of `modes` modes in ascending frequency.
  Eigen::VectorXd modal_ratios(Eigen::Index modes) const {
    if (mode_zetas.empty()) return Eigen::VectorXd::Constant(modes, zeta);
    Eigen::VectorXd z(modes);
    for (Eigen::Index i = 0; i < modes; ++i) z[i] = mode_zetas[std::min(static_cast<size_t>(i), mode_zetas.size() - 1)];
    return z;
  }
};

// A reduced model: Craig-Bampton on master points, matrices from files, or matrices in the case.
struct RomSpec {
  std::string name;                                // names its columns and tables, e.g. "rom"
  std::vector<std::string> masters;                // point names, all three directions of each, in this order
  int modes = 10;                                  // fixed-interface modes
  double modes_below_hz = 0.0;                     // > 0: instead, every fixed-interface mode below this [Hz]
  Eigensolver eigensolver = Eigensolver::spectra;  // of the fixed-interface modes and constraint modes
  std::filesystem::path file;                      // a reduced-model sidecar (reduction/reduced_model_io.hpp) instead
  std::optional<ReducedModel> matrices;            // or matrices written in the case (a lumped model)
  enum class Method { direct, modal } method = Method::direct;
  std::vector<FrfForce> forces;     // empty: the analysis's
  std::vector<PointDof> responses;  // empty: the analysis's
};

}  // namespace bb
