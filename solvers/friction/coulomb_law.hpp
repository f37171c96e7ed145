// Coulomb's law: a stuck contact held rigidly (no tangential spring), slip at |T| = mu N, lift-off.
// The exact flow of shooting integrates it as such (timeint/piecewise_flow.hpp: a stuck contact is
// a constraint whose force is linear in the state), the flow that reproduces Den Hartog's
// oscillator. The frequency domain and the Newmark step have no rigid stick: there the law is
// regularised by the point's kt, i.e. it is the Jenkins law, which tends to Coulomb's as kt grows
// (describe() says so in every report). Units: SI.
#pragma once
#include "friction/friction_law.hpp"

namespace bb::friction {

const std::shared_ptr<const FrictionLaw>& coulomb_law();

}  // namespace bb::friction
