// The rotating analysis (analysis/rotating_spec.hpp) on a model: the floating-frame time run of
// ffrf/, the steady centrifugal deflection, the modes at the run's speed and the Campbell diagram,
// as result tables. Units: SI, frequencies in Hz.
#pragma once
#include <string>
#include <vector>

#include "analysis/rotating_spec.hpp"
#include "assembly/stress_recovery.hpp"
#include "common/work_limits.hpp"
#include "ffrf/ffrf_integrator.hpp"
#include "ffrf/rotating_modes.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

struct RotatingOutcome {
  ResultTables tables;
  ffrf::FfrfHistory history;
  std::vector<std::string> history_sets;  // in spec.histories order
  Eigen::MatrixXd set_histories;          // every step x (sets * dim): the sets' mean displacements [m]
  int dim = 2;
  ffrf::CampbellDiagram campbell;
  std::vector<ffrf::EngineOrderCrossing> crossings;
  ffrf::RotatingModes modes_at_speed;  // at the run's (final) speed
  int free_dofs = 0, basis_size = 0;
  double time_step = 0.0;
  double setup_seconds = 0.0, run_seconds = 0.0, campbell_seconds = 0.0;
  std::string profile;          // description of the rotor's motion
  StressField steady_stresses;  // of the steady deflection at the run's (final) speed [Pa]
};

// Throws InputError for a history set the model lacks or a basis the body cannot hold, SolverError
// when the run diverges (energy blow-up, spin-softening divergence: the message names the time).
RotatingOutcome run_rotating(const Model& model, const RotatingSpec& spec, const WorkLimits& limits = {});

// The amplitude spectrum of a sampled signal (mean removed, Hann window, zero-padded FFT), and its
// dominant peak in a band: the local maximum refined by a parabola; NaN when the maximum sits on the
// band's edge (no peak inside). Amplitudes are those of sinusoids [the signal's unit].
struct SpectralPeak {
  double frequency_hz = 0.0;
  double amplitude = 0.0;
};
class AmplitudeSpectrum {
 public:
  AmplitudeSpectrum(const Eigen::VectorXd& signal, double dt);
  SpectralPeak peak(double f_lo, double f_hi) const;
  double resolution_hz() const { return df_; }

 private:
  Eigen::VectorXd amplitude_;  // per bin
  double df_ = 0.0;            // bin width [Hz]
};

}  // namespace bb
