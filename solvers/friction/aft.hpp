// Alternating frequency-time (AFT) evaluation of one Jenkins contact point (friction/jenkins.hpp):
// harmonic coefficients of the relative displacements (u, v) in, harmonic coefficients of the
// contact forces (T, N) and their exact Jacobian out. The frequency-domain half of the refined
// approach of thesis section 3.3.2.5 (eqs 3.28-3.31), with H harmonics instead of the thesis's one.
// Units: SI.
//
// Real harmonic layout, used for every coefficient vector here: with theta = omega t,
//   x(theta) = c0 + sum_{h=1..H} a_h cos(h theta) + b_h sin(h theta),   stored as [c0, a1, b1, ..., aH, bH],
// so a vector of 2H + 1 entries. The contact law has no rate dependence, so omega never enters.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "friction/jenkins.hpp"

namespace bb::friction {

// 2H + 1; throws std::invalid_argument when harmonics < 0.
Eigen::Index harmonic_size(int harmonics);
// H from a coefficient count; throws std::invalid_argument unless the count is odd and >= 1.
int harmonics_of(Eigen::Index coefficients);

// Samples theta_k = 2 pi k / n_t, k = 0 .. n_t - 1. Row k of the n_t x (2H+1) synthesis matrix
// holds [1, cos theta_k, sin theta_k, ..., cos H theta_k, sin H theta_k], so x(theta_k) = E c.
// The (2H+1) x n_t analysis matrix P is the discrete Fourier transform in the same layout
// (P E = I exactly when n_t >= 2H + 1). A plain DFT rather than an FFT: n_t is tens to hundreds,
// the Jacobian needs P applied to an n_t x (2(2H+1)) matrix anyway (a matrix product, not a
// transform per column), and any n_t works, not only FFT-friendly sizes. Both throw
// std::invalid_argument unless harmonics >= 0 and samples >= 2H + 1.
Eigen::MatrixXd synthesis_matrix(int harmonics, int samples);
Eigen::MatrixXd analysis_matrix(int harmonics, int samples);

// synthesis_matrix and analysis_matrix of (harmonics, samples), kept per thread for the last pair
// asked (a sweep calls an AFT thousands of times with the same pair). The synthesis is row-major:
// the march reads one row per sample, and in column-major storage a row is strided by n doubles
// (a power-of-two n maps it onto a few L1 sets: 256 samples cost 1.7x per sample what 240 did at
// H = 7). Valid until the thread asks for another pair.
struct AftTransforms {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> synthesis;
  Eigen::MatrixXd analysis;
};
const AftTransforms& aft_transforms(int harmonics, int samples);

struct AftOptions {
  // n_t, time samples per period. Required: >= 2H + 1 (no aliasing of the input), in practice
  // >= 16 (2H + 1) since stick-slip forces have kinks and their coefficients converge as 1 / n_t^2.
  int samples = 0;
  // Periods are repeated until the slider closes its loop; at least two are always marched (the
  // first one starts from an arbitrary slider state), at most this many. For this law two suffice:
  // each step clamps w onto [u - mu N / kt, u + mu N / kt] (or onto u when open), a period is a
  // composition of clamps, i.e. a clamp onto one interval, and a clamp applied twice is the same
  // clamp. The cap guards against rounding and against laws that lack this property.
  int max_periods = 20;
  // The loop is closed when |w(end of period) - w(end of previous period)| <= closure_tolerance
  // times the displacement scale (max |u(t)| + mu max N / kt).
  double closure_tolerance = 1e-12;
  // Slider position w at the start of the first period [m]. A loop that slips or lifts off
  // somewhere forgets it; a loop that sticks throughout keeps it, since a stuck friction contact
  // carries whatever tangential force it was closed with. 0 means the contact closed with zero
  // tangential force at u = 0, so a stuck contact is the linear spring T = kt u.
  double initial_slider = 0.0;
  // Also compute AftResult::dtangential_dlaw and dnormal_dlaw (sensitivity analysis, hbm/
  // sensitivity.hpp). Off by default: the Newton solves do not need them.
  bool law_derivatives = false;
  // Locate every stick / slip / lift-off transition and integrate the forces between them
  // (friction/aft_events.hpp) instead of taking the DFT of the samples: coefficients and Jacobian
  // continuous in the inputs, their error independent of where a transition falls.
  bool resolve_events = false;
};

// Column order of the law-parameter derivatives in AftResult.
enum LawParameter : Eigen::Index { law_kn = 0, law_kt = 1, law_mu = 2, law_n0 = 3 };

struct AftResult {
  Eigen::VectorXd tangential;  // T coefficients [N], 2H + 1
  Eigen::VectorXd normal;      // N coefficients [N], 2H + 1
  // Exact derivatives of the coefficients above with respect to those of u and v, (2H+1) x (2H+1)
  // each [N/m]; dN/du is zero. Exact for the discrete march, valid while no sample changes state:
  // see aft.cpp for the chain rule through the slider history.
  Eigen::MatrixXd dtangential_du, dtangential_dv, dnormal_dv;
  // Derivatives of the same coefficients with respect to the law parameters at fixed (u, v),
  // (2H+1) x 4, columns (kn, kt, mu, n0) as LawParameter; empty unless options.law_derivatives.
  // Exact for the discrete march under the same condition (no sample changes state).
  Eigen::MatrixXd dtangential_dlaw, dnormal_dlaw;

  // The last marched period at the samples theta_k: displacements, forces, slider after each
  // sample and the state of Table X at each sample.
  Eigen::VectorXd u, v, t, n, w;
  std::vector<ContactState> state;
  Eigen::VectorXd u_2;  // the second direction's displacement samples; empty for a law of one

  int periods = 0;                // periods marched
  bool closed = false;            // the slider loop closed within the tolerance
  double closure_mismatch = 0.0;  // |w(end) - w(end of the period before)| [m], last period
};

// The checks every AFT makes of its inputs: the point's parameters, `directions` tangential
// coefficient vectors in u for the normal one in v, every coefficient finite, the options in range.
// Returns H; throws std::invalid_argument naming what is wrong.
int checked_aft_inputs(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                       const AftOptions& options, int directions = 1);

// The Jenkins law's AFT, sampled or event-resolved (friction/aft_events.hpp) as
// options.resolve_events asks; the dispatch is the law's (friction/jenkins_law.cpp). Throws
// std::invalid_argument when the parameters are invalid (validate()), the two coefficient vectors
// differ in size or hold a non-finite value, or the options are out of range. A loop that does not
// close within max_periods is returned with closed == false, never thrown: the caller decides (a
// Newton solve treats it as a failed evaluation).
[[nodiscard]] AftResult aft_jenkins(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                    const AftOptions& options);
// Its sampled march alone, inputs checked by aft_jenkins.
[[nodiscard]] AftResult aft_jenkins_sampled(const PointParameters& p, const Eigen::VectorXd& u,
                                            const Eigen::VectorXd& v, const AftOptions& options);

// Work done by the force f on the displacement x over one period, W = integral of f dx
// = pi sum_h h (f_a,h x_b,h - f_b,h x_a,h) in the layout above; the energy a contact dissipates per
// cycle when f = T and x = u. Exact for the given coefficients (orthogonality of the harmonics).
// Throws std::invalid_argument when the sizes differ.
double cycle_work(const Eigen::VectorXd& force, const Eigen::VectorXd& displacement);

}  // namespace bb::friction
