// Models shared by the FFRF tests (ffrf_*_test.cpp): straight cantilever beams clamped at their root
// on a rotor turning about z, as plane-stress (q4, cst) or solid (hex8, hex8i, hex20) meshes, and the
// chain RotatingBody -> ElasticBasis -> ProjectedBody. Units: SI.
#pragma once
#include <Eigen/Dense>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ffrf/elastic_basis.hpp"
#include "ffrf/rotating_body.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/mapped_quad.hpp"
#include "model/model.hpp"

namespace bb::test {

// A straight beam from x = root_radius to root_radius + length, its cross-section centred on the
// x axis (width along y, depth along z in 3D), clamped at the root: the rotor turns about z, so y
// is the in-plane (chordwise, lag) direction and z the flapwise one.
struct BeamSpec {
  double length = 1.0, width = 0.05, depth = 0.05;  // [m]; 2D: width = height in the plane, depth = thickness
  double root_radius = 0.0;                         // [m]
  double youngs_modulus = 2.0e11, poisson_ratio = 0.0, density = 7800.0;
  ElementType element = ElementType::q4;
  int nx = 20, ny = 1, nz = 1;  // divisions along x, y (width), z (depth, 3D only)
};

inline std::vector<int> nodes_at_x(const Mesh& mesh, double x, double tol = 1e-9) {
  std::vector<int> out;
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (std::abs(mesh.coords(n, 0) - x) < tol) out.push_back(n);
  return out;
}

inline int nearest_node(const Mesh& mesh, const Eigen::VectorXd& p) {
  int best = 0;
  double d = 1e300;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const double dn = (mesh.coords.row(n).transpose() - p).norm();
    if (dn < d) d = dn, best = n;
  }
  return best;
}

inline Model beam_model(const BeamSpec& b) {
  Model model;
  const double x0 = b.root_radius, x1 = b.root_radius + b.length;
  if (element_dimension(b.element) == 2) {
    MappedQuadSpec q;
    q.corners = {Eigen::Vector2d(x0, -0.5 * b.width), Eigen::Vector2d(x1, -0.5 * b.width),
                 Eigen::Vector2d(x1, 0.5 * b.width), Eigen::Vector2d(x0, 0.5 * b.width)};
    q.nx = b.nx;
    q.ny = b.ny;
    q.element = b.element;
    model.mesh = generate_mapped_quad(q);
  } else {
    HexBlockSpec h;
    const double y = 0.5 * b.width, z = 0.5 * b.depth;
    h.corners = {Eigen::Vector3d(x0, -y, -z), Eigen::Vector3d(x1, -y, -z), Eigen::Vector3d(x1, y, -z),
                 Eigen::Vector3d(x0, y, -z),  Eigen::Vector3d(x0, -y, z),  Eigen::Vector3d(x1, -y, z),
                 Eigen::Vector3d(x1, y, z),   Eigen::Vector3d(x0, y, z)};
    h.nx = b.nx;
    h.ny = b.ny;
    h.nz = b.nz;
    h.element = b.element;
    model.mesh = generate_hex_block(h);
  }
  model.section = {.youngs_modulus = b.youngs_modulus,
                   .poisson_ratio = b.poisson_ratio,
                   .density = b.density,
                   .thickness = element_dimension(b.element) == 2 ? b.depth : 0.0};
  model.node_sets["root"] = nodes_at_x(model.mesh, x0);
  model.node_sets["tip"] = nodes_at_x(model.mesh, x1);
  std::vector<Direction> all{0, 1};
  if (model.mesh.dim == 3) all.push_back(2);
  model.constraints = {{"root", all, 0.0}};
  return model;
}

// Global DOF of the node nearest to the tip centre, direction d.
inline int tip_dof(const Model& model, const BeamSpec& b, int d) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(model.mesh.dim);
  p[0] = b.root_radius + b.length;
  return nearest_node(model.mesh, p) * model.mesh.dim + d;
}

// Everything an FFRF solver needs, kept alive together (ProjectedBody refers to body and basis).
struct FfrfSetup {
  Model model;
  std::unique_ptr<ffrf::RotatingBody> body;
  std::unique_ptr<ffrf::ElasticBasis> basis;
  std::unique_ptr<ffrf::ProjectedBody> projected;
};

inline FfrfSetup ffrf_setup(Model model, const ffrf::ElasticBasisOptions& basis = {},
                            const ffrf::RotationAxis& axis = {}) {
  FfrfSetup s;
  s.model = std::move(model);
  s.body = std::make_unique<ffrf::RotatingBody>(ffrf::build_rotating_body(s.model, axis));
  s.basis = std::make_unique<ffrf::ElasticBasis>(ffrf::make_elastic_basis(*s.body, basis));
  s.projected = std::make_unique<ffrf::ProjectedBody>(ffrf::project(*s.body, *s.basis));
  return s;
}

inline ffrf::ElasticBasisOptions modal_basis(int n_modes, bool static_correction = true) {
  ffrf::ElasticBasisOptions o;
  o.kind = ffrf::BasisKind::modal;
  o.n_modes = n_modes;
  o.static_correction = static_correction;
  return o;
}

}  // namespace bb::test
