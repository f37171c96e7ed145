// The phase shift of a cyclic contact's next sector (friction/friction_system.hpp): harmonic
// coefficients [c0, a1, b1, ..., aH, bH] of q(theta) turned into those of q(theta + phi).
#pragma once
#include <Eigen/Dense>

namespace bb::hbm {

// In harmonic h: a' = a cos(h phi) + b sin(h phi), b' = b cos(h phi) - a sin(h phi).
Eigen::VectorXd shift_coefficients(const Eigen::VectorXd& c, double phase);

// The m x (nc m) map from the condensed unknowns x (x[j nc + i], condensed_balance.hpp) to the
// harmonic coefficients of own . q(theta) + next . q(theta + phi), m = 2H + 1.
Eigen::MatrixXd cyclic_gap_operator(const Eigen::RowVectorXd& own, const Eigen::RowVectorXd& next, double phase,
                                    int harmonics);

}  // namespace bb::hbm
