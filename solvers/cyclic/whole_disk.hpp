// The whole structure from one sector: N copies turned about the z axis by multiples of 2 pi / N
// and merged at their common faces, for verifying a cyclic analysis against the structure it
// stands for. Each node set becomes the union of its copies, and a one-node set (a point) also
// names each copy's node "<name>@<j>" (copy j turned by j 2 pi / N); constraints are kept; loads and
// contact pairs are not carried over (a modal verification needs neither).
#pragma once
#include "model/model.hpp"

namespace bb {

// `tolerance` [m]: nodes of neighbouring copies closer than this are one node. Throws InputError
// when the model has loads or contact pairs.
Model whole_from_sector(const Model& sector, int sectors, double tolerance);

}  // namespace bb
