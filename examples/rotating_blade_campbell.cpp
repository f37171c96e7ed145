// A blade (the bar of the other examples, clamped at the rotation axis) spinning about z: its
// Campbell diagram, where the lines of the engine orders cross it, and the flapwise frequency
// against the published values for a rotating cantilever.
//
// Spinning stiffens the blade out of the plane of rotation (the centrifugal tension) and softens it
// in that plane (spin softening), so the bending pair at rest splits. bladebench writes the body's
// motion in a floating frame of reference (thesis ch. 2) and linearizes it about the steady spin.
#include <bladebench/ffrf/elastic_basis.hpp>
#include <bladebench/ffrf/rotating_body.hpp>
#include <bladebench/ffrf/rotating_modes.hpp>
#include <bladebench/mesh/hex_block.hpp>
#include <bladebench/model/model.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

int main() {
  const double length = 0.3, side = 0.02, E = 2.1e11, rho = 7850.0;
  bb::HexBlockSpec block;  // along x from the axis; the root face's centre on the z axis
  block.corners = {Eigen::Vector3d(0, -side / 2, -side / 2),
                   {length, -side / 2, -side / 2},
                   {length, side / 2, -side / 2},
                   {0, side / 2, -side / 2},
                   {0, -side / 2, side / 2},
                   {length, -side / 2, side / 2},
                   {length, side / 2, side / 2},
                   {0, side / 2, side / 2}};
  block.nx = 12;
  block.ny = block.nz = 2;
  block.element = bb::ElementType::hex20;
  bb::Model model;
  model.mesh = bb::generate_hex_block(block);
  model.section = {E, 0.3, rho, 0.0};
  std::vector<int> root;
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    if (model.mesh.coords(n, 0) < 1e-12) root.push_back(n);
  model.node_sets["root"] = root;
  model.constraints.push_back({"root", {0, 1, 2}, 0.0});

  // The rotating body, its 12 lowest modes at rest (with static correction shapes) as the elastic
  // coordinates, and its operators projected on them.
  const bb::ffrf::RotatingBody body = bb::ffrf::build_rotating_body(model);  // axis z through the origin
  const bb::ffrf::ElasticBasis basis =
      bb::ffrf::make_elastic_basis(body, {.kind = bb::ffrf::BasisKind::modal, .n_modes = 12});
  const bb::ffrf::ProjectedBody projected = bb::ffrf::project(body, basis);

  // Speeds in units of sqrt(E I / (rho A L^4)), the published tables' dimensionless speed.
  const double unit = std::sqrt(E * side * side / (12 * rho)) / (length * length);  // [rad/s]
  std::vector<double> speeds;
  for (double s : {0.0, 1.0, 2.0, 3.0, 4.0}) speeds.push_back(s * unit);
  const bb::ffrf::CampbellDiagram diagram = bb::ffrf::campbell_diagram(projected, speeds, {.n_modes = 4});
  for (size_t i = 0; i < speeds.size(); ++i)
    std::printf("%7.0f rpm: %8.2f %8.2f %8.2f %8.2f Hz%s\n", speeds[i] * 60 / (2 * std::numbers::pi),
                diagram.frequencies_hz(static_cast<Eigen::Index>(i), 0),
                diagram.frequencies_hz(static_cast<Eigen::Index>(i), 1),
                diagram.frequencies_hz(static_cast<Eigen::Index>(i), 2),
                diagram.frequencies_hz(static_cast<Eigen::Index>(i), 3), diagram.stable[i] ? "" : "  unstable");
  for (const bb::ffrf::EngineOrderCrossing& c :
       bb::ffrf::engine_order_crossings(projected, diagram, {1, 2, 3, 4}, {.n_modes = 4}))
    std::printf("engine order %d meets mode %d at %.0f rpm, %.2f Hz\n", c.engine_order, c.mode,
                c.speed * 60 / (2 * std::numbers::pi), c.frequency_hz);

  // At speed 4: flap (z) 5.5850 (Hamza-Cherif & Houmat 2004, Euler-Bernoulli, hub radius 0), chord
  // (y) sqrt(flap^2 - speed^2) by spin softening. This bar is stubbier (L / h = 15): within 1.5 %.
  const double to_unit = 2 * std::numbers::pi / unit;
  const double chord = diagram.frequencies_hz(4, 0) * to_unit, flap = diagram.frequencies_hz(4, 1) * to_unit;
  const double chord_ref = std::sqrt(5.5850 * 5.5850 - 16.0);
  std::printf("speed 4: flap %.4f (published 5.5850, %+.2f %%), chord %.4f (%.4f, %+.2f %%)\n", flap,
              100 * (flap / 5.5850 - 1), chord, chord_ref, 100 * (chord / chord_ref - 1));
  const bool ok = std::abs(flap / 5.5850 - 1) < 0.015 && std::abs(chord / chord_ref - 1) < 0.015;
  return ok && diagram.stable.back() ? 0 : 1;
}
