// The contact-modal analysis (analysis/contact_modal_spec.hpp) on a model with contact pairs:
// static contact solve and modal analysis at every grid point, as result tables. SI units, Hz.
#pragma once
#include <Eigen/Dense>

#include <vector>

#include "analysis/contact_modal_spec.hpp"
#include "analysis/hbm_analysis.hpp"
#include "contact/surface_contact.hpp"
#include "model/model.hpp"
#include "results/table.hpp"

namespace bb {

struct ContactGridPoint {
  double interference = 0.0, penalty_factor = 0.0;
  Eigen::VectorXd frequencies_hz;
  double closed_fraction = 0.0;  // of the contact points, pairs together
  double max_pressure = 0.0;     // [Pa]
  int static_iterations = 0, newton_iterations = 0, status_changes = 0;
  double static_seconds = 0.0, modal_seconds = 0.0;
};

struct ContactModalOutcome {
  ResultTables tables;
  std::vector<ContactGridPoint> grid;  // interference slowest, penalty factor fastest
  Eigen::VectorXd glued_hz;            // empty unless glued_reference
  int free_dofs = 0, contact_points = 0;
  double glued_seconds = 0.0, setup_seconds = 0.0;
  std::vector<std::string> pair_names;
};

// Throws InputError when the model has no contact pair or the interference is not small against
// the contact facets, SolverError when a contact solve or an eigensolve fails.
// `progress` receives one line per grid point with the time left (none when empty).
ContactModalOutcome run_contact_modal(const Model& model, const ContactModalSpec& spec,
                                      const HbmProgress& progress = {});

}  // namespace bb
