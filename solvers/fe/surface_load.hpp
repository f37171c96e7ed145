// Work-equivalent ("consistent") nodal forces of a distributed load on one facet of an element,
// f_a = integral over the facet of N_a t dA (e.g. Cook, Malkus, Plesha & Witt, Concepts and
// Applications of FEA, 4th ed., sec. 3.9 and 6.9), with the facet's own shape functions, so that a
// curved (hex20) face and its mid-edge nodes get their share: on a flat 8-node face under a uniform
// pressure the corners carry -1/12 and the mid-edge nodes 1/3 of the force. Pure functions. SI units.
//
// The load per area is t = traction - pressure n, n the unit outward normal: a positive pressure
// pushes into the body, a negative one pulls (a suction). Outward: a plane element's edge runs
// counterclockwise around it, n is its right-hand normal; a face's corners run counterclockwise seen
// from outside, n = dx/dxi x dx/deta / |.| (mesh/element_topology.hpp orders them so).
#pragma once
#include <Eigen/Dense>

namespace bb::fe {

// A plane element's straight 2-node edge (rows: its nodes), over its length times `thickness`.
// Exact (closed form). Result (fx1, fy1, fx2, fy2) [N].
Eigen::Matrix<double, 4, 1> edge2_load(const Eigen::Matrix<double, 2, 2>& xy, double thickness, double pressure,
                                       const Eigen::Vector2d& traction);

// A bilinear 4-node face (hex8, hex8i), 2x2 Gauss: exact for a pressure on any (also warped) face
// and for a traction on a parallelogram. Result (fx1, fy1, fz1, fx2, ...) [N].
Eigen::Matrix<double, 12, 1> quad4_face_load(const Eigen::Matrix<double, 4, 3>& xyz, double pressure,
                                             const Eigen::Vector3d& traction);

// An 8-node serendipity face (hex20: corners, then mid-edge nodes of edges 1-2, 2-3, 3-4, 4-1),
// 3x3 Gauss: exact for a pressure or traction on a flat parallelogram face, and of the element's own
// accuracy on a curved one. Result (fx1, fy1, fz1, fx2, ...) [N].
Eigen::Matrix<double, 24, 1> quad8_face_load(const Eigen::Matrix<double, 8, 3>& xyz, double pressure,
                                             const Eigen::Vector3d& traction);

}  // namespace bb::fe
