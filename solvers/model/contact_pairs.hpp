// Contact pairs of a case checked against its mesh and turned into facing facets.
#pragma once
#include "model/model.hpp"
#include "model/model_spec.hpp"

namespace bb {

// Every boundary facet of the contact set faces a coincident boundary facet of the target set (the
// target may be larger). Throws InputError naming the pair's line for an unknown or facet-less set,
// a node in both sets (glued, not in contact), or a contact facet with no coincident target facet.
ContactPair build_contact_pair(const Model& model, const ContactPairSpec& spec);

}  // namespace bb
