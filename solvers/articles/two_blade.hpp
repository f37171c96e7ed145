// The two-blade test article of Michelis (MSc thesis, UIC 2014, section 3.1, Table VI): two
// dummy blades, two wedges and a fixture, all extruded through the same thickness, built from
// mapped hexahedral blocks that merge_meshes glues at coincident nodes.
//
// The thesis gives almost no dimensions (its figures are missing); every default below is the
// nominal value of a reconstruction whose sources are quoted, dimension by dimension, in
// cases/thesis/table06_glued_modal.toml: [T] stated in the thesis, [D] derived from stated
// values, [A] assumed, [F] fitted to Table VI frequencies with a scratch hex20 model.
//
// Frame: x tangential (blade 1 -> blade 2), y radial (root -> tip), z through the thickness.
// Origin at the bottom-left corner of blade 1's root on the z = 0 face; blade 2 is blade 1
// shifted by the pitch p along x. Units: SI (m, degrees only for beta_deg).
//
// Vertical levels (nominal values in brackets):
//   Y0 = -(h_w + t_fb) fixture base (clamped)  [-0.030]
//   Y1 = -h_w          cavity floor = wedge bottom  [-0.010]
//   Y2 = 0             wedge top = root bottom
//   Y3 = H_r           root top = underside of the fixture arms  [0.015]
//   Y4 = H_r + t_a     top of the fixture  [0.025]
//   Y5 = H_r + H_n     lower end of the platform contact faces, at the neck  [0.031]
//   Y6 = Y5 + c        upper end of the contact faces, c = (B_p - w_n)/2 tan(beta)  [0.0435]
//   Y7 = Y6 + e_p      platform top = airfoil root  [0.0635]
//   Y8 = Y7 + L_a      tip  [0.2200]
#pragma once
#include <Eigen/Dense>

#include <array>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "articles/dimension_error.hpp"
#include "mesh/hex_block.hpp"

namespace bb {

struct TwoBladeDimensions {
  // Blade (per blade, x measured from the left face of its root) [m].
  double t = 0.050;        // thickness (z) of every body [T] Fig. 2.21, "constant thickness"
  double B_r = 0.035;      // root width (x) [T] planar node 2 = (0.035, 0)
  double H_r = 0.015;      // root height (y) [T] planar node 3 = (0.035, 0.015)
  double x_n1 = 0.0225;    // right face of the neck [T] planar node 4 = (0.0225, 0.015)
  double w_n = 0.010;      // neck width; the neck spans [x_n1 - w_n, x_n1] [D] symmetric root
  double H_n = 0.016;      // neck height, root top to the lower end of the contact faces [A][F]
  double B_p = 0.035;      // platform (central body) width [A] = B_r
  double beta_deg = 45.0;  // platform contact faces, angle from the x axis [deg] [A]
  double e_p = 0.020;      // platform lip: vertical face from the contact face to the top [A][F]
  double w = 0.0054;       // airfoil width (x) at its root [A][F]
  double w_t = 0.0;        // airfoil width at the tip; 0 = w (untapered) [A]
  double L_a = 0.1565;     // airfoil length, platform top to tip [D][F] f1 on Table VI
  // Fixture and wedges [m].
  double p = 0.050;     // blade pitch (x offset of blade 2) [A]
  double t_a = 0.010;   // fixture arm thickness above the root shoulders [A]
  double g_s = 0.0025;  // clearance neck / arm slot, each side (not glued) [A]
  double g_r = 0.0025;  // clearance root and wedge sides / cavity walls (not glued) [A]
  double h_w = 0.010;   // wedge height (a B_r x h_w x t block under each root) [A]
  double t_fb = 0.020;  // fixture base thickness below the cavities [A]
  double m_f = 0.015;   // outer side-wall thickness of the fixture [A]
  // Mesh density.
  int refinement = 1;           // r: every block's in-plane divisions are multiplied by r
  int thickness_divisions = 0;  // divisions through t; 0 = 4 r (the thesis's SAMS 3D model: 4)
  int airfoil_divisions = 8;    // divisions along L_a at r = 1 (times r); 8 puts a node at L_a / 4 (F)

  // Derived quantities (no validation; call validate() first).
  double x_n0() const { return x_n1 - w_n; }       // left face of the neck
  double x_c() const { return x_n1 - 0.5 * w_n; }  // blade axis: neck, platform and airfoil centre
  double tip_width() const { return w_t > 0 ? w_t : w; }
  double contact_rise() const;  // c = (B_p - w_n)/2 tan(beta)
  int nz() const { return thickness_divisions > 0 ? thickness_divisions : 4 * refinement; }
  std::array<double, 9> levels() const;                           // Y0..Y8 of the header
  double fixture_left_x() const { return -g_r - m_f; }            // XF0, clamped face
  double fixture_right_x() const { return p + B_r + g_r + m_f; }  // XF1, clamped face

  // Throws DimensionError naming the first dimension that makes the geometry impossible
  // (non-positive size, overlapping bodies, a clearance that closes, a point with no node).
  void validate() const;
};

// Every double member by name, in declaration order: what a case's [mesh.dimensions] may set.
struct TwoBladeDimensionField {
  const char* name;
  double TwoBladeDimensions::*member;
};
std::span<const TwoBladeDimensionField> two_blade_dimension_fields();

enum class TwoBladeBody { blade1, blade2, wedge1, wedge2, fixture };

struct TipFace {
  double y = 0.0;                   // tip level
  double x_min = 0.0, x_max = 0.0;  // airfoil faces at the tip
};

struct TwoBladeArticle {
  std::vector<HexBlockSpec> blocks;  // blades, wedges, fixture; merge to glue them
  std::vector<TwoBladeBody> body;    // body of each block
  std::vector<std::string> label;    // e.g. "blade1.PR", for messages
  // Master nodes of the thesis, all at mid-thickness z = t/2: T1, T2 (tip centres, L1035),
  // F (right face of blade 2's airfoil at L_a / 4, force along x; height assumed), L1, L2 (lower
  // and upper point on blade 1's right contact face, at 1/4 and 3/4 of it), R (midpoint of
  // blade 2's left contact face); and C1, C2, the tip corners (x_max, tip, z = 0) of blades 1
  // and 2, off the torsion axis. Each is a node of the mesh.
  std::map<std::string, Eigen::Vector3d> points;
  double fixture_base_y = 0.0;     // Y0: clamped base face
  double fixture_left_x = 0.0;     // XF0: clamped lateral face
  double fixture_right_x = 0.0;    // XF1: clamped lateral face
  std::array<TipFace, 2> tips;     // blade 1, blade 2
  std::array<double, 9> levels{};  // Y0..Y8
};

// Throws DimensionError (validate()) for impossible geometry, std::invalid_argument for a
// non-solid element type.
TwoBladeArticle two_blade_article(const TwoBladeDimensions& dims, ElementType element);

// Names of the node sets a two-blade mesh defines by itself (cases/build_model): the points
// above, "fixture_base", "fixture_left", "fixture_right", "tip1", "tip2".
std::span<const char* const> two_blade_set_names();

// The surfaces of the root interfaces a mesh with glue = false names for contact pairs (b = 1, 2):
// "root<b>_top" (the blade's root shoulders) under "arm<b>_bottom" (the fixture arms above them),
// "root<b>_bottom" (the blade's root base) on "wedge<b>_top". The wedges stay glued to the fixture.
std::span<const char* const> two_blade_contact_set_names();

}  // namespace bb
