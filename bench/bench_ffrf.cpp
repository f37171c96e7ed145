// Floating-frame runs (solvers/ffrf): the thesis's blade on a rotor at 300 rad/s for 10 s (section
// 2.1.4: planar q4 model of ~233 nodes, and the hex8 model of ~196 elements, 4 through the
// thickness), with gravity (Fig. 2.21: 9.81 m/s^2), started at speed from rest as SAMS/2000 does;
// and the spin-up beam of Kane, Ryan & Banerjee (1987). Measurement only: nothing asserts a time.
//
// Geometry (a reconstruction, like solvers/articles/two_blade.hpp): root 35 x 15 mm, airfoil
// 5.4 mm wide and 157 mm long centred on the root, thickness 50 mm; steel (E = 220 GPa, nu = 0.3,
// rho = 7730 kg/m^3, Fig. 2.21); root face clamped; the rotor axis (z) 0.25 m below the root.
// Time step: 40 steps per period of the lowest rotating mode at 300 rad/s (generalized-alpha period
// error (w dt)^2 / 12 = 0.2 %); modal basis of the first 8 fixed-interface modes plus the static
// shapes. Counters: free DOFs, coordinates, steps, factorizations, and the wall time per simulated
// second (sim_s_per_s, "seconds of wall time per second of simulated time").
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "ffrf/ffrf_integrator.hpp"
#include "ffrf/rotating_modes.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/mapped_quad.hpp"

namespace {

constexpr double kRootWidth = 0.035, kRootHeight = 0.015, kAirfoilWidth = 0.0054, kAirfoilLength = 0.157;
constexpr double kThickness = 0.05, kAxisBelowRoot = 0.25;

// x positions of the root's three columns: left of the airfoil, under it, right of it.
std::vector<double> columns() {
  const double c = 0.5 * kRootWidth, h = 0.5 * kAirfoilWidth;
  return {0.0, c - h, c + h, kRootWidth};
}

bb::Mesh planar_blade_mesh() {
  const auto x = columns();
  std::vector<bb::Mesh> parts;
  const int nx[3] = {3, 2, 3};
  for (int i = 0; i < 3; ++i) {
    bb::MappedQuadSpec s;
    s.corners = {Eigen::Vector2d(x[i], 0), Eigen::Vector2d(x[i + 1], 0), Eigen::Vector2d(x[i + 1], kRootHeight),
                 Eigen::Vector2d(x[i], kRootHeight)};
    s.nx = nx[i];
    s.ny = 3;
    parts.push_back(bb::generate_mapped_quad(s));
  }
  bb::MappedQuadSpec a;
  a.corners = {Eigen::Vector2d(x[1], kRootHeight), Eigen::Vector2d(x[2], kRootHeight),
               Eigen::Vector2d(x[2], kRootHeight + kAirfoilLength),
               Eigen::Vector2d(x[1], kRootHeight + kAirfoilLength)};
  a.nx = 2;
  a.ny = 66;
  parts.push_back(bb::generate_mapped_quad(a));
  return bb::merge_meshes(parts, 1e-9);
}

bb::Mesh solid_blade_mesh() {
  const auto x = columns();
  auto block = [](double x0, double x1, double y0, double y1, int nx, int ny) {
    bb::HexBlockSpec s;
    s.corners = {Eigen::Vector3d(x0, y0, 0),          Eigen::Vector3d(x1, y0, 0),
                 Eigen::Vector3d(x1, y1, 0),          Eigen::Vector3d(x0, y1, 0),
                 Eigen::Vector3d(x0, y0, kThickness), Eigen::Vector3d(x1, y0, kThickness),
                 Eigen::Vector3d(x1, y1, kThickness), Eigen::Vector3d(x0, y1, kThickness)};
    s.nx = nx;
    s.ny = ny;
    s.nz = 4;
    s.element = bb::ElementType::hex8;
    return bb::generate_hex_block(s);
  };
  std::vector<bb::Mesh> parts{block(x[0], x[1], 0, kRootHeight, 3, 2), block(x[1], x[2], 0, kRootHeight, 2, 2),
                              block(x[2], x[3], 0, kRootHeight, 3, 2),
                              block(x[1], x[2], kRootHeight, kRootHeight + kAirfoilLength, 2, 17)};
  return bb::merge_meshes(parts, 1e-9);
}

bb::Model blade_model(bb::Mesh mesh) {
  bb::Model m;
  m.mesh = std::move(mesh);
  m.section = {.youngs_modulus = 2.2e11, .poisson_ratio = 0.3, .density = 7730.0, .thickness = kThickness};
  std::vector<int> root;
  for (int n = 0; n < m.mesh.n_nodes(); ++n)
    if (m.mesh.coords(n, 1) < 1e-9) root.push_back(n);
  m.node_sets["root"] = root;
  std::vector<bb::Direction> all{0, 1};
  if (m.mesh.dim == 3) all.push_back(2);
  m.constraints = {{"root", all, 0.0}};
  return m;
}

// One timed run of `simulated` seconds with the given basis. The benchmark's time is the
// integration alone; setup_s is the model, basis and projection; sim_s_per_s the integration's wall
// time per simulated second.
void run(benchmark::State& state, const bb::Model& model, const bb::ffrf::ElasticBasisOptions& basis_options,
         const bb::ffrf::RotationProfile& profile, double simulated, double dt, bb::ffrf::FfrfOptions o,
         const bb::ffrf::RotationAxis& axis) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const bb::ffrf::RotatingBody body = bb::ffrf::build_rotating_body(model, axis);
  const bb::ffrf::ElasticBasis basis = bb::ffrf::make_elastic_basis(body, basis_options);
  const bb::ffrf::ProjectedBody p = bb::ffrf::project(body, basis);
  const double setup = std::chrono::duration<double>(clock::now() - t0).count();
  o.time_step = dt;
  o.end_time = simulated;
  bb::ffrf::FfrfHistory h;
  double wall = 0.0;
  for (auto _ : state) {
    const auto t1 = clock::now();
    h = bb::ffrf::integrate(p, profile, o);
    wall += std::chrono::duration<double>(clock::now() - t1).count();
  }
  state.counters["setup_s"] = setup;
  state.counters["sim_s_per_s"] = wall / simulated / static_cast<double>(state.iterations());
  state.counters["free_dofs"] = body.n_free();
  state.counters["coordinates"] = basis.size();
  state.counters["steps"] = h.steps;
  state.counters["factorizations"] = h.factorizations;
  state.counters["corrections"] = static_cast<double>(h.solve_iterations);
}

