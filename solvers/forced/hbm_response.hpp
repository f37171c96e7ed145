// Quantities of a harmonic-balance solution that the sweep, the peaks and the tables share: the
// first harmonic of every model DOF and the in-phase / out-of-phase components of a peak.
#pragma once
#include <Eigen/Dense>

#include <complex>

#include "forced/hbm_level.hpp"
#include "hbm/harmonic_balance.hpp"

namespace bb {

// First-harmonic complex amplitude of each model DOF (Re(Z e^{i theta}) = a cos + b sin).
Eigen::VectorXcd first_harmonic(const hbm::HarmonicBalance& system, const Eigen::VectorXd& x, double omega);
// The same from the recovered coefficients (HarmonicBalance::recover: rows DOFs, columns c0, a1, b1, ...).
Eigen::VectorXcd first_harmonic(const Eigen::MatrixXd& q);

// Row `row` of a table's per-response matrices (points x responses): each response's first-harmonic
// amplitude [m], its phase to the first force [deg] and its largest |u(t)| [m], from q (the
// coefficients HarmonicBalance::recover gives) and the first force's complex amplitude (1 for a
// force-controlled solve, whose force is the phase reference).
void write_response_row(const PreparedHbm& p, const Eigen::MatrixXd& q, std::complex<double> force, Eigen::Index row,
                        Eigen::MatrixXd& amplitude, Eigen::MatrixXd& phase_deg, Eigen::MatrixXd& excursion);

// Largest |x(t)| over a period of the signal x(t) = c0 + sum_h c(2h-1) cos(h theta) + c(2h) sin(h
// theta) (one row of HarmonicBalance::recover): every harmonic counts, as in the displacement a
// gauge or a clearance sees. Sampled, then refined by golden section around the largest sample.
double largest_excursion(const Eigen::RowVectorXd& coefficients);

// What a peak of `kind` (0 in-phase, 1 out-of-phase, or the first response) measures in a response
// z: the component that peaks, and the amplitude of the right (or first) response.
struct PeakValues {
  double component = 0.0;
  double amplitude = 0.0;
};
PeakValues peak_values(const PreparedHbm& p, const Eigen::VectorXcd& z, int kind);

}  // namespace bb
