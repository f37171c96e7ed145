// The exact flow's state along one piece, z(tau) = exp(a tau) z: a linear function of it, the
// location of its first zero and its turning point (how timeint/piecewise_flow.cpp finds where a
// contact's transition happens inside a piece), and its Fourier integrals. Phases in rad (the period
// is 2 pi).
#pragma once
#include <Eigen/Dense>

#include <vector>

namespace bb::timeint {

// Phases below this are one point: a transition is located to it.
inline constexpr double kPhaseResolution = 1e-13;

// g by the modes of a (O(size) per value) where their basis reproduces the piece's end, else by the
// exponential.
class FlowTrace {
 public:
  // modal: row V and lambda the eigenvalues of a (a = V diag(lambda) V^-1), coordinates V^-1 z; null
  // without a usable basis. The references must outlive the trace.
  FlowTrace(const Eigen::RowVectorXd& row, const Eigen::MatrixXd& a, const Eigen::VectorXd& z,
            const Eigen::RowVectorXcd* modal, const Eigen::VectorXcd* lambda, const Eigen::VectorXcd* coordinates,
            double check_tau, double check_value);
  double value(double tau) const;
  double rate(double tau) const;

 private:
  const Eigen::RowVectorXd& row_;
  const Eigen::MatrixXd& a_;
  const Eigen::VectorXd& z_;
  Eigen::VectorXcd weights_, lambda_;
  bool spectral_ = false;
};

// The first zero of g in [lo, hi], g(lo) <= 0 < g(hi): Illinois, returning a phase on the far side
// (g > 0), so the transition has happened there.
double crossing(const FlowTrace& g, double lo, double hi);

// The phase in (0, hi) where g' changes from + to - (bisection).
double turning_point(const FlowTrace& g, double hi);

// Adds the integrals over the piece [theta0, theta0 + tau] of z_e, z_e cos(h theta) and z_e sin(h
// theta), z(theta0 + s) = exp(a s) z, to columns 0, 2 h - 1 and 2 h of fourier's row i for e =
// entries[i]: in closed form by the modes where given (coordinates V^-1 z, vectors V, lambda), else
// by 8-point Gauss-Legendre (exact to rounding on a piece where the fastest motion turns by 1 rad).
void add_fourier_integrals(const Eigen::MatrixXd& a, const Eigen::VectorXd& z, const Eigen::VectorXcd* coordinates,
                           const Eigen::MatrixXcd* vectors, const Eigen::VectorXcd* lambda, double theta0, double tau,
                           const std::vector<Eigen::Index>& entries, Eigen::MatrixXd& fourier);

}  // namespace bb::timeint
