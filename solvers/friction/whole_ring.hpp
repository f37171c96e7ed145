// The whole ring of N sectors from one cyclic sector's friction system (friction_system.hpp):
// N copies of its matrices, each cyclic contact's next rows on the next copy, the harmonic load of
// copy j shifted by j phi (a travelling wave of engine order EO: phi = 2 pi EO / N). For verifying
// a cyclic solve against the structure it stands for; the sectors are coupled only by contacts
// (e.g. blades on a rigid disk with a damper between each pair).
#pragma once
#include "friction/friction_system.hpp"

namespace bb::friction {

// Throws std::invalid_argument when sectors < 2 or a cyclic contact's phase is not 2 pi EO / N
// for one engine order.
FrictionModel whole_ring(const FrictionModel& sector, int sectors);

}  // namespace bb::friction
