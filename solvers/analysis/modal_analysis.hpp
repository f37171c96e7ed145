// Modal analysis: lowest natural frequencies and mass-normalized shapes of the constrained model.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <vector>

#include "analysis/modal_spec.hpp"
#include "assembly/dof_map.hpp"
#include "assembly/free_system.hpp"
#include "assembly/stress_recovery.hpp"
#include "linalg/cached_modes.hpp"
#include "linalg/modal_solver.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

struct ModalResult {
  Eigen::VectorXd frequencies_hz;
  // Effective modal mass of each mode along x, y (, z) as a fraction of the free mass:
  // (phi^T M r_d)^2 / (r_d^T M r_d), r_d the unit translation along d.
  Eigen::MatrixXd effective_mass_fraction;
  std::vector<Eigen::MatrixXd> shapes;  // per mode: n_nodes x dim, mass-normalized
  int n_free_dofs = 0;
  int iterations = 0;
  int lanczos_runs = 0;  // more than 1 when the Sturm count exposed a missed mode
  int sturm_count = -1;  // modes below sturm_frequency_hz by the inertia of K - sigma M; -1 = not checked
  double sturm_frequency_hz = 0.0;
  double sturm_seconds = 0.0;
  int rigid_body_modes = 0;  // of the modes returned: lambda < 1e-8 lambda_max (free-free models)
  double max_residual = 0.0;
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;  // of the run that solved it when the modes came from the cache
  CacheUse cache;
};

// Throws InputError when more modes are asked than the model has free DOFs. The lowest modes go
// through the model cache in `cache`, when given.
ModalResult solve_modal(const Model& model, const ModeSelection& selection, const ModalOptions& options,
                        const ModelCacheSettings* cache = nullptr);
ModalResult solve_modal(const Model& model, const FreeSystem& system, const ModeSelection& selection,
                        const ModalOptions& options, const ModelCacheSettings* cache = nullptr);

// The lowest options.n_modes modes.
ModalResult solve_modal(const Model& model, const ModalOptions& options);

// A modal analysis's run: the modes, and the stresses of the modes the spec asks for.
struct ModeStresses {
  int mode = 0;  // 1-based
  StressField field;
};
struct ModalOutcome {
  ModalResult modal;
  std::vector<ModeStresses> stresses;
};

ResultTable frequency_table(const Eigen::VectorXd& frequencies_hz);
ResultTable participation_table(const ModalResult& result);

}  // namespace bb
