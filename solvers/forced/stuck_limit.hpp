// The stuck limit: the friction model with every contact held by its springs (kn on the normal, kt
// on the tangential direction; eq 3.51), the linear response its friction response tends to at
// small loads. Solved here once for the harmonic balance's limit tables and the time sweeps' linear
// columns.
#pragma once
#include <Eigen/Dense>

#include "friction/friction_system.hpp"

namespace bb {

// The stuck model's response to the harmonic load (harmonic 1) at omega [rad/s]: a cyclic sector's
// at harmonic 1's nodal diameter. n complex amplitudes [m].
Eigen::VectorXcd stuck_response(const friction::FrictionModel& model, double omega);

}  // namespace bb
