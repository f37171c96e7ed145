// The lowest modes of a clamped steel bar, and the proof that none is missing.
//
// A square bar bends alike in its two transverse directions, so its first frequency is a repeated
// pair. Lanczos from one start vector can miss a member of such a pair; bladebench counts the
// eigenvalues below its last one by the inertia of K - sigma M (Sylvester's law, the Sturm
// sequence) and solves again until the count agrees. This program builds the mesh, assembles the
// free system, solves, and checks the first frequency against Euler-Bernoulli beam theory.
#include <bladebench/assembly/free_system.hpp>
#include <bladebench/linalg/modal_solver.hpp>
#include <bladebench/mesh/hex_block.hpp>
#include <bladebench/model/model.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

int main() {
  const double length = 0.3, side = 0.02;           // [m]
  const double E = 2.1e11, nu = 0.3, rho = 7850.0;  // steel [Pa, -, kg/m^3]

  // 1. The mesh: one hex20 block, 12 elements along the bar, 2 x 2 across.
  bb::HexBlockSpec block;
  block.corners = {Eigen::Vector3d(0, 0, 0), {length, 0, 0},       {length, side, 0}, {0, side, 0}, {0, 0, side},
                   {length, 0, side},        {length, side, side}, {0, side, side}};
  block.nx = 12;
  block.ny = block.nz = 2;
  block.element = bb::ElementType::hex20;
  bb::Model model;
  model.mesh = bb::generate_hex_block(block);
  model.section = {E, nu, rho, 0.0};  // the thickness is for plane elements only

  // 2. The clamp: every node of the face x = 0 held in x, y and z.
  std::vector<int> root;
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    if (model.mesh.coords(n, 0) < 1e-12) root.push_back(n);
  model.node_sets["root"] = root;
  model.constraints.push_back({"root", {0, 1, 2}, 0.0});

  // 3. K and M over the free DOFs, and their six lowest modes.
  const bb::FreeSystem system = bb::assemble_free_system(model);
  bb::ModalOptions options;
  options.n_modes = 6;
  const bb::ModalSolution modes = bb::lowest_modes(system.stiffness, system.mass, options);
  for (Eigen::Index i = 0; i < modes.eigenvalues.size(); ++i)
    std::printf("mode %ld: %10.3f Hz\n", static_cast<long>(i + 1),
                std::sqrt(modes.eigenvalues[i]) / (2 * std::numbers::pi));
  std::printf("Sturm count: %d eigenvalues below %.3f Hz, %d Lanczos run(s)\n", modes.sturm_count,
              std::sqrt(modes.sturm_shift) / (2 * std::numbers::pi), modes.lanczos_runs);

  // 4. Checks: the pair is whole, the count agrees, the first frequency is the beam's.
  const double f1 = std::sqrt(modes.eigenvalues[0]) / (2 * std::numbers::pi);
  const double f2 = std::sqrt(modes.eigenvalues[1]) / (2 * std::numbers::pi);
  const double beam =
      1.8751 * 1.8751 / (2 * std::numbers::pi * length * length) * std::sqrt(E * side * side / (12 * rho));
  std::printf("first bending: %.3f Hz, Euler-Bernoulli %.3f Hz (%+.2f %%)\n", f1, beam, 100 * (f1 / beam - 1));
  const bool pair = std::abs(f2 / f1 - 1) < 1e-6;
  const bool counted = modes.sturm_count == static_cast<int>(modes.eigenvalues.size());
  const bool beam_like = std::abs(f1 / beam - 1) < 0.02;  // shear and the clamp's 3D stiffness: below 2 %
  return pair && counted && beam_like ? 0 : 1;
}
