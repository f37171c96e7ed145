// Export of a 3D model as a CalculiX (ccx) input deck, to run an established solver on the
// identical mesh (bench/calculix_compare.sh). SI units, written as they are in the model.
#pragma once
#include <filesystem>

#include "model/model.hpp"

namespace bb {

// Writes an ASCII .inp deck for a *FREQUENCY step asking for the lowest n_modes modes:
// *NODE (number = internal index + 1), *ELEMENT per block (hex20 -> C3D20, hex8 -> C3D8,
// hex8i -> C3D8I; our node order is CalculiX's, see mesh/mesh.hpp), one *NSET and *BOUNDARY
// per constraint, *MATERIAL (*ELASTIC, *DENSITY), *SOLID SECTION, *STEP / *FREQUENCY.
// Loads are left out: a frequency step does not use them. Mode shapes are not requested
// (no *NODE FILE), so ccx writes the eigenvalues to the .dat file only.
// Throws InputError for a 2D mesh, a nonzero prescribed displacement, or n_modes < 1, and
// std::runtime_error when the file cannot be written.
//
// With `contact`, the model's contact pairs become ccx face-to-face penalty contact (*CONTACT PAIR,
// TYPE=SURFACE TO SURFACE; slave = the contact surface, master = the target), a linear
// pressure-overclosure of slope kn = FKN E / h per group of equal-sized faces (one interaction per
// group), sticking friction of slope kt (a friction coefficient of 1e3), and *CLEARANCE = -interference
// on the interference pairs; a *STATIC step loads the interference and the *FREQUENCY step is a
// PERTURBATION of it (ccx linearizes its contact there). Throws InputError for the rough law (ccx's
// linear law is the only common one).
struct CalculixContact {
  double interference = 0.0;    // [m]
  double penalty_factor = 1.0;  // FKN
  double tangential_ratio = 1.0;
  bool sticking = true;
  double roughness = 0.0;
};
//
// With `cyclic`, the model is one sector of a structure of `sectors` about the z axis: the two
// faces are tied by *TIE, CYCLIC SYMMETRY (the right face dependent, without its constrained
// nodes, which ccx refuses on the dependent side of its MPCs; their partners are constrained
// alike), *CYCLIC SYMMETRY MODEL, and *SELECT CYCLIC SYMMETRY MODES picks the nodal diameters.
// ccx returns each nodal diameter's modes twice (cosine and sine), so ask for twice the families.
struct CalculixCyclic {
  int sectors = 0;
  std::string left, right;  // node sets of the cyclic faces
  int nd_min = 0, nd_max = 0;
};
void write_calculix_frequency_deck(const Model& model, int n_modes, const std::filesystem::path& inp,
                                   const CalculixContact* contact = nullptr, const CalculixCyclic* cyclic = nullptr);

}  // namespace bb
