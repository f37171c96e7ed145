// One force level of the nonlinear forced response by harmonic balance: the case's friction model
// made ready once (prepare_hbm) and the sweep of a level at fixed or adaptive H, with its peaks.
// The analysis (hbm_analysis.hpp) runs the levels and writes the tables; the nonlinear modes
// (hbm_nonlinear_modes.hpp) read the levels' peaks; both include this header, not each other.
#pragma once
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cache/model_cache_settings.hpp"
#include "damper/rigid_damper.hpp"
#include "forced/hbm_spec.hpp"
#include "forced/level_relay.hpp"
#include "hbm/harmonic_balance.hpp"
#include "hbm/harmonic_truncation.hpp"
#include "hbm/hill_stability.hpp"
#include "model/model.hpp"
#include "reduction/craig_bampton.hpp"
#include "results/table.hpp"

namespace bb {

// One line of progress ("Fe = 60 N: 176.2 Hz, 212 points"); the caller decides where it goes.
using HbmProgress = std::function<void(const std::string&)>;

// The linear model, contacts and loads assembled once; the force level and H are set per sweep.
struct PreparedHbm {
  friction::FrictionModel model;           // harmonic load for a first-force amplitude of 1 N
  std::vector<std::string> dof_names;      // of the model's DOFs ("T2.x", "mode 3", "damper.x")
  std::vector<std::string> contact_names;  // of the model's contacts (an Iwan joint's sliders "joint.1", ...)
  // The model contacts [first, last) of each [[analysis.contact]] (its sliders); the damper's come first.
  std::vector<std::pair<size_t, size_t>> contact_sliders;
  std::vector<Eigen::Index> responses;  // model DOF of each response
  std::vector<std::string> response_names;
  std::optional<std::pair<Eigen::Index, Eigen::Index>> ip_oop;  // (left, right) DOFs
  std::optional<damper::RigidDamper> damper;
  std::optional<damper::DamperStaticState> damper_static;
  double centrifugal_force = 0.0;  // CF on the damper [N]
  ReducedModel linear;  // the linear model (its recovery matrix when reduced here); empty for a cyclic sector
  Eigen::VectorXd linear_frequencies_hz;  // of the linear model without contacts
  int blade_dofs = 0;                     // DOFs of the linear model (the damper's follow)
  CraigBamptonTiming timing;
  double setup_seconds = 0.0;
};

// Throws InputError for unknown DOFs or points, a singular static problem or a damper whose static
// pre-solve fails (message with the reason); SolverError from the reduction. A Craig-Bampton
// reduction goes through the model cache in `cache`, when given.
PreparedHbm prepare_hbm(const Model& model, const HbmSpec& spec, const ModelCacheSettings* cache = nullptr);
// The same for one meshed sector of a tuned disk ([analysis.cyclic] with Craig-Bampton masters and
// an [analysis.gap_damper]), or the whole disk built from it (forced/hbm_cyclic_sector.cpp).
PreparedHbm prepare_cyclic_sector(const Model& model, const HbmSpec& spec, const ModelCacheSettings* cache = nullptr);

struct HbmPeak {
  std::string kind;  // "IP", "OOP", or "peak" (maximum of the first response)
  double frequency_hz = 0.0;
  double amplitude = 0.0;  // first-harmonic amplitude of the right (or first) response [m]
  double component = 0.0;  // the in-phase / out-of-phase component that peaks there [m]
  hbm::HbmSolution solution;
  hbm::CycleEnergy energy;
  // False when the path did not converge next to the peak (a rejected grid frequency between its
  // neighbours, or the last point of a sweep that stopped): the maximum may be an artefact of the
  // failure, not the resonance. `doubt` says why.
  bool trusted = true;
  std::string doubt;
  // |g_2N(x) - g_N(x)| / force scale: the contact forces of the peak's motion with twice the AFT
  // samples against those the solve used, as a residual of the balance (hbm::HarmonicBalance::
  // force_scale, the solve's convergence measure): the time-sampling error the solution carries.
  double sampling_error = 0.0;
  // The shares of the peak's motion that the harmonics above the level's H would add
  // (hbm/harmonic_truncation.hpp): the truncation error the solution carries.
  hbm::HarmonicTruncation truncation;
  // With HbmSpec::stability: the Floquet exponents of the peak's solution (Hill's method).
  std::optional<hbm::HillStability> stability;
  int harmonics = 0;  // H of `solution` (the level's, or with the point scope the largest of its neighbours)
  // Per path of HbmSpec::sensitivities: p d(frequency_hz)/dp and p d(amplitude)/dp as the peak moves
  // (forced/hbm_peak_sensitivity.hpp); NaN where the peak is not a smooth maximum. Empty = not asked.
  std::vector<double> frequency_hz_dlog, amplitude_dlog;
};

struct HbmLevel {
  double force = 0.0;  // amplitude of the first force [N]
  hbm::ContinuationResult path;
  std::vector<double> frequency_hz;  // of the path points
  Eigen::MatrixXd amplitude;         // path points x responses, first harmonic [m]
  Eigen::MatrixXd phase_deg;         // path points x responses, first harmonic's phase to the force
  Eigen::MatrixXd excursion;         // path points x responses, largest |u(t)| over a period, all harmonics [m]
  Eigen::MatrixXd components;        // path points x (IP, OOP) [m] when ip_oop is set
  // With HbmSpec::Stability::path, per path point: 1 stable, 0 unstable, NaN not computed; the largest
  // real part of its Floquet exponents [1/s].
  std::vector<double> stable, floquet_max_real;
  // Per path of spec.sensitivities: path points x responses, p d|z|/dp [m] and p d phase/dp [deg]
  // at fixed frequency (hbm/sensitivity.hpp); NaN where the sensitivity is not defined.
  std::vector<Eigen::MatrixXd> amplitude_dlog, phase_dlog_deg;
  std::vector<HbmPeak> peaks;
  // With HbmSpec::harmonic_tolerance, per path point: the largest amplitude the harmonics above H
  // would add at a response, relative to that response's largest first-harmonic amplitude over the
  // path (hbm/harmonic_truncation.hpp); and the highest harmonic any point needs.
  std::vector<double> harmonic_share;
  int harmonics_needed = 0;
  // With HbmSpec::HarmonicScope::point, per path point: the H it was solved with, and the largest
  // relative change of its responses from the H one step below (NaN where the last pair did not
  // both converge). NaN or above the tolerance: the point kept its H without two H agreeing.
  std::vector<int> point_harmonics;
  std::vector<double> point_change;
  std::vector<double> failed_hz;  // grid frequencies that did not converge
  int samples = 0;                // AFT samples per period the level was solved with
  int harmonics = 0;              // H the level was solved with (the point scope: the largest any point needed)
  double seconds = 0.0;
  // With HbmSpec::aft_tolerance: every sweep tried, coarsest first; the level holds the last one.
  struct SamplingTrial {
    int samples = 0;
    double aft_error = 0.0;  // largest HbmPeak::sampling_error of the sweep
    bool reached_end = false, trusted = false;
    double seconds = 0.0;
  };
  std::vector<SamplingTrial> sampling_trials;
  // With HbmSpec::harmonic_tolerance: every H tried, lowest first; `chosen` marks the one kept.
  struct HarmonicTrial {
    int harmonics = 0, samples = 0;
    double share = 0.0;  // largest share over the sweep's points and peaks
    // With HarmonicCriterion::change: the largest relative change against the previous H whose
    // sweep reached its end with trusted peaks (NaN for the first such H, or a failed sweep).
    double change = std::numeric_limits<double>::quiet_NaN();
    // With it: the error of this H, the changes of the last three good H fitted by a power law of H
    // (power_law_error; NaN with fewer, infinite where they do not fall as one).
    double estimated_error = std::numeric_limits<double>::quiet_NaN();
    bool reached_end = false, trusted = false, chosen = false;
    double seconds = 0.0;
    // With the peaks scope of a grid sweep, H above the first is swept only on windows of the band
    // around the previous good H's peaks: their half-width [Hz] (0: the whole band).
    double window_hz = 0.0;
    // The whole band's sweep at the H the windows chose: its peaks' largest relative change from
    // the windows' (NaN on the other trials). Above the tolerance the band holds a peak the windows missed.
    double band_change = std::numeric_limits<double>::quiet_NaN();
  };
  std::vector<HarmonicTrial> harmonic_trials;
};

// The sweep of one force level with H harmonics. A continuation that stops is reported in
// path.failure (with frequency and residual) and the level keeps the points reached. With
// spec.aft_tolerance > 0 the level is swept again with more AFT samples while its peaks'
// sampling error exceeds the tolerance, the sweep stops short or a peak is doubtful (an
// under-sampled stick-slip residual is too rough for the corrector), up to spec.max_time_samples;
// with retry_failures = false, a sweep that stops short or a doubtful peak ends the raising (the
// caller has a cheaper remedy: another H).
// With a link, the first point starts from the previous level's first solution (else, or when
// that fails, from the static one) and hands its own on.
HbmLevel sweep_hbm_level(const PreparedHbm& prepared, const HbmSpec& spec, double force, int harmonics,
                         const HbmProgress& progress = {}, bool retry_failures = true, const LevelLink* link = nullptr);

// The sweep of one force level with the harmonics it needs: from spec.harmonics, H is raised to
// the highest harmonic whose share of the motion (at the path points and peaks, or the peaks alone:
// spec.harmonic_scope) exceeds spec.harmonic_tolerance (at most spec.max_harmonics), until the
// shares meet it with the sweep at its end and its peaks trusted.
// Keeps the first H that meets it; when none does, the highest H whose sweep reached its end with
// trusted peaks (else the last), so a failed sweep at a higher H never replaces a good one.
// With spec.harmonic_criterion = change, H rises by spec.harmonic_step until the result (the
// peaks, and with the path scope the curve) changes by at most the tolerance from the previous H
// whose sweep reached its end; the higher H of that pair is kept.
// Once one H has succeeded, a failed sweep moves on to the next H instead of raising its AFT
// samples (on Table XI such retries at 2048-4096 samples cost 30-275 s a level and still failed).
// With the peaks scope and a grid sweep, the H after the first are swept on windows around the
// previous good H's peaks (widened while a peak lies at a window's edge), and the H chosen is then
// swept over the whole band once: the frequencies away from the peaks, where a low H's sweep may
// fail at a kink (Table XI, 60 N, H = 2: 4 frequencies near 170.7 Hz, 61 s), are solved once.
// (hbm_harmonic_choice.cpp)
HbmLevel sweep_hbm_level_adaptive(const PreparedHbm& prepared, const HbmSpec& spec, double force,
                                  const HbmProgress& progress = {}, const LevelLink* link = nullptr);

// The name of level `force`'s FRF table, e.g. "frf_300" or "frf_0.5".
// Its sensitivity columns: "<response>_amp_m_dlog_<path>" and "<response>_phase_deg_dlog_<path>".
std::string hbm_frf_table_name(double force);

}  // namespace bb
