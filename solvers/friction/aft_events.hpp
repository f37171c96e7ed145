// Event-resolved AFT of one Jenkins contact point (the same law and layout as aft.hpp): the slider
// is marched in continuous time over the trigonometric polynomials u(theta), v(theta), each stick /
// slip / lift-off transition is located by root finding (the samples only bracket them), and the
// force coefficients are integrated exactly between transitions: within a piece T and N are linear
// in u and v, so each piece contributes the basis's integral and Gram matrix over it, in closed
// form. The coefficients are then exact to rounding whatever the sample count, and they and their
// Jacobian are continuous in the displacement coefficients and the law parameters wherever no
// transition appears or vanishes (a grazing): the Newton solves of the harmonic balance see a
// smooth residual, where the sampled AFT's error falls as 1 / n and jumps as a transition crosses
// a sample.
//
// Why the Jacobian needs no boundary terms: T and N are continuous at every transition, and the
// stuck slider a transition leaves is stationary in the transition's position (slip ends where
// d(u -+ mu N / kt)/dtheta = 0), except after a lift-off, whose closing point theta_c (N = 0) moves
// the stuck slider u(theta_c) by u'(theta_c) d theta_c; that term is carried.
#pragma once
#include "friction/aft.hpp"

namespace bb::friction {

// As aft_jenkins (inputs checked by it). options.samples is the number of sample intervals that
// bracket the transitions: two of one kind inside one interval (a stick or lift-off phase shorter
// than 2 pi / n that starts and ends within it) are not seen.
[[nodiscard]] AftResult aft_jenkins_events(const PointParameters& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                           const AftOptions& options);

}  // namespace bb::friction
