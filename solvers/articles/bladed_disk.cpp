// Block decomposition of a bladed-disk sector in cylindrical parameters (r, theta, z), mapped to
// Cartesian coordinates node by node. Units: SI (m).
#include "articles/bladed_disk.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "common/constants.hpp"
#include "mesh/hex_block.hpp"

namespace bb {
namespace {

// Cartesian point of the parameters: polar inside the rim; above it the arc length from the blade's
// axis at the rim, R_rim (theta - theta_m), is kept at every radius.
Eigen::Vector3d map_point(const Eigen::Vector3d& p, double rim, double theta_m) {
  const double r = p.x();
  const double angle = r <= rim ? p.y() : theta_m + (p.y() - theta_m) * rim / r;
  return {r * std::cos(angle), r * std::sin(angle), p.z()};
}

HexBlockSpec box(double r0, double r1, double t0, double t1, double chord, int nr, int nt, int nz, ElementType e) {
  HexBlockSpec b;
  const std::array<std::array<double, 2>, 4> face = {{{r0, t0}, {r1, t0}, {r1, t1}, {r0, t1}}};
  for (size_t a = 0; a < 4; ++a) {
    b.corners[a] = Eigen::Vector3d(face[a][0], face[a][1], 0.0);
    b.corners[a + 4] = Eigen::Vector3d(face[a][0], face[a][1], chord);
  }
  b.nx = nr;
  b.ny = nt;
  b.nz = nz;
  b.element = e;
  return b;
}

}  // namespace

double BladedDiskDimensions::sector_angle() const { return kTwoPi / sectors; }
double BladedDiskDimensions::platform_radius() const { return sectors * pitch / kTwoPi; }
double BladedDiskDimensions::rim_radius() const { return platform_radius() - neck_height; }
double BladedDiskDimensions::bore_radius() const { return rim_radius() - disk_depth; }
double BladedDiskDimensions::tip_radius() const { return platform_radius() + platform_thickness + airfoil_length; }

void BladedDiskDimensions::validate() const {
  if (sectors < 3 || sectors > 1000)
    throw DimensionError("sectors", fmt::format("sectors must lie in 3..1000, found {}", sectors));
  for (const BladedDiskDimensionField& f : bladed_disk_dimension_fields())
    require_positive_size(f.name, this->*f.member);
  if (refinement < 1 || refinement > 64)
    throw DimensionError("refinement", fmt::format("refinement must lie in 1..64, found {}", refinement));
  if (chord_divisions < 2 || chord_divisions % 2 != 0)
    throw DimensionError(
        "chord_divisions",
        fmt::format("chord_divisions must be even and >= 2 (a node at mid-chord), found {}", chord_divisions));
  if (airfoil_divisions < 1)
    throw DimensionError("airfoil_divisions",
                         fmt::format("airfoil_divisions must be >= 1, found {}", airfoil_divisions));
  if (!(bore_radius() > 0))
    throw DimensionError("disk_depth",
                         fmt::format("the bore radius N pitch / 2 pi - neck_height - disk_depth = {:.6g} m "
                                     "must be > 0: raise the pitch or the sectors, or thin the disk",
                                     bore_radius()));
  if (!(neck_width < rim_radius() * sector_angle()))
    throw DimensionError("neck_width", fmt::format("neck_width = {} must be narrower than the rim's arc per sector, "
                                                   "{:.6g} m",
                                                   neck_width, rim_radius() * sector_angle()));
  if (!(airfoil_width < neck_width))
    throw DimensionError("airfoil_width", fmt::format("airfoil_width = {} must be narrower than the neck, {}",
                                                      airfoil_width, neck_width));
  if (!(pitch - platform_gap > neck_width))
    throw DimensionError("platform_gap", fmt::format("the platform, pitch - platform_gap = {:.6g} m wide, must be "
                                                     "wider than the neck, {} m",
                                                     pitch - platform_gap, neck_width));
}

std::span<const BladedDiskDimensionField> bladed_disk_dimension_fields() {
  static constexpr BladedDiskDimensionField fields[] = {
      {"pitch", &BladedDiskDimensions::pitch},
      {"chord", &BladedDiskDimensions::chord},
      {"disk_depth", &BladedDiskDimensions::disk_depth},
      {"neck_width", &BladedDiskDimensions::neck_width},
      {"neck_height", &BladedDiskDimensions::neck_height},
      {"platform_thickness", &BladedDiskDimensions::platform_thickness},
      {"platform_gap", &BladedDiskDimensions::platform_gap},
      {"airfoil_width", &BladedDiskDimensions::airfoil_width},
      {"airfoil_length", &BladedDiskDimensions::airfoil_length},
  };
  return fields;
}

std::span<const char* const> bladed_disk_set_names() {
  static constexpr const char* names[] = {"bore",     "cyclic_left",   "cyclic_right",
                                          "tip",      "platform_left", "platform_right",
                                          "tip_lead", "damper_left",   "damper_right"};
  return names;
}

BladedDiskSector bladed_disk_sector(const BladedDiskDimensions& d, ElementType element) {
  d.validate();
  const int r = d.refinement;
  const int nz = d.chord_divisions * r;
  const double alpha = d.sector_angle(), tm = 0.5 * alpha;
  const double R_bore = d.bore_radius(), R_rim = d.rim_radius(), R_pu = d.platform_radius();
  const double R_pt = R_pu + d.platform_thickness, R_tip = d.tip_radius();
  // Angles at the rim of the neck's and the airfoil's faces and of the platform's edges (the
  // platform's arc half-width s_p leaves platform_gap at its underside).
  const double dn = 0.5 * d.neck_width / R_rim, da = 0.5 * d.airfoil_width / R_rim;
  const double dp = 0.5 * (R_pu * alpha - d.platform_gap) / R_rim;
  const std::array<double, 4> strip = {tm - dn, tm - da, tm + da, tm + dn};  // neck | airfoil | neck
  std::vector<HexBlockSpec> blocks;
  auto add = [&](double r0, double r1, double t0, double t1, int nr, int nt) {
    blocks.push_back(box(r0, r1, t0, t1, d.chord, nr, nt, nz, element));
  };
  const int side = 3 * r, across = r;
  // Disk: the side blocks, the neck's strips, the airfoil's strip.
  add(R_bore, R_rim, 0.0, strip[0], 4 * r, side);
  add(R_bore, R_rim, strip[3], alpha, 4 * r, side);
  for (size_t s = 0; s < 3; ++s) {
    add(R_bore, R_rim, strip[s], strip[s + 1], 4 * r, across);
    add(R_rim, R_pu, strip[s], strip[s + 1], 2 * r, across);  // neck
    add(R_pu, R_pt, strip[s], strip[s + 1], 2 * r, across);   // platform under the neck
  }
  add(R_pu, R_pt, tm - dp, strip[0], 2 * r, side);  // platform overhangs
  add(R_pu, R_pt, strip[3], tm + dp, 2 * r, side);
  add(R_pt, R_tip, strip[1], strip[2], d.airfoil_divisions * r, across);  // airfoil

  std::vector<Mesh> parts;
  for (const HexBlockSpec& b : blocks) {
    Mesh part = generate_hex_block(b);
    for (int n = 0; n < part.n_nodes(); ++n)
      part.coords.row(n) = map_point(part.coords.row(n).transpose(), R_rim, tm).transpose();
    parts.push_back(std::move(part));
  }
  BladedDiskSector sector;
  // The thinnest feature is the airfoil's arc per division; rounding of the map is ~1e-16 m.
  sector.mesh = merge_meshes(parts, 1e-9);
  const Mesh& mesh = sector.mesh;

  const double tol = 1e-9 * R_tip;
  auto radius = [&](int n) { return std::hypot(mesh.coords(n, 0), mesh.coords(n, 1)); };
  auto angle = [&](int n) { return std::atan2(mesh.coords(n, 1), mesh.coords(n, 0)); };
  // Distance from the plane through the axis at angle a.
  auto off_plane = [&](int n, double a) { return -std::sin(a) * mesh.coords(n, 0) + std::cos(a) * mesh.coords(n, 1); };
  auto select = [&](const std::string& name, auto&& on) {
    std::vector<int>& nodes = sector.sets[name];
    for (int n = 0; n < mesh.n_nodes(); ++n)
      if (on(n)) nodes.push_back(n);
  };
  select("bore", [&](int n) { return std::abs(radius(n) - R_bore) <= tol; });
  select("cyclic_left", [&](int n) { return std::abs(off_plane(n, 0.0)) <= tol; });
  select("cyclic_right", [&](int n) { return std::abs(off_plane(n, alpha)) <= tol; });
  select("tip", [&](int n) { return std::abs(radius(n) - R_tip) <= tol; });
  // Platform side faces: radius within the platform, arc from the axis at the platform's edge.
  auto on_platform_edge = [&](int n, double sign) {
    const double rr = radius(n);
    const double arc = (angle(n) - tm) * rr;  // arc from the blade's axis, kept by the map
    return rr >= R_pu - tol && rr <= R_pt + tol && std::abs(arc - sign * dp * R_rim) <= tol;
  };
  select("platform_left", [&](int n) { return on_platform_edge(n, -1.0); });
  select("platform_right", [&](int n) { return on_platform_edge(n, 1.0); });
  auto nearest = [&](const std::string& name, const Eigen::Vector3d& parameters) {
    const Eigen::Vector3d p = map_point(parameters, R_rim, tm);
    int best = 0;
    for (int n = 1; n < mesh.n_nodes(); ++n)
      if ((mesh.coords.row(n).transpose() - p).norm() < (mesh.coords.row(best).transpose() - p).norm()) best = n;
    sector.sets[name] = {best};
  };
  nearest("tip_lead", {R_tip, strip[1], 0.0});
  nearest("damper_left", {R_pu, tm - dp, 0.5 * d.chord});
  nearest("damper_right", {R_pu, tm + dp, 0.5 * d.chord});
  return sector;
}

}  // namespace bb
