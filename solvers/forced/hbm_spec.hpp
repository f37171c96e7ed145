// What a nonlinear forced-response (harmonic balance) analysis computes: one linear model (a
// Craig-Bampton reduction of the mesh, a reduced model from files, or lumped matrices), friction
// contacts between its DOFs or with the ground, optionally a rigid underplatform damper, swept in
// frequency at several force levels.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/source_location.hpp"
#include "forced/base_motion_spec.hpp"
#include "forced/linear_model_spec.hpp"
#include "friction/aft.hpp"
#include "friction/friction_law.hpp"
#include "friction/jenkins.hpp"
#include "friction/masing.hpp"

namespace bb {

// A contact between lumped DOFs: u = sum c_i q_i along `tangential`, v = sum c_i q_i along
// `normal` (v > 0 presses). One DOF alone ties it to the ground; no normal terms = constant load n0.
struct HbmContactSpec {
  std::string name;
  std::vector<std::pair<PointDof, double>> tangential, normal;
  // With [analysis.cyclic]: the terms of the next sector's DOFs (named as this sector's), which in
  // the travelling wave move as this sector's shifted by 2 pi EO / N (friction/friction_system.hpp).
  std::vector<std::pair<PointDof, double>> tangential_next, normal_next;
  friction::PointParameters point;  // the point: kn, n0, its stuck kt and its Coulomb limit mu
  std::shared_ptr<const friction::SliderDistribution> distribution;            // null: one Jenkins slider
  std::shared_ptr<const friction::FrictionLaw> law = friction::jenkins_law();  // what the solvers call
  // The second tangential direction of a law of two (coupled_slip); empty otherwise.
  std::vector<std::pair<PointDof, double>> tangential_2;
  SourceLocation at;
};

// One point of the rigid damper: its position and the blade point that carries the platform side.
struct DamperPointSpec {
  std::string name;       // "L1"
  bool left_face = true;  // flat face on the left platform, else the right platform
  std::string point;      // master point of the blade model (x and y DOFs); empty = rigid platform
  std::optional<std::array<double, 2>> position;  // [x, y] in the model frame; default: the point's node
  SourceLocation position_at;                     // of `position`, for a position its node contradicts
};

// Rigid planar damper (damper/rigid_damper.hpp) pressed by the centrifugal force.
struct DamperSpec {
  double mass = 0.0, inertia = 0.0;  // [kg], [kg m^2] about G
  std::array<double, 2> centre{};    // G in the model frame [m]
  double left_face_deg = 45.0, right_face_deg = 45.0;
  double centrifugal_force = 0.0;   // CF along +y at G [N]
  friction::PointParameters point;  // kn, kt, mu of every point (n0 = 0: the static solve sets the load)
  // Every point's law; one of two directions takes the blade point's z as its second (the planar
  // damper does not move out of its plane).
  std::shared_ptr<const friction::FrictionLaw> law = friction::jenkins_law();
  std::vector<DamperPointSpec> points;
};

struct HbmSweepSpec {
  double f_min = 0.0, f_max = 0.0;  // [Hz]
  // grid: Newton at each frequency of a fixed grid from the previous solutions (cubic predictor);
  // robust on the kinks of stick-slip-lift-off, cannot pass a fold. arclength: pseudo-arclength
  // continuation, passes folds (impacts, softening), may stall on kinks.
  enum class Method { grid, arclength } method = Method::grid;
  double step_hz = 0.05;                                         // grid
  double initial_step = 0.01, max_step = 0.05, min_step = 1e-6;  // arclength, scaled (hbm::ContinuationOptions)
};

// A parameter of the model whose exact log-sensitivity the analysis adds to its FRF tables
// (hbm/sensitivity.hpp): one law parameter of one [[analysis.contact]] or of every damper contact,
// the modal damping ratio (of every mode, or of one mode when they are given per mode), an entry
// of the stiffness or mass matrix written in the case, or a modal model's frequency or modal mass.
struct HbmParameter {
  enum class Kind {
    contact_law,
    damper_law,
    modal_damping,
    mode_damping,
    lumped_matrix,
    modal_coordinate
  } kind = Kind::modal_damping;
  size_t contact = 0;       // contact_law: index into HbmSpec::contacts
  bool mass = false;        // lumped_matrix: an entry of M (else of K); modal_coordinate: the modal
                            //   mass (else the frequency)
  size_t row = 0, col = 0;  // lumped_matrix: (row, col) and its mirror; mode_damping, modal_coordinate:
                            //   the mode (row)
  friction::LawParameter law = friction::law_kt;  // contact_law, damper_law
  std::string label;                              // its case path, e.g. "analysis.contact.0.kt": names the columns
};

// Nonlinear modes of the model (hbm/nonlinear_modes.hpp) along a modal amplitude range, and the
// forced-response peak each predicts at every force level (single-nonlinear-mode theory).
struct NonlinearModesSpec {
  std::vector<int> linear_modes;  // 1-based, ascending frequency of the stuck linearization
  // The sweep's peak kind each mode is compared with ("ip", "oop" or "peak"); empty = no comparison.
  std::vector<std::string> peaks;
  double amplitude_min = 0.0, amplitude_max = 0.0;  // modal amplitude a [m kg^1/2], q_1 = a psi, psi^H M psi = 1
  int points = 40;                                  // log-spaced amplitudes
  SourceLocation at;
};

// One sector of a tuned cyclic structure (a bladed disk) in the travelling wave of an engine-order
// excitation: the forces act on this sector, each other sector moves as it does shifted by the
// inter-sector phase 2 pi EO / N, and contacts may join the next sector's DOFs.
struct HbmCyclicSpec {
  int sectors = 0;       // N
  int engine_order = 0;  // EO
  // Verification: the whole ring built from the sector (friction::whole_ring: N copies, the next
  // terms on the next copy, the forces of copy j shifted by j 2 pi EO / N) solved as one structure;
  // its tables are the first sector's.
  bool whole = false;
  // With a mesh (Craig-Bampton masters): the sector's cyclic faces, reduced per nodal diameter
  // (cyclic/cyclic_reduction.hpp).
  std::string left = "cyclic_left", right = "cyclic_right";
  double face_tolerance = 1e-9;  // [m]
  SourceLocation at;
};

// A point damper in the gap between this sector's blade and the next one's (a cyclic sector of a
// mesh): two DOFs, "damper.t" along the circumference and "damper.r" along the radius of the gap,
// pushed outward by its centrifugal force into the platform point `own` of this sector and `next`
// of the next sector, through two Jenkins contacts on the faces of a wedge (contacts "own" and
// "next"; the normal load varies with the motion, n0 = 0 and the static balance loads them). Each
// face's normal leans from the radius towards its own platform by the face angle: with flat faces
// (0 deg) nothing but friction holds the damper's mean circumferential position, which a slipping
// contact leaves free (the balance is then singular).
struct GapDamperSpec {
  double mass = 0.0;                                                 // [kg]
  double face_angle_deg = 45.0;                                      // in (0, 90)
  std::string own, next;                                             // master points of the sector
  double centrifugal_force = 0.0;                                    // [N], outward at the gap
  friction::PointParameters point;                                   // kn, kt, mu of each face
  std::shared_ptr<const friction::SliderDistribution> distribution;  // null: one Jenkins slider per face
  SourceLocation at;
};

// A stepped sine as a rig runs it: the frequencies in the order they were stepped (up or down),
// each at its own force amplitude (a force-controlled rig holds its force only roughly: it drifts
// along the curve). Each point starts from the one before, as the structure does on the rig, so an
// up and a down sweep may settle on different branches where the response folds.
struct SteppedSineSpec {
  std::string name;                  // writes table frf_<name>
  std::vector<double> frequency_hz;  // strictly increasing or strictly decreasing
  std::vector<double> force;         // amplitude of the first force at each frequency [N]
  std::string file;                  // the measured data it was read from; empty when written in the case
  SourceLocation at;
};

// A response-controlled stepped sine: at each frequency, in the order stepped, the force that
// holds a response's first harmonic at a given amplitude (hbm/response_control.hpp), as rigs run
// joints and dampers at constant vibration level. The amplitude may be a displacement, a velocity
// or an acceleration (held constant in that quantity: the displacement is amplitude / w^derivative).
struct ResponseControlSpec {
  std::string name;                  // writes table frf_<name>
  size_t response = 0;               // index into HbmSpec::responses of the held DOF
  double amplitude = 0.0;            // [m], [m/s] or [m/s^2] by `derivative`
  int derivative = 0;                // 0 displacement, 1 velocity, 2 acceleration
  std::vector<double> frequency_hz;  // strictly increasing or strictly decreasing
  SourceLocation at;
  // Read from a measured curve (`file`): the level is the median of its amplitude column, whose
  // smallest and largest values lie at spread_low, spread_high relative to it; file empty otherwise.
  std::string file;
  double spread_low = 0.0, spread_high = 0.0;

