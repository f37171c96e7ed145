#include "analysis/work_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "friction/masing.hpp"
#include "mesh/element_topology.hpp"

namespace bb {
namespace {

double row_nonzeros(ElementType type) { return topology(type).row_nonzeros; }

// Adds b to a: operations and bytes summed, the basis and key of the larger part kept.
WorkEstimate combine(WorkEstimate a, const WorkEstimate& b) {
  const bool b_larger = b.operations > a.operations || b.bytes > a.bytes;
  WorkEstimate out = b_larger ? b : a;
  out.operations = a.operations + b.operations;
  out.bytes = a.bytes + b.bytes;
  return out;
}

// The Jenkins sliders the solvers see: an Iwan joint is as many as its distribution's shares.
double slider_count(const HbmSpec& s) {
  double n = 0.0;
  for (const HbmContactSpec& c : s.contacts)
    n += c.distribution ? static_cast<double>(c.distribution->shares().size()) : 1.0;
  return n + (s.damper ? static_cast<double>(s.damper->points.size()) : 0.0);
}

double grid_points(double f_min, double f_max, double step) { return std::floor((f_max - f_min) / step + 1e-9) + 1.0; }

// The sweeps of a harmonic-balance analysis: frequencies x levels x the H and samples it may climb
// through (each climb counted at its top H: an upper bound) x Newton iterations, each an AFT of
// every contact (DFT of the Jacobian: 4 S (2H+1)^2) and the LU of the condensed Jacobian
// ((n (2H+1))^3 / 3).
WorkEstimate hbm_work(const HbmSpec& s) {
  double unknowns = 0.0, elements = slider_count(s);
  for (const HbmContactSpec& c : s.contacts) unknowns += static_cast<double>(c.tangential.size() + c.normal.size());
  if (s.damper) unknowns += 3.0 + 2.0 * static_cast<double>(s.damper->points.size());
  unknowns = std::max(unknowns, 1.0);
  elements = std::max(elements, 1.0);
  // The whole ring (cyclic verification) solves every sector's contacts at once, on a linear part
  // N times the sector's, decomposed densely for its modes.
  const double ring = s.cyclic && s.cyclic->whole ? static_cast<double>(s.cyclic->sectors) : 1.0;
  unknowns *= ring;
  elements *= ring;
  const double ring_dofs = ring > 1.0 && s.model.matrices ? ring * static_cast<double>(s.model.matrices->size()) : 0.0;
  const bool adaptive_h = s.harmonic_tolerance > 0.0;
  const int top_h = adaptive_h ? std::max(s.max_harmonics, s.harmonics) : s.harmonics;
  const double m = 2.0 * top_h + 1.0;
  const double h_sweeps = adaptive_h ? std::floor((top_h - s.harmonics) / std::max(s.harmonic_step, 1)) + 1.0 : 1.0;
  // The samples: fixed, or doubled from the start up to max_time_samples (aft_tolerance), whose
  // sweeps together cost less than twice the last one.
  const double first_samples = s.time_samples > 0 ? s.time_samples : std::max(64.0, 16.0 * m);
  const double samples = s.aft_tolerance > 0.0 ? std::max<double>(s.max_time_samples, first_samples) : first_samples;
  double sample_sum = 0.0, sample_sweeps = 0.0;
  for (double n = first_samples;; n = std::min(2.0 * n, samples)) {
    sample_sum += n;
    sample_sweeps += 1.0;
    if (n >= samples) break;
  }
  const bool grid = s.sweep.method == HbmSweepSpec::Method::grid;
  const double frequencies =
      grid ? grid_points(s.sweep.f_min, s.sweep.f_max, s.sweep.step_hz) : 10.0 / std::max(s.sweep.max_step, 1e-6);
  const double levels = static_cast<double>(s.force_levels.size());
  double stepped = 0.0;  // each point of a stepped sine is a solve like a grid frequency's
  for (const SteppedSineSpec& sine : s.stepped_sines) stepped += static_cast<double>(sine.frequency_hz.size());
  for (const ResponseControlSpec& c : s.response_controls) stepped += static_cast<double>(c.frequency_hz.size()) + 40.0;
  const double points = std::max(frequencies * levels + stepped, 1.0);
  // The point scope solves each frequency at a pair of H, raised until they agree.
  const double h_solves = s.harmonic_scope == HbmSpec::HarmonicScope::point ? h_sweeps + 1.0 : h_sweeps;
  const double solves = h_solves * sample_sweeps;
  const double per_point_counted =
      h_solves * (4.0 * elements * sample_sum * m * m + sample_sweeps * std::pow(unknowns * m, 3.0) / 3.0 +
                  (s.stability == HbmSpec::Stability::path ? 10.0 * std::pow(2.0 * unknowns * m, 3.0) : 0.0));
  // A solve costs at least what the counts above leave out (the predictor, assembling the residual,
  // the output rows): a one-DOF sweep at H = 1 took 35 us a point (5e4 points) where they say 2 300
  // operations, so 5 levels of 1e6 frequencies (the reader's cap) were accepted for about 3 minutes.
  constexpr double kLeastPerSolve = 1e5;
  const double per_point = std::max(per_point_counted, solves * kLeastPerSolve);
  const double per_solve_iterations = 5.0;
  WorkEstimate e;
  e.operations = points * per_solve_iterations * per_point + 10.0 * std::pow(ring_dofs, 3.0);
  // The DFT matrices, and per point and level the solution and its output rows (about 40 numbers);
  // the whole ring's dense matrices and modes.
  e.bytes = 2.0 * samples * m * 8.0 * elements + points * (unknowns * m + 40.0) * 8.0 * 3.0 +
            8.0 * 6.0 * ring_dofs * ring_dofs + 8.0 * std::pow(unknowns * m, 2.0);
  e.basis = fmt::format(
      "{:.0f} frequencies x {:.0f} levels{} x {:.0f} sweeps, H up to {}, {:.0f} AFT samples, {:.0f} condensed "
      "unknowns{}",
      frequencies, levels, stepped > 0.0 ? fmt::format(" + {:.0f} stepped-sine points", stepped) : "", solves, top_h,
      samples, unknowns, ring > 1.0 ? fmt::format(" (the whole ring of {:.0f} sectors)", ring) : "");
  e.at = s.at;
  e.key = grid ? "analysis.step_hz, harmonics, time_samples" : "analysis.max_step, harmonics, time_samples";
  if (ring > 1.0) e.key += ", analysis.cyclic.sectors";
  return e;
}

// Newmark on the reduced model: every step of every cycle at every frequency and level.
WorkEstimate time_work(const TimeSpec& t) {
  const HbmSpec& s = t.system;
  const double size = s.model.matrices ? static_cast<double>(s.model.matrices->size())
                                       : 3.0 * static_cast<double>(s.model.masters.size()) + s.model.modes;
  const double elements = slider_count(s);
  const double frequencies = grid_points(s.sweep.f_min, s.sweep.f_max, s.sweep.step_hz);
  const double levels = static_cast<double>(std::max<size_t>(s.force_levels.size(), 1));
  const double steps = frequencies * levels * t.max_cycles * t.steps_per_period;
  WorkEstimate e;
  e.operations = steps * (4.0 * size * size + 100.0 * std::max(elements, 1.0));
  if (t.method == TimeSpec::Method::shooting && t.period_map == TimeSpec::PeriodMap::exact) {
    // The exact flow: about 10 Newton iterations per frequency, each a period of pieces (a stick
    // and a slip per contact and half period), each piece a matrix exponential of the flow's
    // state (2 n + contacts + 3): 30 d^3. A chain of 20 contacts held by Coulomb's stick took
    // 21.5 s, where this counts 7e10; the flow's own cap on transitions bounds a chattering one.
    const double d = 2.0 * size + elements + 3.0;
    const double shooting = frequencies * levels * 10.0 * (4.0 * elements + 2.0) * 30.0 * d * d * d;
    e.operations = std::max(e.operations, shooting);
  }
  e.bytes = 8.0 * (t.history_cycles * t.steps_per_period * (size + 10.0) + frequencies * levels * 40.0);
  e.basis = fmt::format("{:.0f} frequencies x {:.0f} levels x at most {} cycles x {} steps, {:.0f} DOFs", frequencies,
                        levels, t.max_cycles, t.steps_per_period, size);
  e.at = s.at;
  e.key = "analysis.step_hz, max_cycles, steps_per_period";
  if (t.method == TimeSpec::Method::shooting && t.period_map == TimeSpec::PeriodMap::exact) {
    e.basis = fmt::format(
        "{:.0f} frequencies x {:.0f} levels x about 10 Newton iterations, each a period of about "
        "{:.0f} pieces of the exact flow, a matrix exponential of {:.0f} states each",
        frequencies, levels, 4.0 * elements + 2.0, 2.0 * size + elements + 3.0);
    e.key = "analysis.step_hz, force_levels, [[analysis.contact]]";
  }
  return e;
}

WorkEstimate analysis_work(const HbmSpec& s, const Model& model) {
  const WorkEstimate sweep = hbm_work(s);
  return s.model.masters.empty() ? sweep : combine(estimate_mesh_work(model), sweep);
}

WorkEstimate analysis_work(const TimeSpec& t, const Model& model) {
  const WorkEstimate steps = time_work(t);
  return t.system.model.masters.empty() ? steps : combine(estimate_mesh_work(model), steps);
}

// One AFT march of every slider through the period's samples: about 300 ns a slider and sample
// (an Iwan joint of 1 000 sliders at 1e4 samples, 3 s), counted as 4 000 operations as the
// harmonic balance's floor is; 1e4 sliders at 1e6 samples, the reader's caps, ran for an hour.
WorkEstimate analysis_work(const ContactLoopSpec& s, const Model&) {
  const double sliders = s.distribution ? static_cast<double>(s.distribution->shares().size()) : 1.0;
  const double samples = s.samples;
  WorkEstimate e;
  e.operations = 4000.0 * sliders * samples;
  e.bytes = 8.0 * (20.0 * samples + 4.0 * sliders);  // the loop's rows; each slider's law and state
  e.basis = fmt::format("{:.0f} sliders x {:.0f} samples", sliders, samples);
  e.at = s.at;
  e.key = "analysis.samples, analysis.contact.sliders";
  return e;
}

// A force-controlled point samples its residual 400 times over the roots' bracket (each two
// spline evaluations) per mode and weighs its knots for the sensitivities; a held point of one
// mode is one evaluation, of several a root find of about 100 force-controlled points.
WorkEstimate analysis_work(const NonlinearModalSpec& s, const Model&) {
  double forced = 0.0, held = 0.0;
  for (const SteppedSineSpec& sine : s.stepped_sines) forced += static_cast<double>(sine.frequency_hz.size());
  for (const ResponseControlSpec& c : s.response_controls) held += static_cast<double>(c.frequency_hz.size()) + 100.0;
  double knots = 0.0;
  for (const NonlinearMode& m : s.modes) knots += static_cast<double>(m.frequency_hz.knots() + m.damping_ratio.knots());
  const double modes = static_cast<double>(s.modes.size()), held_forced = s.modes.size() > 1 ? 100.0 : 0.0;
  WorkEstimate e;
  e.operations = forced * (500.0 * 60.0 * modes + knots * knots * 20.0) +
                 held * (held_forced * 500.0 * 60.0 * modes + knots * knots * 20.0);
  e.bytes = 8.0 * (forced + held) * (10.0 + 2.0 * static_cast<double>(s.sensitivities.size()));
  e.basis = fmt::format("{:.0f} force-controlled and {:.0f} held points, {:.0f} knots", forced, held, knots);
  e.at = s.at;
  e.key = "analysis.stepped_sine, analysis.response_control";
  return e;
}

WorkEstimate analysis_work(const ModalSpec& s, const Model& model) {
  return estimate_mesh_work(model, s.options.out_of_core);
}

// Each nodal diameter (at each speed) factors a real problem of up to twice the sector (the
// cosine and sine parts): twice the memory, 4x the flops of the mesh's; the whole structure of N
// sectors, N times the unknowns (flops as n^2, memory as n^(4/3), estimate_mesh_work's 3D laws).
WorkEstimate analysis_work(const CyclicModalSpec& s, const Model& model) {
  const WorkEstimate mesh = estimate_mesh_work(model, s.options.out_of_core);
  const double diameters =
      s.nodal_diameters.empty() ? std::floor(s.sectors / 2.0) + 1.0 : static_cast<double>(s.nodal_diameters.size());
  const double speeds = static_cast<double>(std::max<size_t>(s.speeds_rpm.size(), 1));
  const double n = static_cast<double>(s.sectors);
  WorkEstimate e = mesh;
  e.operations = 4.0 * mesh.operations * diameters * (1.0 + speeds);
  e.bytes = 2.0 * mesh.bytes;
  if (s.whole) {
    e.operations += mesh.operations * n * n;
    e.bytes = std::max(e.bytes, mesh.bytes * std::pow(n, 4.0 / 3.0));
  }
  e.basis = fmt::format("{:.0f} nodal diameters x {:.0f} speeds of a {}-sector structure{}; per sector: {}", diameters,
                        speeds, s.sectors, s.whole ? ", and the whole structure" : "", mesh.basis);
  e.at = s.at;
  e.key = "analysis.sectors, nodal_diameters, speeds_rpm, whole";
  return e;
}

template <typename Spec>
WorkEstimate analysis_work(const Spec&, const Model& model) {
  return estimate_mesh_work(model);
}

}  // namespace

// Out of core, the share of the factors MUMPS holds in memory at once (its active fronts and the
// blocks it reads back), from the two-blade article at 1.28 M DOFs (bench/README.md).
constexpr double kOutOfCoreFactorShare = 0.25;

WorkEstimate estimate_mesh_work(const Model& model, bool factors_out_of_core) {
  const Mesh& mesh = model.mesh;
  const double n = static_cast<double>(mesh.n_nodes()) * mesh.dim;
  if (n < 1.0 || mesh.blocks.empty()) return {};
  double row = 0.0;
  for (const ElementBlock& b : mesh.blocks) row = std::max(row, row_nonzeros(b.type));
  // Nested-dissection fill: n log2 n in 2D, n^(4/3) in 3D (scaled by the element's coupling).
  const double factor = mesh.dim == 2 ? 4.0 * n * std::log2(std::max(n, 2.0)) : row / 8.0 * std::pow(n, 4.0 / 3.0);
  const double flops = mesh.dim == 2 ? 10.0 * std::pow(n, 1.5) : row / 8.0 * n * n;
  WorkEstimate e;
  e.operations = flops;
  // K and M as triplets and compressed, the factor, a few vectors per DOF.
  e.bytes = n * row * (16.0 + 24.0) + factor * 12.0 * (factors_out_of_core ? kOutOfCoreFactorShare : 1.0) + n * 200.0;
  e.basis = fmt::format("{:.0f} DOFs of {} {} elements, factor about {:.3g} nonzeros{}", n, mesh.n_elements(),
                        element_name(mesh.blocks.front().type), factor, factors_out_of_core ? " (out of core)" : "");
  e.key = "mesh";
  return e;
}

WorkEstimate estimate_work(const AnalysisSpec& spec, const Model& model) {
  return std::visit([&](const auto& s) { return analysis_work(s, model); }, spec);
}

}  // namespace bb
