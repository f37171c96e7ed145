// The Campbell diagram of a cyclically symmetric structure turning about its axis (z), nodal
// diameter by nodal diameter from one sector: at speed Omega the modes of
//   (K + Omega^2 (K_sigma1 - M_p)) x = w^2 M x,
// K_sigma1 the initial-stress stiffness of the centrifugal deflection at unit speed, found on the
// sector with its faces tied in phase (nodal diameter 0: the load is the same on every sector), M_p
// the spin softening (ffrf/body_assembly.hpp), the pre-stress linear in Omega^2 as for the rotating
// blade (ffrf/rotating_body.hpp). The Coriolis coupling is left out (its effect on the blade-
// dominated families of a disk is second order), so each nodal diameter's problem stays symmetric.
// And the engine-order crossings: where a family of the nodal diameter an engine order excites
// meets the line f = EO Omega / 2 pi.
#pragma once
#include <Eigen/Dense>

#include <cstddef>
#include <vector>

#include "assembly/free_system.hpp"
#include "cyclic/cyclic_modes.hpp"
#include "model/model.hpp"

namespace bb {

struct CyclicCampbell {
  std::vector<double> speeds;        // [rad/s]
  std::vector<int> nodal_diameters;  // ascending
  // frequencies_hz[d](s, f): nodal diameter d, speed s, family f (each pair once).
  std::vector<Eigen::MatrixXd> frequencies_hz;
  double max_unit_speed_deflection = 0.0;  // largest |u1| [m s^2]: the deflection is Omega^2 u1
};

// `workers` eigenproblems (speed, nodal diameter) at once. Throws InputError for a model without
// density, SolverError when the in-phase static problem cannot be factored or a nodal diameter's
// modes do not converge at some speed.
CyclicCampbell cyclic_campbell(const Model& model, const FreeSystem& sector, const CyclicDofs& cyclic,
                               const std::vector<double>& speeds, const std::vector<int>& nodal_diameters, int families,
                               const ModalOptions& options, std::size_t workers);

struct CyclicCrossing {
  int engine_order = 0;
  int nodal_diameter = 0;
  int family = 0;             // 1-based
  double speed = 0.0;         // [rad/s], linear between the diagram's speeds
  double frequency_hz = 0.0;  // EO speed / 2 pi
};

// The nodal diameter that engine order EO excites on N sectors: EO mod N folded into 0..N/2.
int excited_nodal_diameter(int engine_order, int sectors);

// Crossings of every family of each engine order's nodal diameter (when the diagram has it).
std::vector<CyclicCrossing> engine_order_crossings(const CyclicCampbell& campbell,
                                                   const std::vector<int>& engine_orders, int sectors);

}  // namespace bb
