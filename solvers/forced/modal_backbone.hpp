// An amplitude-dependent modal property (a backbone's natural frequency, or its damping ratio) as
// a smooth free-form curve: the cubic spline through knot values y_i at amplitudes a_i, in
// s = log(a), with zero slope at both end knots and constant beyond them. So the curve is C1
// everywhere, tends to its first knot's value as a -> 0 (the linear limit) and holds its last
// beyond the data; between knots it is not forced to be monotone, since measured joints are not
// (issue 68: a resonance that moves down, then up, while the damping grows several-fold).
//
// The value is linear in the knot values: y(a) = sum_i w_i(a) y_i, so the exact sensitivity of
// anything computed from y to a knot value is the weight w_i(a) (weights() below).
#pragma once
#include <Eigen/Dense>

#include <vector>

namespace bb {

class ModalBackbone {
 public:
  ModalBackbone() = default;
  // Throws std::invalid_argument unless amplitudes are positive and strictly increasing, with
  // one finite value each and at least one knot (one knot: a constant).
  ModalBackbone(std::vector<double> amplitudes, std::vector<double> values);

  size_t knots() const { return a_.size(); }
  const std::vector<double>& amplitudes() const { return a_; }
  const std::vector<double>& values() const { return y_; }
  void set_value(size_t knot, double value);

  double operator()(double amplitude) const;
  // d y / d a at the amplitude (0 outside the knots).
  double slope(double amplitude) const;
  // w_i(a): y(a) = sum_i w_i(a) y_i for every choice of the values.
  Eigen::VectorXd weights(double amplitude) const;
  // The smallest and largest value on [lo, hi], sampled (a validity check, not a bound).
  std::pair<double, double> range(double lo, double hi, int samples = 400) const;

 private:
  // The interval of s and its local coordinates; value and slope from second derivatives m.
  double evaluate(double s, const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::VectorXd& m, double* dyds) const;
  std::vector<double> a_, s_, y_;
  Eigen::MatrixXd second_;  // knot second derivatives per unit knot value: m = second_ * y
  Eigen::VectorXd m_;       // second_ * y_, kept with the values
};

}  // namespace bb