bb::ffrf::ElasticBasisOptions modal(int n) {
  bb::ffrf::ElasticBasisOptions o;
  o.kind = bb::ffrf::BasisKind::modal;
  o.n_modes = n;
  return o;
}

// 40 steps per period of the lowest rotating mode at 300 rad/s.
double blade_time_step(const bb::Model& model, const bb::ffrf::RotationAxis& axis) {
  const bb::ffrf::RotatingBody body = bb::ffrf::build_rotating_body(model, axis);
  const bb::ffrf::ElasticBasis basis = bb::ffrf::make_elastic_basis(body, modal(8));
  const bb::ffrf::ProjectedBody p = bb::ffrf::project(body, basis);
  return bb::ffrf::time_step_resolving(p, 300.0);
}

void blade_benchmark(benchmark::State& state, bb::Model model, double simulated) {
  bb::ffrf::RotationAxis axis;
  axis.point = Eigen::Vector3d(0.5 * kRootWidth, -kAxisBelowRoot, 0.0);
  const double dt = blade_time_step(model, axis);
  bb::ffrf::FfrfOptions o;
  o.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
  o.output_stride = 20;
  const bool nodal = state.range(0) == 0;
  run(state, model, nodal ? bb::ffrf::ElasticBasisOptions{} : modal(8),
      bb::ffrf::RotationProfile::constant_speed(300.0), simulated, dt, o, axis);
  state.counters["time_step_us"] = dt * 1e6;
  state.counters["nodes"] = model.mesh.n_nodes();
  state.counters["elements"] = model.mesh.n_elements();
}

// Planar q4 blade: 10 s with the modal basis; the nodal basis is measured over 0.5 s (its cost is
// linear in the simulated time).
void BM_FfrfPlanarBlade300rads(benchmark::State& state) {
  blade_benchmark(state, blade_model(planar_blade_mesh()), state.range(0) == 0 ? 0.5 : 10.0);
}
BENCHMARK(BM_FfrfPlanarBlade300rads)->ArgName("modal")->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

void BM_FfrfSolidBlade300rads(benchmark::State& state) {
  blade_benchmark(state, blade_model(solid_blade_mesh()), state.range(0) == 0 ? 0.2 : 10.0);
}
BENCHMARK(BM_FfrfSolidBlade300rads)->ArgName("modal")->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

// Spin-up beam (tests/unit/ffrf_spin_up_test.cpp): hex8i 40 x 1 x 1, dt = 5 ms, 25 s.
// Arg 0: nodal basis refactorizing at every change of Omega; 1: nodal with stale-factor
// correction (the default); 2: modal basis of 12 modes plus static shapes.
void BM_FfrfSpinUpBeam(benchmark::State& state) {
  const double h = std::sqrt(12.0 * 1.4e4 / 2.8e7);
  bb::HexBlockSpec s;
  s.corners = {Eigen::Vector3d(0, -h / 2, -h / 2), Eigen::Vector3d(10, -h / 2, -h / 2),
               Eigen::Vector3d(10, h / 2, -h / 2), Eigen::Vector3d(0, h / 2, -h / 2),
               Eigen::Vector3d(0, -h / 2, h / 2),  Eigen::Vector3d(10, -h / 2, h / 2),
               Eigen::Vector3d(10, h / 2, h / 2),  Eigen::Vector3d(0, h / 2, h / 2)};
  s.nx = 40;
  s.element = bb::ElementType::hex8i;
  bb::Model model;
  model.mesh = bb::generate_hex_block(s);
  model.section = {.youngs_modulus = 2.8e7 / (h * h), .poisson_ratio = 0.3, .density = 1.2 / (h * h), .thickness = 0};
  std::vector<int> root;
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    if (model.mesh.coords(n, 0) < 1e-9) root.push_back(n);
  model.node_sets["root"] = root;
  model.constraints = {{"root", {0, 1, 2}, 0.0}};
  bb::ffrf::FfrfOptions o;
  o.output_stride = 10;
  o.factorization =
      state.range(0) == 0 ? bb::ffrf::FactorizationReuse::every_change : bb::ffrf::FactorizationReuse::with_correction;
  run(state, model, state.range(0) == 2 ? modal(12) : bb::ffrf::ElasticBasisOptions{},
      bb::ffrf::RotationProfile::spin_up(6.0, 15.0), 25.0, 0.005, o, {});
}
BENCHMARK(BM_FfrfSpinUpBeam)->ArgName("variant")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
