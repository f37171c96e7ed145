#include "report/describe_analysis.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cache/cache_use.hpp"
#include "distributed/distributed.hpp"
#include "report/describe_cyclic.hpp"
#include "report/describe_hbm.hpp"
#include "report/nonlinear_modal_report.hpp"
#include "report/number_format.hpp"

namespace bb {

// Whether a reduction or a set of modes was computed here or came from the model cache.
void describe_cache(const std::string& what, const CacheUse& u, RunRecord& run) {
  std::string use;
  switch (u.outcome) {
    case CacheUse::Outcome::off:
      use = u.note.empty() ? "off" : u.note;
      break;
    case CacheUse::Outcome::loaded:
      use = fmt::format("loaded in {:.2f} s (computed by an earlier run in {:.2f} s{})", u.seconds, u.build_seconds,
                        u.note.empty() ? "" : "; " + u.note);
      break;
    case CacheUse::Outcome::stored:
      use = fmt::format("computed here in {:.2f} s and stored in {:.2f} s", u.build_seconds, u.seconds);
      break;
    case CacheUse::Outcome::not_stored:
      use = u.note.empty() ? fmt::format("computed here in {:.2f} s; too quick to be worth an entry", u.build_seconds)
                           : u.note;
      break;
  }
  run.facts.emplace_back(fmt::format("model cache ({})", what), use);
}

namespace {

void describe(const FrfSpec& spec, const FrfOutcome& frf, RunRecord& run) {
  std::string forces;
  for (const FrfForce& f : spec.forces)
    forces += fmt::format("{}{} N on {}", forces.empty() ? "" : ", ", format_setting(f.amplitude), f.dof.name());
  const std::string damping =
      spec.damping.kind == FrfDamping::Kind::modal
          ? fmt::format("modal, zeta = {}", describe_modal_ratios(spec.damping))
          : fmt::format("Rayleigh, zeta = {} at {} Hz and {} at {} Hz", format_setting(spec.damping.rayleigh_zeta[0]),
                        format_setting(spec.damping.rayleigh_hz[0]), format_setting(spec.damping.rayleigh_zeta[1]),
                        format_setting(spec.damping.rayleigh_hz[1]));
  run.facts.emplace_back(
      "analysis", fmt::format("linear forced response, {} to {} Hz, {} ({} frequencies), {}; force {}",
                              format_setting(spec.f_min), format_setting(spec.f_max),
                              spec.adaptive ? fmt::format("step {} Hz refined to {} Hz around peaks",
                                                          format_setting(spec.step), format_setting(spec.min_step))
                                            : fmt::format("step {} Hz", format_setting(spec.step)),
                              frf.sweep.frequency_hz.size(), damping, forces));
  if (frf.full_modal) {
    run.facts.emplace_back(
        "full mesh",
        fmt::format("{} free DOFs; modal superposition (eq 3.32) of the lowest {} modes (up to {:.1f} Hz){}",
                    frf.full_modal->n_free_dofs, frf.full_modal->frequencies_hz.size(),
                    frf.full_modal->frequencies_hz.maxCoeff(),
                    spec.residual_flexibility ? " + static residual flexibility of the rest" : ""));
    run.facts.emplace_back("full mesh: assembly / modes + residual / sweep [s]",
                           fmt::format("{:.2f} / {:.2f} / {:.4f}", frf.full_modal->assembly_seconds,
                                       frf.full_setup_seconds, frf.full_sweep_seconds));
    describe_cache("full mesh modes", frf.full_modal->cache, run);
  }
  for (size_t i = 0; i < frf.roms.size(); ++i) {
    const RomOutcome& r = frf.roms[i];
    const RomSpec& rs = spec.roms[i];
    const std::string origin = rs.file.empty()
                                   ? fmt::format("Craig-Bampton, masters {} (3 DOFs each), {} fixed-interface modes",
                                                 fmt::join(rs.masters, " "), rs.modes)
                                   : fmt::format("read from {}", rs.file.filename().string());
    run.facts.emplace_back(
        fmt::format("reduced model '{}'", r.name),
        fmt::format("{} DOFs, {}; response by {}", r.model.size(), origin,
                    rs.method == RomSpec::Method::direct ? "direct solve of D(w)" : "modal superposition"));
    run.facts.emplace_back(
        fmt::format("reduced model '{}': constraint modes / fixed-interface modes / projection / sweep [s]", r.name),
        fmt::format("{:.2f} / {:.2f} / {:.3f} / {:.4f}", r.timing.constraint_modes_seconds,
                    r.timing.fixed_interface_seconds, r.timing.projection_seconds, r.sweep_seconds));
    if (rs.file.empty() && !rs.matrices) describe_cache(fmt::format("reduced model '{}'", r.name), r.timing.cache, run);
  }
}

void describe(const TimeSpec& spec, const TimeOutcome& time, RunRecord& run) {
  const PreparedHbm& p = time.prepared;
  run.facts.emplace_back(
      "analysis",
      fmt::format("direct time integration ({}), {} steps per period, stepped sine {} to {} Hz every {} Hz, "
                  "each frequency to a cycle-to-cycle change below {} (at most {} periods) from the "
                  "previous one's state; first {} harmonic(s) by DFT over the last period",
                  spec.alpha == 0.0 ? "Newmark average acceleration"
                                    : fmt::format("HHT-alpha, alpha = {}", format_setting(spec.alpha)),
                  spec.steps_per_period, format_setting(spec.system.sweep.f_min),
                  format_setting(spec.system.sweep.f_max), format_setting(spec.system.sweep.step_hz),
                  format_setting(spec.steady_tolerance), spec.max_cycles, spec.system.harmonics));
  describe_levels(spec.system, run);
  const std::string contacts = describe_contacts(p, spec.system);
  run.facts.emplace_back("contacts", contacts.empty() ? "none (linear model)" : contacts);
  run.facts.emplace_back("model DOFs", std::to_string(p.model.mass.rows()));
  if (spec.system.model.file.empty() && !spec.system.model.matrices)
    describe_cache("Craig-Bampton reduction", p.timing.cache, run);
  long steps = 0, not_steady = 0, by_envelope = 0;
  long settled = 0, subharmonic = 0;  // of the shooting's frequencies marched, not read by their envelope
  double seconds = 0, widest = 0;
  for (const TimeLevel& l : time.levels) {
    steps += l.steps;
    seconds += l.seconds;
    for (size_t i = 0; i < l.steady.size(); ++i) {
      if (l.steady[i]) continue;
      ++not_steady;
      if (steady_first_harmonic(l, spec, static_cast<Eigen::Index>(i))) {
        ++by_envelope, widest = std::max(widest, l.envelope_span[i]);
      } else if (i < l.period_multiple.size()) {
        settled += l.period_multiple[i] == 1;
        subharmonic += l.period_multiple[i] >= 2;
      }
    }
  }
  const bool shooting = spec.method == TimeSpec::Method::shooting;
  if (not_steady > by_envelope && shooting && marches(spec)) {
    // What the march did where Newton failed: it settled (and Newton failed from its orbit too),
    // repeats every k >= 2 periods, or repeats within none.
    std::vector<std::string> parts;
    if (settled > 0)
      parts.push_back(fmt::format("{} settled in the march but Newton failed from its orbit as well", settled));
    if (subharmonic > 0) parts.push_back(fmt::format("{} repeat every 2 or more periods", subharmonic));
    if (const long rest = not_steady - by_envelope - settled - subharmonic; rest > 0)
      parts.push_back(fmt::format("{} repeat within no period after {} periods", rest, spec.max_cycles));
    run.warnings.push_back(fmt::format(
        "{} frequencies have no periodic solution found (Newton failed; of them {}): their amplitudes are the "
        "march's last period (frf: change, period_multiple and the envelope columns say what the motion did)",
        not_steady - by_envelope, fmt::join(parts, ", ")));
  } else if (not_steady > by_envelope && shooting)
    run.warnings.push_back(fmt::format(
        "{} frequencies have no periodic solution found (Newton failed; frf: residual_m)", not_steady - by_envelope));
  else if (not_steady > by_envelope)
    run.warnings.push_back(
        fmt::format("{} frequencies did not reach the steady state within {} periods: their amplitudes are not the "
                    "steady response (frf: change, period_multiple and the envelope columns say what the motion did)",
                    not_steady - by_envelope, spec.max_cycles));
  if (by_envelope > 0)
    run.warnings.push_back(fmt::format(
        "{} frequencies {} within no period after {} periods, but their first harmonics span at most {:.3g} % "
        "over the last periods (envelope_tolerance {:.3g} %): read as steady in their first harmonic",
        by_envelope, shooting ? "have no periodic solution found, and the march from each repeats" : "repeat",
        spec.max_cycles, 100.0 * widest, 100.0 * spec.envelope_tolerance));
  run.facts.emplace_back("steps / frequencies not steady / time [s]",
                         fmt::format("{} / {} / {:.2f} (per step {:.2f} us)", steps, not_steady, seconds,
                                     1e6 * seconds / static_cast<double>(std::max(1L, steps))));
  if (spec.compare_harmonics > 0)
    run.facts.emplace_back("comparison", fmt::format("harmonic balance, H = {}, same grid", spec.compare_harmonics));
  if (time.record)
    run.facts.emplace_back(
        "recorded run",
        fmt::format("{} Hz, Fe = {} N: steady after {} periods ({}), then {} periods recorded{}",
                    format_setting(time.record->frequency_hz), format_setting(time.record->force),
                    time.record->steady.cycles,
                    time.record->steady.converged ? "converged" : time.record->steady.failure, spec.history_cycles,
                    time.record->history.converged ? "" : ": " + time.record->history.failure));
}

void describe(const ContactLoopSpec& spec, const ContactLoopOutcome& loop, RunRecord& run) {
  const friction::PointParameters& p = spec.point;
  run.facts.emplace_back("analysis",
                         fmt::format("friction-contact test rig: one Jenkins contact under u = {} cos(theta) m, "
                                     "v = {} cos(theta + {} deg) m (v > 0 presses), {} samples per period, "
                                     "AFT march to the periodic steady state",
                                     format_setting(spec.tangential_amplitude), format_setting(spec.normal_amplitude),
                                     format_setting(spec.normal_phase_deg), spec.samples));
  run.facts.emplace_back(
      "contact", fmt::format("kn {} N/m, kt {} N/m, mu {}, n0 {} N: slip force mu n0 = {} N, slip displacement "
                             "mu n0 / kt = {} m",
                             format_setting(p.kn), format_setting(p.kt), format_setting(p.mu), format_setting(p.n0),
                             format_setting(p.mu * p.n0), format_setting(p.mu * p.n0 / p.kt)));
  run.facts.emplace_back("periods marched / loop closed",
                         fmt::format("{} / {} (slider mismatch {:.3g} m)", loop.aft.periods,
                                     loop.aft.closed ? "yes" : "NO", loop.aft.closure_mismatch));
}

// The largest von Mises stress of a field and where it is: "3.21e+08 Pa at node 17".
std::string peak_von_mises(const Mesh& mesh, const StressField& field) {
  Eigen::Index node = 0;
  double peak = -1.0;
  for (Eigen::Index n = 0; n < field.nodal.rows(); ++n)
    if (const double v = von_mises(field.nodal.row(n)); v > peak) {
      peak = v;
      node = n;
    }
  return fmt::format("{:.4g} Pa at node {} (elements there disagree by {:.3g} Pa)", peak,
                     mesh.node_ids[static_cast<size_t>(node)], field.scatter[node]);
}

void describe(const StaticSpec&, const StaticOutcome& outcome, const Model& model, RunRecord& run) {
  const StaticSolution& sol = outcome.solution;
  run.facts.emplace_back("analysis", "linear static, sparse Cholesky (CHOLMOD)");
  run.facts.emplace_back("free DOFs", std::to_string(sol.n_free_dofs));
  run.facts.emplace_back("pivot ratio (rcond estimate)", fmt::format("{:.3e}", sol.pivot_ratio));
  run.facts.emplace_back("relative residual ||Ku - f|| / ||f||", fmt::format("{:.3e}", sol.relative_residual));
  const double applied = sol.loads.sum(), reacted = sol.reactions.sum();
  run.facts.emplace_back("force balance |sum f + sum R| [N]", fmt::format("{:.3e}", std::abs(applied + reacted)));
  const int dim = static_cast<int>(sol.displacements.cols());
  std::string resultant;
  for (int d = 0; d < dim; ++d) {
    double sum = 0.0;
    for (Eigen::Index i = d; i < sol.loads.size(); i += dim) sum += sol.loads[i];
    resultant += fmt::format("{}{} = {:.6g}", d ? ", " : "", "xyz"[d], sum);
  }
  run.facts.emplace_back("resultant of the applied loads [N]", resultant);
  run.facts.emplace_back(
      "assembly / factor+solve / stress recovery [s]",
      fmt::format("{:.4f} / {:.4f} / {:.4f}", sol.assembly_seconds, sol.solve_seconds, outcome.stresses.seconds));
  run.facts.emplace_back("largest nodal von Mises stress", peak_von_mises(model.mesh, outcome.stresses));
}

void describe(const ModalSpec& spec, const ModalOutcome& outcome, const Model& model, RunRecord& run) {
  const ModalResult& modal = outcome.modal;
  const ModeSelection& sel = spec.modes;
  const bool slepc = spec.options.eigensolver == Eigensolver::slepc;
  const int ranks = distributed::shared_solves() ? distributed::size() : 1;
  run.facts.emplace_back(
      "analysis",
      fmt::format("modal, {}, {}",
                  sel.band_max_hz
                      ? fmt::format("all modes in [{}, {}] Hz", sel.band_min_hz.value_or(0.0), *sel.band_max_hz)
                      : fmt::format("lowest {} modes", sel.lowest),
                  slepc ? fmt::format("SLEPc Krylov-Schur spectrum slicing (MUMPS Cholesky per shift), {} MPI rank{}",
                                      ranks, ranks > 1 ? "s" : "")
                        : std::string("Lanczos shift-invert (Spectra + CHOLMOD)")));
  run.facts.emplace_back("free DOFs", std::to_string(modal.n_free_dofs));
  run.facts.emplace_back(slepc ? "Krylov-Schur iterations" : "Lanczos iterations", std::to_string(modal.iterations));
  const std::string runs = slepc ? std::string("from the inertias of the slicing's own factorizations")
                                 : fmt::format("{} Lanczos run{}, count {:.3f} s", modal.lanczos_runs,
                                               modal.lanczos_runs > 1 ? "s" : "", modal.sturm_seconds);
  run.facts.emplace_back(slepc ? "completeness (inertias of K - sigma M at the slicing's ends)"
                               : "completeness (Sturm count of K - sigma M)",
                         modal.sturm_count < 0 ? std::string("not checked (every mode found is a rigid-body mode)")
                                               : fmt::format("{} modes below {:.6g} Hz, all found ({})",
                                                             modal.sturm_count, modal.sturm_frequency_hz, runs));
  if (modal.rigid_body_modes > 0)
    run.facts.emplace_back("rigid-body modes (free model)", std::to_string(modal.rigid_body_modes));
  run.facts.emplace_back("max eigen-residual (backward error)", fmt::format("{:.3e}", modal.max_residual));
  run.facts.emplace_back("assembly / eigensolve [s]",
                         fmt::format("{:.4f} / {:.4f}", modal.assembly_seconds, modal.solve_seconds));
  describe_cache("modes", modal.cache, run);
  if (spec.pairs) {
    const ModePairSpec& p = *spec.pairs;
    run.facts.emplace_back("mode labels",
                           fmt::format("pair: sign of '{}' vs '{}' along {}; type: motion of tip face '{}' "
                                       "(else '{}')",
                                       p.left, p.right, "xyz"[p.direction], p.right_tip, p.left_tip));
  }
  for (const ModeStresses& m : outcome.stresses)
    run.facts.emplace_back(
        fmt::format("mode {}: largest von Mises stress per unit modal coordinate (shape normalized to unit modal mass)",
                    m.mode),
        peak_von_mises(model.mesh, m.field));
}

void describe(const RotatingSpec& spec, const RotatingOutcome& o, RunRecord& run) {
  run.facts.emplace_back(
      "analysis",
      fmt::format("rotating body, floating frame of reference: {} for {} s; axis through ({}, {}, {}) m along "
                  "({}, {}, {}); gravity ({}, {}, {}) m/s^2; geometric stiffening {}, Coriolis {}",
                  o.profile, format_setting(spec.end_time), format_setting(spec.axis_point.x()),
                  format_setting(spec.axis_point.y()), format_setting(spec.axis_point.z()),
                  format_setting(spec.axis_direction.x()), format_setting(spec.axis_direction.y()),
                  format_setting(spec.axis_direction.z()), format_setting(spec.gravity.x()),
                  format_setting(spec.gravity.y()), format_setting(spec.gravity.z()), spec.stiffening ? "on" : "off",
                  spec.coriolis ? "on" : "off"));
  run.facts.emplace_back("elastic coordinates",
                         spec.modal_basis ? fmt::format("{} of {} free DOFs: {} fixed-interface modes at rest + "
                                                        "static shapes (centrifugal, Euler, gravity)",
                                                        o.basis_size, o.free_dofs, spec.basis_modes)
                                          : fmt::format("every free DOF ({})", o.free_dofs));
  run.facts.emplace_back(
      "time integration",
      fmt::format("generalized-alpha, rho_inf = {}, dt = {:.4g} s ({}), {} steps, {} factorizations",
                  format_setting(spec.rho_infinity), o.time_step,
                  spec.time_step > 0 ? "as given" : "40 steps per period of the lowest rotating mode", o.history.steps,
                  o.history.factorizations));
  run.facts.emplace_back("setup / integration / Campbell [s]",
                         fmt::format("{:.3f} / {:.3f} / {:.3f} ({:.2f} us per step)", o.setup_seconds, o.run_seconds,
                                     o.campbell_seconds, 1e6 * o.run_seconds / std::max(1, o.history.steps)));
  std::string modes;
  for (Eigen::Index m = 0; m < o.modes_at_speed.frequencies_hz.size(); ++m)
    modes += fmt::format("{}{:.2f}", m ? ", " : "", o.modes_at_speed.frequencies_hz[m]);
  run.facts.emplace_back(fmt::format("rotating modes at {} rad/s [Hz]", format_setting(o.modes_at_speed.speed)), modes);
  std::string crossings;
  for (const ffrf::EngineOrderCrossing& c : o.crossings)
    crossings += fmt::format("{}EO {} x mode {} at {:.4g} rad/s ({:.0f} rpm, {:.2f} Hz)", crossings.empty() ? "" : "; ",
                             c.engine_order, c.mode, c.speed, c.speed * 60.0 / (2 * 3.141592653589793), c.frequency_hz);
  run.facts.emplace_back("engine-order crossings (Campbell)",
                         crossings.empty() ? std::string("none in the speed range") : crossings);
  if (!o.modes_at_speed.stable)
    run.warnings.push_back(
        fmt::format("the linearized model is unstable at {} rad/s (growth rate {:.3g} 1/s): the centrifugal softening "
                    "exceeds the stiffness",
                    format_setting(o.modes_at_speed.speed), o.modes_at_speed.max_growth_rate));
}

void describe(const ContactModalSpec& spec, const ContactModalOutcome& o, RunRecord& run) {
  run.facts.emplace_back(
      "analysis",
      fmt::format(
          "static contact (penalty, status iterations) and modes about it, at {} interferences x {} penalty "
          "factors; kn = FKN E / h (h: the contact face's size), normal law {}, tangential {}; stress "
          "stiffening {}",
          spec.interferences.size(), spec.penalty_factors.size(),
          spec.roughness > 0 ? fmt::format("stiffening with the pressure (roughness {:g} m)", spec.roughness)
                             : std::string("linear"),
          spec.sticking ? fmt::format("sticking, kt = {} kn", format_setting(spec.tangential_ratio)) : "frictionless",
          spec.prestress ? "on" : "off"));
  run.facts.emplace_back("contact pairs", fmt::format("{} ({} Gauss points), {} free DOFs",
                                                      fmt::join(o.pair_names, ", "), o.contact_points, o.free_dofs));
  double static_s = 0, modal_s = 0;
  int iterations = 0, most = 0;
  for (const ContactGridPoint& p : o.grid) {
    static_s += p.static_seconds;
    modal_s += p.modal_seconds;
    iterations += p.static_iterations;
    most = std::max(most, p.static_iterations);
  }
  const double n = static_cast<double>(std::max<size_t>(o.grid.size(), 1));
  run.facts.emplace_back(
      "cost per grid point [s]",
      fmt::format("static contact {:.3f} ({:.1f} status iterations on average, at most {}), modes "
                  "{:.3f}; setup {:.3f}; glued reference {:.3f}",
                  static_s / n, iterations / n, most, modal_s / n, o.setup_seconds, o.glued_seconds));
  if (o.glued_hz.size() > 0) {
    std::string glued;
    for (Eigen::Index m = 0; m < o.glued_hz.size(); ++m) glued += fmt::format("{}{:.2f}", m ? ", " : "", o.glued_hz[m]);
    run.facts.emplace_back("glued model [Hz]", glued);
  }
}

}  // namespace

void describe_model(const ModelSpec& spec, bool driven_contact, const Model& model, RunRecord& run) {
  const Mesh& mesh = model.mesh;
  std::string elements;
  for (const auto& b : mesh.blocks)
    elements += fmt::format("{}{} x {}", elements.empty() ? "" : ", ", b.ids.size(), element_name(b.type));
  std::string source;
  switch (spec.mesh.kind) {
    case MeshSpec::Kind::csv:
      source = fmt::format("CSV ({}, {})", spec.mesh.nodes_csv.filename().string(),
                           spec.mesh.elements_csv.filename().string());
      break;
    case MeshSpec::Kind::mapped_quad:
      source = fmt::format("mapped quad, {} x {} divisions", spec.mesh.mapped.nx, spec.mesh.mapped.ny);
      break;
    case MeshSpec::Kind::hex_blocks:
      source = fmt::format("{} hexahedral block(s) merged at coincident nodes", spec.mesh.blocks.size());
      break;
    case MeshSpec::Kind::gmsh:
      source = fmt::format("Gmsh {}", spec.mesh.gmsh_file.filename().string());
      break;
    case MeshSpec::Kind::inp:
      source = fmt::format("deck {}", spec.mesh.inp_file.filename().string());
      break;
    case MeshSpec::Kind::none:
      run.facts.emplace_back("model", driven_contact
                                          ? "none: one contact driven by an imposed relative motion (test rig)"
                                          : "no mesh: reduced or lumped models given by their matrices");
      return;
    case MeshSpec::Kind::blade_section: {
      const BladeSectionDivisions& n = spec.mesh.blade_divisions;
      source = fmt::format(
          "chapter-2 blade (the two-blade article's blade in its plane{}): root {} x {}, neck {} rows, lip {} rows, "
          "airfoil "
          "{} x {}{}",
          spec.mesh.element == ElementType::hex8 ? ", extruded, damper-face corners left out" : "",
          2 * n.root_side_columns + n.airfoil_columns + 2, n.root_rows, n.neck_rows, n.lip_rows, n.airfoil_columns,
          n.airfoil_rows, spec.mesh.element == ElementType::hex8 ? fmt::format(", {} layers through t", n.layers) : "");
      break;
    }
    case MeshSpec::Kind::bladed_disk: {
      const BladedDiskDimensions& d = spec.mesh.bladed_disk;
      source = fmt::format(
          "bladed-disk sector ({} sectors; bore {:.4g} m, rim {:.4g} m, tip {:.4g} m), refinement {}, "
          "{} divisions along the chord, {} along the airfoil",
          d.sectors, d.bore_radius(), d.rim_radius(), d.tip_radius(), d.refinement, d.chord_divisions * d.refinement,
          d.airfoil_divisions * d.refinement);
      std::string dims;
      for (const BladedDiskDimensionField& f : bladed_disk_dimension_fields())
        dims += fmt::format("{}{} = {}", dims.empty() ? "" : ", ", f.name, format_setting(d.*f.member));
      run.facts.emplace_back("bladed-disk dimensions [m]", dims);
      break;
    }
    case MeshSpec::Kind::two_blade: {
      const TwoBladeDimensions& d = spec.mesh.two_blade;
      source = fmt::format(
          "two-blade article (2 blades, 2 wedges, fixture), refinement {}, {} divisions through t, "
          "{} along the airfoil, glued at coincident nodes (tolerance {} m)",
          d.refinement, d.nz(), d.airfoil_divisions * d.refinement, format_setting(spec.mesh.merge_tolerance));
      std::string dims;
      for (const TwoBladeDimensionField& f : two_blade_dimension_fields())
        dims += fmt::format("{}{} = {}", dims.empty() ? "" : ", ", f.name, format_setting(d.*f.member));
      run.facts.emplace_back("two-blade dimensions [m, deg]", dims);
      break;
    }
  }
  run.facts.emplace_back("mesh", source);
  for (const std::string& note : model.import_notes) run.facts.emplace_back("read from the deck", note);
  run.facts.emplace_back("elements", elements);
  run.facts.emplace_back("nodes", std::to_string(mesh.n_nodes()));
  run.facts.emplace_back("E [Pa], nu, rho [kg/m^3]",
                         fmt::format("{}, {}, {}", format_setting(spec.section.youngs_modulus),
                                     format_setting(spec.section.poisson_ratio), format_setting(spec.section.density)));
  if (mesh.dim == 2) run.facts.emplace_back("thickness [m]", format_setting(spec.section.thickness));
  for (const auto& l : model.loads)
    run.facts.emplace_back(fmt::format("load on '{}'", l.set),
                           fmt::format("{} N along {}, split {}", format_setting(l.total), "xyz"[l.direction],
                                       l.split == LoadSplit::equal ? "equally" : "consistently over the edge"));
  auto vec = [&](const Eigen::Vector3d& v) {
    return mesh.dim == 2
               ? fmt::format("({}, {})", format_setting(v.x()), format_setting(v.y()))
               : fmt::format("({}, {}, {})", format_setting(v.x()), format_setting(v.y()), format_setting(v.z()));
  };
  const char* facets = mesh.dim == 2 ? "boundary edges" : "boundary faces";
  for (const SurfaceLoad& l : model.surface_loads)
    run.facts.emplace_back(
        fmt::format("{} on '{}'", l.kind == SurfaceLoad::Kind::pressure ? "pressure" : "traction", l.set),
        l.kind == SurfaceLoad::Kind::pressure
            ? fmt::format("{} Pa normal to the {} of the set (> 0 pushes into the body), consistent nodal forces",
                          format_setting(l.pressure), facets)
            : fmt::format("{} Pa on the {} of the set, consistent nodal forces", vec(l.traction), facets));
  for (const BodyLoad& l : model.body_loads)
    run.facts.emplace_back(
        l.kind == BodyLoad::Kind::gravity ? "gravity" : "centrifugal load",
        l.kind == BodyLoad::Kind::gravity
            ? fmt::format("{} m/s^2 on every element, through its consistent mass", vec(l.acceleration))
            : fmt::format("{} rad/s about the axis ({}, {}, {}) through {} m, through the consistent mass (no spin "
                          "softening, no stress stiffening)",
                          format_setting(l.speed), format_setting(l.axis.x()), format_setting(l.axis.y()),
                          format_setting(l.axis.z()), vec(l.origin)));
}

void describe_analysis(const AnalysisSpec& spec, const AnalysisResults& results, const Model& model, RunRecord& run) {
  visit_analysis(spec, results, [&](const auto& s, const auto& outcome) {
    if constexpr (requires { describe(s, outcome, model, run); })
      describe(s, outcome, model, run);  // facts that name nodes
    else
      describe(s, outcome, run);
  });
}

}  // namespace bb
