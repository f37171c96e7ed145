// Linear forced response of a model: the full mesh by modal superposition (eq 3.32, with the
// static residual of the truncated modes) and any number of reduced models (Craig-Bampton or
// imported), swept over one frequency grid, with peaks and the modes they belong to.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/frf_spec.hpp"
#include "analysis/modal_analysis.hpp"
#include "analysis/mode_pairs.hpp"
#include "forced/linear_model.hpp"
#include "frf/sweep.hpp"
#include "reduction/craig_bampton.hpp"
#include "results/table.hpp"

namespace bb {

struct FrfCurveSet {
  std::string model;                 // "full" or a reduced model's name
  std::vector<std::string> outputs;  // response DOF names, one per column of the sweep
  int first_column = 0;              // columns of the shared sweep that hold this model's outputs
};

struct RomOutcome {
  std::string name;
  ReducedModel model;
  CraigBamptonTiming timing;       // zero when read from a file
  Eigen::VectorXd frequencies_hz;  // eigenfrequencies of the reduced model
  double setup_seconds = 0.0;      // reduction or reading, plus damping matrix
  double sweep_seconds = 0.0;      // response evaluations over the whole grid
};

struct FrfOutcome {
  ResultTables tables;
  std::optional<ModalResult> full_modal;
  std::vector<FrfCurveSet> curves;
  Sweep sweep;  // every model's outputs side by side
  std::vector<RomOutcome> roms;
  double full_sweep_seconds = 0.0;
  double full_setup_seconds = 0.0;  // modes + residual flexibility
  // Force levels (linearity): the first response of the first model at each level.
  std::vector<double> level_forces;
  std::vector<Eigen::VectorXd> level_amplitudes;
};

// The models of an analysis made ready to respond (modes, residual flexibility, reductions):
// the expensive part, done once. Throws as run_frf.
// `built(done, total)` follows the models (the full one, then each reduced one) as they are made;
// the full model's modes and the Craig-Bampton reductions go through the model cache in `cache`,
// when given.
struct PreparedFrf;
using ModelsBuilt = std::function<void(int done, int total)>;
std::shared_ptr<const PreparedFrf> prepare_frf(const Model& model, const FrfSpec& spec, const ModelsBuilt& built = {},
                                               const ModelCacheSettings* cache = nullptr);
const std::vector<FrfCurveSet>& frf_curves(const PreparedFrf& prepared);
// The outputs of model `curve` (an index into frf_curves) at one frequency, for the spec's forces.
Eigen::VectorXcd frf_respond(const PreparedFrf& prepared, size_t curve, double frequency_hz);
// The sweep, peaks, mode matching and linearity levels of `spec` on prepared models.
FrfOutcome sweep_frf(const PreparedFrf& prepared, const FrfSpec& spec);

// prepare_frf + sweep_frf. Throws InputError for points that are not one-node sets, constrained DOFs, masters that
// repeat, responses or forces a reduced model does not hold; SolverError from the solvers.
FrfOutcome run_frf(const Model& model, const FrfSpec& spec, const ModelsBuilt& built = {},
                   const ModelCacheSettings* cache = nullptr);

}  // namespace bb