  // The displacement amplitude that holds `amplitude` in the controlled quantity at omega [rad/s].
  double held_displacement(double omega) const { return amplitude / std::pow(omega, derivative); }
};

struct HbmSpec {
  RomSpec model;                                  // the linear part: masters / file / matrices
  FrfDamping damping;                             // on the linear model's modes (the damper is undamped)
  std::optional<Eigen::MatrixXd> damping_matrix;  // or C itself, written with matrices in the case
  std::vector<HbmContactSpec> contacts;
  std::optional<DamperSpec> damper;
  std::optional<HbmCyclicSpec> cyclic;
  std::optional<GapDamperSpec> gap_damper;
  std::vector<std::pair<PointDof, double>> static_loads;  // [N], besides the damper's CF
  std::vector<FrfForce> forces;                           // the excitation pattern; each level scales it
  std::vector<double> force_levels;                       // amplitude of the first force at each level [N]
  // Or the supports' motion as the excitation (no forces): force_levels then hold its levels, the
  // base acceleration of harmonic 1 [m/s^2], and a stepped sine's or response control's "force"
  // is that acceleration.
  std::optional<BaseMotionSpec> base_motion;
  std::vector<SteppedSineSpec> stepped_sines;           // solved at spec.harmonics after the levels
  std::vector<ResponseControlSpec> response_controls;   // likewise
  std::vector<PointDof> responses;                      // first-harmonic amplitudes written per level
  std::optional<std::pair<PointDof, PointDof>> ip_oop;  // (left, right): in-phase / out-of-phase peaks
  int harmonics = 1;
  int time_samples = 0;  // AFT samples per period; 0 = automatic
  // aft = "events" (default): transitions located and the forces integrated between them (contact/
  // aft_events.hpp), a residual smooth in the unknowns whose error does not depend on the samples;
  // "samples": the DFT of the sampled march, whose error at a stick-slip kink falls as 1 / samples.
  bool aft_events = true;
  // When > 0, each level's samples are raised from time_samples (up to max_time_samples) until
  // the AFT sampling error at its peaks is at most this (relative to the force scale, as
  // HbmPeak::sampling_error) and its sweep reaches the end with trusted peaks. 0 = fixed samples.
  double aft_tolerance = 0.0;
  int max_time_samples = 4096;
  // When > 0, each level's H is raised from `harmonics` (up to max_harmonics) until the share of
  // its motion the harmonics above H would add (hbm/harmonic_truncation.hpp), at every path point
  // and peak, is at most this, with the sweep at its end and its peaks trusted. 0 = H fixed.
  double harmonic_tolerance = 0.0;
  int max_harmonics = 9;
  // Where the shares must meet it: every path point and peak (a check may read any frequency), or
  // the peaks alone (what a peaks table reports). `point`: each frequency of a grid sweep gets its
  // own H (criterion change only), raised by harmonic_step until its responses (largest
  // displacement, first harmonic, IP/OOP components) move by at most the tolerance; the next
  // frequency starts one step lower, so H falls again away from resonance.
  enum class HarmonicScope { path, peaks, point } harmonic_scope = HarmonicScope::path;
  // What harmonic_tolerance bounds: the share the harmonics above H would add (estimated from one
  // sweep), or the change of the result from the previous good H (measured, one
  // more sweep per level): the peaks' frequency and component, and with the path scope the largest
  // displacement along the curve, relative to the higher H's.
  enum class HarmonicCriterion { share, change } harmonic_criterion = HarmonicCriterion::share;
  int harmonic_step = 1;    // the smallest raise of H between two sweeps (2: odd harmonics compared)
  double tolerance = 1e-9;  // relative, hbm::HbmOptions
  // Newton iterations per start (a solve tries up to three starts). On a sweep a converging point
  // needs 1-5 from the cubic guess; a small cap makes the rare failures cheap.
  int max_iterations = 20;
  HbmSweepSpec sweep;
  // Parameters whose log-sensitivities each frf_<Fe> table carries (p d|z|/dp, p d phase/dp) and
  // the peaks table (p d f/dp, p d|z|/dp as each peak moves). Empty = none.
  std::vector<HbmParameter> sensitivities;
  // False: the peaks only (a fit of peaks needs no curve's derivatives, one factorization per point).
  bool path_sensitivities = true;
  std::optional<NonlinearModesSpec> nonlinear_modes;
  // Floquet exponents by Hill's method (hbm/hill_stability.hpp): at no point, at the peaks, or at
  // every path point (and the peaks). The path costs one eigenproblem of size 2 n (2H + 1) per point.
  enum class Stability { none, peaks, path } stability = Stability::none;
  // Force levels swept at once, each on its own thread (they are independent: the results are
  // those of the serial run, bit for bit). 0: one per core of the machine.
  int threads = 0;
  SourceLocation at;  // of [analysis], for errors found when the model is built
};

// Why the analysis cannot differentiate `parameter` (no such contact, no damper, damping that is not
// one modal ratio), or nullopt when it can.
std::optional<std::string> unsupported_sensitivity(const HbmSpec& spec, const HbmParameter& parameter);

}  // namespace bb
