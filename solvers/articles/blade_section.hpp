// The single blade of the thesis's chapter 2 (sections 2.1.4.1.3-2.1.4.2.1, Figs 2.13, 2.22, 2.30):
// the outline of one blade of the two-blade article (articles/two_blade.hpp: root, neck, platform
// with its two 45-degree damper faces, lip, airfoil) in its x-y plane, meshed the three ways the
// thesis does. The thesis's figures are missing; what it states is reproduced exactly:
//   q4    rectangles everywhere and one triangle in each platform corner (the damper faces): "168
//         elements, 166 plates and 2 triangles ... the system has 233 nodes" (L722);
//   cst   triangles only, "112 elements" (L800): every rectangle split in two plus the two corners;
//   hex8  "196 elements" with "4 elements along the thickness", the two corners "avoided" (L858-861).
// The divisions that give those counts are in blade_section_divisions() and argued there.
// Frame: x across the blade, y radial (root at y = 0, tip at y = Y8), z through the thickness.
#pragma once
#include <map>
#include <span>
#include <string>
#include <vector>

#include "articles/two_blade.hpp"
#include "mesh/mesh.hpp"

namespace bb {

struct BladeSectionDivisions {
  int root_side_columns = 1;  // across each root shoulder [0, x_n0] and [x_n1, B_r]
  int root_rows = 3;          // root height H_r
  int neck_rows = 8;          // neck height H_n
  int lip_rows = 5;           // platform lip e_p
  int airfoil_columns = 2;    // airfoil width w (the neck has these + 2 columns)
  int airfoil_rows = 41;      // airfoil length L_a
  int layers = 4;             // hex8: through the thickness t
};

// The divisions of the thesis's three meshes (see the header): q4 166 + 2 CST / 233 nodes, cst 112,
// hex8 196.
BladeSectionDivisions blade_section_divisions(ElementType element);

struct BladeSection {
  Mesh mesh;
  // Node sets: "root" (the root's base and flanks, clamped to the rotor: planar nodes 1-3 of the
  // Presams list, Fig. 2.19, are constrained and node 4 at the neck is free), "tip" (the airfoil's
  // trailing tip corner, x = x_c + w/2, y = Y8; mid-thickness in 3D), "mid" (the node of the same
  // face nearest to mid-airfoil), "airfoil" (every node with y >= Y7).
  std::map<std::string, std::vector<int>> sets;
};

// Names of the node sets blade_section defines itself.
std::span<const char* const> blade_section_set_names();

// element: q4, cst or hex8. Node ids 1-4 are the Presams nodes of Fig. 2.19 (0, 0), (B_r, 0),
// (B_r, H_r), (x_n1, H_r) in plane meshes. Throws DimensionError for impossible dimensions,
// std::invalid_argument for an element type or divisions the generator does not make.
BladeSection blade_section(const TwoBladeDimensions& dims, const BladeSectionDivisions& divisions, ElementType element);

}  // namespace bb
