// What a cyclic modal analysis computes: the modes of a cyclically symmetric structure about z
// from one sector, per nodal diameter, optionally verified against the whole structure, and the
// engine orders whose resonances it lists.
#pragma once
#include <string>
#include <vector>

#include "common/source_location.hpp"
#include "linalg/modal_solver.hpp"

namespace bb {

struct CyclicModalSpec {
  int sectors = 0;                   // N: the sector spans 360 / N degrees
  std::string left = "cyclic_left";  // node sets of the two cyclic faces
  std::string right = "cyclic_right";
  double face_tolerance = 1e-9;      // [m] a right node lies this close to a left node's image
  int families = 6;                  // modes per nodal diameter
  std::vector<int> nodal_diameters;  // ascending, within 0..N/2; empty = all
  ModalOptions options;              // n_modes unused (families decides)
  int threads = 0;                   // nodal diameters solved at once; 0 = one per core
  // Build the whole structure (N turned copies merged) and solve it too: its spectrum below the
  // lowest top family against the union of the nodal diameters', and the Sturm counts.
  bool whole = false;
  // Interference diagram: the speeds at which engine order EO meets a family of the nodal
  // diameter it excites (ND = EO mod N folded into 0..N/2), up to max_speed_rpm.
  std::vector<int> engine_orders;
  double max_speed_rpm = 0.0;
  // Campbell diagram: the nodal diameters' families at these speeds (ascending, from 0) with the
  // centrifugal pre-stress and spin softening (cyclic/cyclic_campbell.hpp), and the engine-order
  // crossings between them (with engine orders, for the nodal diameters they excite only). Empty:
  // the structure at rest only.
  std::vector<double> speeds_rpm;
  SourceLocation at;
};

}  // namespace bb
