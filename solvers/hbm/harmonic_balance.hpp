// Multi-DOF harmonic balance of a small linear model with point Jenkins friction contacts (thesis
// eqs 3.10-3.35): one include for its callers. The parts, one job each:
//   hbm/friction_system.hpp    the model (M, C, K, contacts, loads) and its condensation onto the contact DOFs
//   hbm/condensed_balance.hpp  R(x, omega) = L(omega) x + g(x) - b(omega) on the contact DOFs, recovery of all DOFs
//   hbm/fixed_frequency.hpp    R = 0 at one omega (damped Newton from several starts)
//   hbm/continuation.hpp       the path in (x, omega) through folds (pseudo-arclength)
//   hbm/cycle_energy.hpp       the energy balance of a solution over one cycle
#pragma once
#include "friction/friction_system.hpp"
#include "hbm/condensed_balance.hpp"
#include "hbm/continuation.hpp"
#include "hbm/cycle_energy.hpp"
#include "hbm/fixed_frequency.hpp"
