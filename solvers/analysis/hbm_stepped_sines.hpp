// The stepped sines of an hbm analysis, run and tabled: force-controlled (forced/hbm_stepped_sine.hpp),
// frf_<name> with the force of each point and stepped_sine_cost; response-controlled
// (forced/hbm_response_control.hpp), frf_<name> with the force that holds the response and
// response_control.
#pragma once
#include <vector>

#include "forced/hbm_response_control.hpp"
#include "forced/hbm_stepped_sine.hpp"
#include "results/table.hpp"

namespace bb {

// frf_<name>: per converged point in the order stepped: point (1-based in the spec), frequency_hz,
// force_n, then the columns of a level's frf table (amplitudes, phases, largest excursions,
// residual, iterations, sensitivities). stepped_sine_cost: per stepped sine its points, failures,
// iterations and seconds, with its name and first failure as text.
void add_stepped_sine_tables(const PreparedHbm& p, const HbmSpec& spec, const std::vector<HbmSteppedSine>& sines,
                             ResultTables& tables);

// frf_<name> per response control: point, frequency_hz, force_n, force_phase_deg (the held response
// at phase 0), held_m (the held displacement amplitude), then amplitudes, phases to the force and
// largest excursions of every response, residual_n, iterations. response_control: per control its
// amplitude and derivative (0 displacement, 1 velocity, 2 acceleration), the smallest force, its
// frequency and the held response's phase to the force there, min_interior (1 when refined between
// two points), points, failed, iterations, harmonics, samples, seconds; text: name, dof, held,
// first_failure.
void add_response_control_tables(const PreparedHbm& p, const HbmSpec& spec, const std::vector<HbmControlled>& controls,
                                 ResultTables& tables);

// Runs spec.stepped_sines and spec.response_controls on spec.threads workers and adds the tables
// above. SolverError when one converges at no frequency (as a level without a solution).
void run_stepped_sines(const PreparedHbm& p, const HbmSpec& spec, const HbmProgress& progress,
                       std::vector<HbmSteppedSine>& sines, std::vector<HbmControlled>& controls, ResultTables& tables);

}  // namespace bb
