// What a contact-modal analysis computes (thesis section 3.2): for every interference and normal
// penalty factor of a grid, the static state of the model's contact pairs pressed by the
// interference, and the modes linearized about it: closed contact points as springs (normal
// penalty, and the sticking tangential one), open points free, and the stress stiffening of the
// pre-stress. Optionally the same modes with every pair glued, the limit of stiff closed contact.
#pragma once
#include <vector>

#include "common/source_location.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {

struct ContactModalSpec {
  int modes = 8;
  std::vector<double> interferences;    // initial overlap of the pairs marked `interference` [m]
  std::vector<double> penalty_factors;  // FKN: kn = FKN E / h, h the contact facet's size [-]
  bool sticking = true;                 // tangential: sticking (kt = tangential_ratio kn) or frictionless
  double tangential_ratio = 1.0;        // kt / kn, both at the static state's pressure
  double roughness = 0.0;               // sigma of the stiffening normal law [m]; 0: linear (contact/surface_contact.hpp)
  bool prestress = true;                // geometric stiffness of the static contact stresses
  bool glued_reference = true;          // also the modes with every pair's facing nodes tied
  int max_status_iterations = 50;       // of each static contact solve (contact/static_contact.hpp)
  // The grid point whose contact state (gap, pressure, status per point) is written: indices into
  // the two lists; default the largest interference at the last penalty factor.
  int state_interference = -1, state_penalty = -1;
  ModalOptions options;
  SourceLocation at;
};

}  // namespace bb
