// The pieces of one period of an event-resolved AFT (friction/aft_events.cpp) and the force
// coefficients integrated over them in closed form: within a piece the contact is in one state, T
// and N are linear in the trigonometric polynomials u and v, so each coefficient is a product with
// the basis's integral or its Gram matrix over the piece.
#pragma once
#include <Eigen/Dense>

#include <utility>
#include <vector>

#include "friction/aft.hpp"

namespace bb::friction {

// The stuck slider of a stick phase, with its derivatives: d w / d[u; v] and d w / d(law).
struct StuckSlider {
  double w = 0.0;
  Eigen::RowVectorXd dw;
  Eigen::RowVector4d dw_law = Eigen::RowVector4d::Zero();
};

// A piece of the period in one state, integrated after the march.
struct Piece {
  double a = 0.0, b = 0.0;
  ContactState state = ContactState::stick;
  int slider = -1;  // index into the march's stuck sliders (stick only)
};

// The coefficients of T and N and their derivatives (the law's too with `with_law`) from the
// pieces of one period into r.
void integrate_pieces(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                      const std::vector<Piece>& pieces, const std::vector<StuckSlider>& sliders, bool with_law,
                      AftResult& r);

// The integrals over a set of pieces [a, b] of the basis phi = [1, cos theta, sin theta, ...,
// sin H theta] and of phi phi^T, each row scaled as a coefficient is (1 / 2 pi, then 1 / pi): a force
// k (u - c) on those pieces has the coefficients k (gram u - c mean), exactly.
struct BasisIntegrals {
  Eigen::VectorXd mean;
  Eigen::MatrixXd gram;
};
BasisIntegrals basis_integrals(const std::vector<std::pair<double, double>>& pieces, int harmonics);

}  // namespace bb::friction
