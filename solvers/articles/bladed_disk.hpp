// One sector of a bladed disk: a disk segment with a blade like the two-blade article's (neck,
// platform, airfoil) glued to its rim, meshed from hexahedral blocks in cylindrical coordinates so
// that its two cyclic faces (the planes at 0 and at the sector angle through the axis) match by the
// sector rotation. cyclic/whole_disk builds the whole disk from it by rotation.
//
// Frame: z the disk axis (the blade's chord runs along z), the sector spans the angles [0, 2 pi / N]
// from the x axis, the blade stands at the middle angle. Units: SI (m).
//
// The thesis's article is two blades on a fixture (Table VI); it gives no disk. Each dimension
// below says where its default comes from: [T] the two-blade article's value
// (articles/two_blade.hpp, sourced there), [A] assumed, with the reason next to it.
//
// Above the rim the map keeps the arc length from the blade's axis: a point at arc s from the
// axis at the rim stays at arc s at every radius. The blade is then a plate of constant thickness
// and the platform's edges move apart with the pitch, r 2 pi / N, as on a real disk.
#pragma once
#include <Eigen/Dense>

#include <map>
#include <span>
#include <string>
#include <vector>

#include "articles/dimension_error.hpp"
#include "mesh/mesh.hpp"

namespace bb {

struct BladedDiskDimensions {
  int sectors = 24;                   // N [A]: a turbine stage's count; the pitch below then puts the rim at 0.175 m
  double pitch = 0.050;               // blade pitch at the platform's underside [T] the two-blade article's p
  double chord = 0.050;               // axial width of blade and disk [T] the article's thickness t
  double disk_depth = 0.040;          // rim radius minus bore radius [A] a thin web-less disk, stiff against the blade
  double neck_width = 0.010;          // tangential width of the neck [T] w_n
  double neck_height = 0.016;         // rim to the platform's underside [T] H_n
  double platform_thickness = 0.010;  // radial [A] about the article's lip e_p / 2
  double platform_gap = 0.002;        // between neighbouring platforms at their underside [A] where a damper sits
  double airfoil_width = 0.0054;      // tangential thickness of the airfoil [T] w
  double airfoil_length = 0.1565;     // platform top to tip [T] L_a
  // Mesh density.
  int refinement = 1;         // every division below is multiplied by it
  int chord_divisions = 4;    // along z (even: a node at mid-chord); times the refinement
  int airfoil_divisions = 8;  // along the airfoil's span; times the refinement

  double sector_angle() const;     // 2 pi / N [rad]
  double platform_radius() const;  // underside of the platform: N pitch / 2 pi
  double rim_radius() const;       // platform_radius - neck_height
  double bore_radius() const;      // rim_radius - disk_depth
  double tip_radius() const;       // platform top + airfoil_length

  // Throws DimensionError naming the first member that makes the geometry impossible.
  void validate() const;
};

// Every double member by name: what a case's [mesh.dimensions] may set.
struct BladedDiskDimensionField {
  const char* name;
  double BladedDiskDimensions::*member;
};
std::span<const BladedDiskDimensionField> bladed_disk_dimension_fields();

struct BladedDiskSector {
  Mesh mesh;
  // "bore" (clamped in the cases), "cyclic_left" and "cyclic_right" (the faces at 0 and at the
  // sector angle), "tip" (the airfoil's tip face), "platform_left" / "platform_right" (the
  // platform's side faces, where an underplatform damper touches), and single nodes
  // "tip_lead" (tip, z = 0, the airfoil's face towards angle 0), "damper_left" / "damper_right"
  // (the platform's underside edges at mid-chord).
  std::map<std::string, std::vector<int>> sets;
};

// Throws DimensionError (validate()), std::invalid_argument for a non-solid element type.
BladedDiskSector bladed_disk_sector(const BladedDiskDimensions& dims, ElementType element);

std::span<const char* const> bladed_disk_set_names();

}  // namespace bb
