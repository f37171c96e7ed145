#include "cli/run_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <system_error>

#include <unistd.h>

#include "analysis/case_results.hpp"
#include "analysis/modal_analysis.hpp"
#include "analysis/mode_pairs.hpp"
#include "analysis/static_analysis.hpp"
#include "cases/calibration_spec.hpp"
#include "common/errors.hpp"
#include "reduction/reduced_model_io.hpp"
#include "report/contact_loop_plots.hpp"
#include "report/frf_plots.hpp"
#include "report/hbm_plots.hpp"
#include "report/time_plots.hpp"
#include "report/plots.hpp"
#include "report/writers.hpp"
#include "study/modal_refinement.hpp"
#include "study/hbm_study.hpp"
#include "study/time_study.hpp"
#include "study/rom_study.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::string g(double v) { return fmt::format("{:.6g}", v); }

void describe_model(const CaseSpec& spec, const Model& model, RunRecord& run) {
  const Mesh& mesh = model.mesh;
  std::string elements;
  for (const auto& b : mesh.blocks) elements += fmt::format("{}{} x {}", elements.empty() ? "" : ", ", b.ids.size(), element_name(b.type));
  std::string source;
  switch (spec.mesh.kind) {
    case MeshSpec::Kind::csv:
      source = fmt::format("CSV ({}, {})", spec.mesh.nodes_csv.filename().string(), spec.mesh.elements_csv.filename().string());
      break;
    case MeshSpec::Kind::mapped_quad:
      source = fmt::format("mapped quad, {} x {} divisions", spec.mesh.mapped.nx, spec.mesh.mapped.ny);
      break;
    case MeshSpec::Kind::hex_blocks:
      source = fmt::format("{} hexahedral block(s) merged at coincident nodes", spec.mesh.blocks.size());
      break;
    case MeshSpec::Kind::gmsh: source = fmt::format("Gmsh {}", spec.mesh.gmsh_file.filename().string()); break;
    case MeshSpec::Kind::none:
      run.facts.emplace_back("model", spec.analysis.type == AnalysisType::contact_loop
                                          ? "none: one contact driven by an imposed relative motion (test rig)"
                                          : "no mesh: reduced or lumped models given by their matrices");
      return;
    case MeshSpec::Kind::two_blade: {
      const TwoBladeDimensions& d = spec.mesh.two_blade;
      source = fmt::format("two-blade article (2 blades, 2 wedges, fixture), refinement {}, {} divisions through t, "
                           "{} along the airfoil, glued at coincident nodes (tolerance {} m)",
                           d.refinement, d.nz(), d.airfoil_divisions * d.refinement, g(spec.mesh.merge_tolerance));
      std::string dims;
      for (const TwoBladeDimensionField& f : two_blade_dimension_fields())
        dims += fmt::format("{}{} = {}", dims.empty() ? "" : ", ", f.name, g(d.*f.member));
      run.facts.emplace_back("two-blade dimensions [m, deg]", dims);
      break;
    }
  }
  run.facts.emplace_back("mesh", source);
  run.facts.emplace_back("elements", elements);
  run.facts.emplace_back("nodes", std::to_string(mesh.n_nodes()));
  run.facts.emplace_back("E [Pa], nu, rho [kg/m^3]", fmt::format("{}, {}, {}", g(spec.section.youngs_modulus),
                                                                 g(spec.section.poisson_ratio), g(spec.section.density)));
  if (mesh.dim == 2) run.facts.emplace_back("thickness [m]", g(spec.section.thickness));
  for (const auto& l : model.loads)
    run.facts.emplace_back(fmt::format("load on '{}'", l.set),
                           fmt::format("{} N along {}, split {}", g(l.total), "xyz"[l.direction],
                                       l.split == LoadSplit::equal ? "equally" : "consistently over the edge"));
}

void describe_frf(const FrfSpec& spec, const FrfOutcome& frf, RunRecord& run) {
  std::string forces;
  for (const FrfForce& f : spec.forces) forces += fmt::format("{}{} N on {}", forces.empty() ? "" : ", ", g(f.amplitude), f.dof.name());
  const std::string damping = spec.damping.kind == FrfDamping::Kind::modal
                                  ? fmt::format("modal, zeta = {}", g(spec.damping.zeta))
                                  : fmt::format("Rayleigh, zeta = {} at {} Hz and {} at {} Hz", g(spec.damping.rayleigh_zeta[0]),
                                                g(spec.damping.rayleigh_hz[0]), g(spec.damping.rayleigh_zeta[1]), g(spec.damping.rayleigh_hz[1]));
  run.facts.emplace_back("analysis", fmt::format("linear forced response, {} to {} Hz, {} ({} frequencies), {}; force {}",
                                                 g(spec.f_min), g(spec.f_max),
                                                 spec.adaptive ? fmt::format("step {} Hz refined to {} Hz around peaks", g(spec.step), g(spec.min_step))
                                                               : fmt::format("step {} Hz", g(spec.step)),
                                                 frf.sweep.frequency_hz.size(), damping, forces));
  if (frf.full_modal) {
    run.facts.emplace_back("full mesh", fmt::format("{} free DOFs; modal superposition (eq 3.32) of the lowest {} modes (up to {:.1f} Hz){}",
                                                    frf.full_modal->n_free_dofs, frf.full_modal->frequencies_hz.size(),
                                                    frf.full_modal->frequencies_hz.maxCoeff(),
                                                    spec.residual_flexibility ? " + static residual flexibility of the rest" : ""));
    run.facts.emplace_back("full mesh: assembly / modes + residual / sweep [s]",
                           fmt::format("{:.2f} / {:.2f} / {:.4f}", frf.full_modal->assembly_seconds, frf.full_setup_seconds, frf.full_sweep_seconds));
  }
  for (size_t i = 0; i < frf.roms.size(); ++i) {
    const RomOutcome& r = frf.roms[i];
    const RomSpec& rs = spec.roms[i];
    const std::string origin = rs.file.empty() ? fmt::format("Craig-Bampton, masters {} (3 DOFs each), {} fixed-interface modes",
                                                             fmt::join(rs.masters, " "), rs.modes)
                                               : fmt::format("read from {}", rs.file.filename().string());
    run.facts.emplace_back(fmt::format("reduced model '{}'", r.name),
                           fmt::format("{} DOFs, {}; response by {}", r.model.size(), origin,
                                       rs.method == RomSpec::Method::direct ? "direct solve of D(w)" : "modal superposition"));
    run.facts.emplace_back(fmt::format("reduced model '{}': constraint modes / fixed-interface modes / projection / sweep [s]", r.name),
                           fmt::format("{:.2f} / {:.2f} / {:.3f} / {:.4f}", r.timing.constraint_modes_seconds, r.timing.fixed_interface_seconds,
                                       r.timing.projection_seconds, r.sweep_seconds));
  }
}

void describe_hbm(const HbmSpec& spec, const HbmOutcome& hbm, RunRecord& run) {
  const PreparedHbm& p = hbm.prepared;
  std::string levels;
  for (double f : spec.force_levels) levels += fmt::format("{}{}", levels.empty() ? "" : ", ", g(f));
  const std::string damping = spec.damping_matrix ? "damping matrix given in the case"
                              : spec.damping.kind == FrfDamping::Kind::modal
                                  ? fmt::format("modal damping {} on every mode of the linear model", g(spec.damping.zeta))
                                  : fmt::format("Rayleigh damping fitted to zeta = {}, {} at {}, {} Hz", g(spec.damping.rayleigh_zeta[0]),
                                                g(spec.damping.rayleigh_zeta[1]), g(spec.damping.rayleigh_hz[0]), g(spec.damping.rayleigh_hz[1]));
  const std::string sweep = spec.sweep.method == HbmSweepSpec::Method::grid
                                ? fmt::format("a {} Hz grid (Newton from the secant guess)", g(spec.sweep.step_hz))
                                : "pseudo-arclength continuation";
  run.facts.emplace_back("analysis", fmt::format("harmonic balance, H = {}, {} time samples per period, {} to {} Hz by {}; {}", spec.harmonics,
                                                 spec.time_samples > 0 ? g(spec.time_samples) : "automatic", g(spec.sweep.f_min),
                                                 g(spec.sweep.f_max), sweep, damping));
  run.facts.emplace_back("force levels [N] (amplitude of the first force)", levels);
  std::string contacts;
  for (const hbm::ContactElement& c : p.model.contacts)
    contacts += fmt::format("{}{}: kn {} N/m, kt {} N/m, mu {}", contacts.empty() ? "" : "; ", p.contact_names[static_cast<size_t>(&c - p.model.contacts.data())],
                            g(c.law.kn), g(c.law.kt), g(c.law.mu));
  run.facts.emplace_back("contacts", contacts);
  run.facts.emplace_back("model DOFs / linear model DOFs", fmt::format("{} / {}", p.model.mass.rows(), p.blade_dofs));
  if (p.damper_static) {
    std::string n0;
    for (size_t c = 0; c < p.damper->contacts.size(); ++c)
      n0 += fmt::format("{}{} {:.4g} N{}", n0.empty() ? "" : ", ", p.damper->contacts[c].name, p.damper_static->normal_preload[static_cast<Eigen::Index>(c)],
                        p.damper_static->open[c] ? " (open)" : "");
    run.facts.emplace_back("damper static pre-solve: normal loads", n0);
  }
  run.facts.emplace_back("setup (reduction + matrices) / all sweeps [s]", fmt::format("{:.2f} / {:.3f}", p.setup_seconds, hbm.sweep_seconds));
  int reached = 0, points = 0;
  for (const HbmLevel& l : hbm.levels) {
    reached += l.path.converged ? 1 : 0;
    points += static_cast<int>(l.path.points.size());
    if (!l.path.converged) run.facts.emplace_back(fmt::format("sweep at Fe = {} N stopped", g(l.force)), l.path.failure);
  }
  run.facts.emplace_back("sweeps that reached the end / points", fmt::format("{} of {} / {}", reached, hbm.levels.size(), points));
}

void describe_time(const TimeSpec& spec, const TimeOutcome& time, RunRecord& run) {
  const PreparedHbm& p = time.prepared;
  run.facts.emplace_back("analysis", fmt::format("direct time integration ({}), {} steps per period, stepped sine {} to {} Hz every {} Hz, "
                                                 "each frequency to a cycle-to-cycle change below {} (at most {} periods) from the "
                                                 "previous one's state; first {} harmonic(s) by DFT over the last period",
                                                 spec.alpha == 0.0 ? "Newmark average acceleration" : fmt::format("HHT-alpha, alpha = {}", g(spec.alpha)),
                                                 spec.steps_per_period, g(spec.system.sweep.f_min), g(spec.system.sweep.f_max),
                                                 g(spec.system.sweep.step_hz), g(spec.steady_tolerance), spec.max_cycles, spec.system.harmonics));
  std::string levels;
  for (double f : spec.system.force_levels) levels += fmt::format("{}{}", levels.empty() ? "" : ", ", g(f));
  run.facts.emplace_back("force levels [N] (amplitude of the first force)", levels);
  std::string contacts;
  for (size_t c = 0; c < p.model.contacts.size(); ++c)
    contacts += fmt::format("{}{}: kn {} N/m, kt {} N/m, mu {}", contacts.empty() ? "" : "; ", p.contact_names[c], g(p.model.contacts[c].law.kn),
                            g(p.model.contacts[c].law.kt), g(p.model.contacts[c].law.mu));
  run.facts.emplace_back("contacts", contacts.empty() ? "none (linear model)" : contacts);
  run.facts.emplace_back("model DOFs", std::to_string(p.model.mass.rows()));
  long steps = 0, not_steady = 0;
  double seconds = 0;
  for (const TimeLevel& l : time.levels) {
    steps += l.steps;
    seconds += l.seconds;
    for (bool s : l.steady) not_steady += s ? 0 : 1;
  }
  run.facts.emplace_back("steps / frequencies not steady / time [s]", fmt::format("{} / {} / {:.2f} (per step {:.2f} us)", steps, not_steady,
                                                                                  seconds, 1e6 * seconds / static_cast<double>(std::max(1L, steps))));
  if (spec.compare_harmonics > 0) run.facts.emplace_back("comparison", fmt::format("harmonic balance, H = {}, same grid", spec.compare_harmonics));
  if (time.record)
    run.facts.emplace_back("recorded run", fmt::format("{} Hz, Fe = {} N: steady after {} periods ({}), then {} periods recorded{}",
                                                       g(time.record->frequency_hz), g(time.record->force), time.record->steady.cycles,
                                                       time.record->steady.converged ? "converged" : time.record->steady.failure,
                                                       spec.history_cycles, time.record->history.converged ? "" : ": " + time.record->history.failure));
}

void describe_contact_loop(const ContactLoopSpec& spec, const ContactLoopOutcome& loop, RunRecord& run) {
  const contact::JenkinsParameters& p = spec.law;
  run.facts.emplace_back("analysis", fmt::format("friction-contact test rig: one Jenkins contact under u = {} cos(theta) m, "
                                                 "v = {} cos(theta + {} deg) m (v > 0 presses), {} samples per period, "
                                                 "AFT march to the periodic steady state",
                                                 g(spec.tangential_amplitude), g(spec.normal_amplitude), g(spec.normal_phase_deg), spec.samples));
  run.facts.emplace_back("contact", fmt::format("kn {} N/m, kt {} N/m, mu {}, n0 {} N: slip force mu n0 = {} N, slip displacement "
                                                "mu n0 / kt = {} m",
                                                g(p.kn), g(p.kt), g(p.mu), g(p.n0), g(p.mu * p.n0), g(p.mu * p.n0 / p.kt)));
  run.facts.emplace_back("periods marched / loop closed", fmt::format("{} / {} (slider mismatch {:.3g} m)", loop.aft.periods,
                                                                      loop.aft.closed ? "yes" : "NO", loop.aft.closure_mismatch));
}

void analyse(const CaseSpec& spec, const Model& model, const fs::path& out, const RunOptions& options, RunRecord& run) {
  // Long sweeps report progress on a terminal only (one line, rewritten in place).
  HbmProgress progress;
  if (isatty(STDERR_FILENO)) progress = [](const std::string& line) { std::fprintf(stderr, "\r\033[K%s", line.c_str()); };
  const CaseResults results = compute_case_results(spec, model, progress);
  if (progress) std::fputs("\r\033[K", stderr);
  const ResultTables& tables = results.tables;
  const std::optional<ModalResult>& modal = results.modal;
  if (results.static_solution) {
    const StaticSolution& sol = *results.static_solution;
    run.facts.emplace_back("analysis", "linear static, sparse Cholesky (CHOLMOD)");
    run.facts.emplace_back("free DOFs", std::to_string(sol.n_free_dofs));
    run.facts.emplace_back("pivot ratio (rcond estimate)", fmt::format("{:.3e}", sol.pivot_ratio));
    run.facts.emplace_back("relative residual ||Ku - f|| / ||f||", fmt::format("{:.3e}", sol.relative_residual));
    const double applied = sol.loads.sum(), reacted = sol.reactions.sum();
    run.facts.emplace_back("force balance |sum f + sum R| [N]", fmt::format("{:.3e}", std::abs(applied + reacted)));
    run.facts.emplace_back("assembly / factor+solve [s]", fmt::format("{:.4f} / {:.4f}", sol.assembly_seconds, sol.solve_seconds));
  } else if (results.frf) {
    describe_frf(spec.analysis.frf, *results.frf, run);
  } else if (results.hbm) {
    describe_hbm(spec.analysis.hbm, *results.hbm, run);
  } else if (results.contact_loop) {
    describe_contact_loop(spec.analysis.contact_loop, *results.contact_loop, run);
  } else if (results.time) {
    describe_time(spec.analysis.time, *results.time, run);
  } else {
    const ModeSelection& sel = spec.analysis.modes;
    run.facts.emplace_back("analysis", fmt::format("modal, {}, Lanczos shift-invert (Spectra + CHOLMOD)",
                                                   sel.band_max_hz ? fmt::format("all modes in [{}, {}] Hz", sel.band_min_hz.value_or(0.0), *sel.band_max_hz)
                                                                   : fmt::format("lowest {} modes", sel.lowest)));
    run.facts.emplace_back("free DOFs", std::to_string(modal->n_free_dofs));
    run.facts.emplace_back("Lanczos iterations", std::to_string(modal->iterations));
    run.facts.emplace_back("completeness (Sturm count of K - sigma M)",
                           modal->sturm_count < 0
                               ? std::string("not checked (every mode found is a rigid-body mode)")
                               : fmt::format("{} modes below {:.6g} Hz, all found ({} Lanczos run{}, count {:.3f} s)", modal->sturm_count,
                                             modal->sturm_frequency_hz, modal->lanczos_runs, modal->lanczos_runs > 1 ? "s" : "",
                                             modal->sturm_seconds));
    if (modal->rigid_body_modes > 0)
      run.facts.emplace_back("rigid-body modes (free model)", std::to_string(modal->rigid_body_modes));
    run.facts.emplace_back("max eigen-residual (backward error)", fmt::format("{:.3e}", modal->max_residual));
    run.facts.emplace_back("assembly / eigensolve [s]", fmt::format("{:.4f} / {:.4f}", modal->assembly_seconds, modal->solve_seconds));
    if (spec.analysis.pairs) {
      const ModePairSpec& p = *spec.analysis.pairs;
      run.facts.emplace_back("mode labels", fmt::format("pair: sign of '{}' vs '{}' along {}; type: motion of tip face '{}' "
                                                        "(else '{}')", p.left, p.right, "xyz"[p.direction], p.right_tip, p.left_tip));
    }
  }
  for (const CheckSpec& c : spec.checks) {
    auto entries = evaluate_check(c, tables);
    run.checks.insert(run.checks.end(), entries.begin(), entries.end());
  }
  fs::create_directories(out);
  for (const auto& [name, table] : tables) {
    write_table_csv(table, out / (name + ".csv"));
    run.tables.push_back(name + ".csv");
    if (!table.text_columns.empty()) run.listed_tables.push_back(table);
  }
  if (results.hbm && !spec.analysis.hbm.model.masters.empty()) {
    const fs::path sidecar = out / "reduced_models" / (spec.analysis.hbm.model.name + ".toml");
    fs::create_directories(sidecar.parent_path());
    write_reduced_model(results.hbm->prepared.linear, sidecar);
    run.tables.push_back("reduced_models/" + spec.analysis.hbm.model.name + ".toml");
  }
  if (results.frf) {
    // Reduced models built here are written out, so they can be read back (`file = ...`) or used elsewhere.
    for (const RomOutcome& r : results.frf->roms) {
      if (r.model.recovery.size() == 0) continue;  // read from a file: nothing new
      const fs::path sidecar = out / "reduced_models" / (r.name + ".toml");
      fs::create_directories(sidecar.parent_path());
      write_reduced_model(r.model, sidecar);
      run.tables.push_back("reduced_models/" + r.name + ".toml");
    }
  }
  if (options.plots) {
    if (results.static_solution)
      run.plots.push_back(plot_deformed_mesh(model.mesh, results.static_solution->displacements, out, "deformed", "Deformed mesh"));
    if (modal) {
      for (size_t k = 0; k < std::min<size_t>(4, modal->shapes.size()); ++k)
        run.plots.push_back(plot_deformed_mesh(model.mesh, modal->shapes[k], out, fmt::format("mode{}", k + 1),
                                               fmt::format("Mode {}: {:.4f} Hz", k + 1, modal->frequencies_hz[static_cast<Eigen::Index>(k)])));
    }
    if (results.frf) {
      std::vector<std::string> outputs;  // each response once, in order of appearance
      for (const FrfCurveSet& c : results.frf->curves)
        for (const std::string& o : c.outputs)
          if (std::find(outputs.begin(), outputs.end(), o) == outputs.end()) outputs.push_back(o);
      for (const std::string& o : outputs) run.plots.push_back(plot_frf(*results.frf, o, out, "frf_" + o));
      if (!results.frf->level_forces.empty()) run.plots.push_back(plot_force_levels(*results.frf, out, "force_levels"));
    }
    if (results.contact_loop) run.plots.push_back(plot_contact_loop(*results.contact_loop, out, "hysteresis"));
    if (results.time) {
      const TimeOutcome& t = *results.time;
      for (size_t r = 0; r < t.prepared.response_names.size(); ++r)
        run.plots.push_back(plot_time_frf(t, r, out, "frf_" + t.prepared.response_names[r]));
      if (t.record && t.record->history.steps > 0 && !t.prepared.contact_names.empty()) {
        run.plots.push_back(plot_hysteresis(t, out, "hysteresis"));
        run.plots.push_back(plot_contact_forces(t, out, "contact_forces"));
      }
    }
    if (results.hbm) {
      const HbmOutcome& h = *results.hbm;
      for (size_t r = 0; r < h.prepared.response_names.size(); ++r)
        run.plots.push_back(plot_hbm_levels(h, r, false, out, "frf_levels_" + h.prepared.response_names[r]));
      run.plots.push_back(plot_hbm_levels(h, 0, true, out, "frf_per_newton_" + h.prepared.response_names[0]));
      fs::path reference;  // the thesis's peaks, when a check compares with them
      for (const CheckSpec& c : spec.checks)
        if (c.result == "peaks" && !c.reference.empty() && reference.empty()) reference = c.reference;
      run.plots.push_back(plot_hbm_performance(h, "hz", reference, out, "performance_frequency"));
      run.plots.push_back(plot_hbm_performance(h, "amp_per_n", reference, out, "performance_amplitude"));
      for (const char* kind : {"IP", "OOP", "peak"})
        if ((std::string(kind) == "peak") != h.prepared.ip_oop.has_value())
          run.plots.push_back(plot_contact_states(h, kind, out, fmt::format("contact_states_{}", kind)));
    }
    int i = 0;
    for (const CheckSpec& c : spec.checks) run.plots.push_back(plot_check(run.checks, c.name, out, fmt::format("check{}", ++i)));
  }
  if (options.study && spec.modal_study) {
    run.modal_study = run_modal_refinement_study(spec);
    run.study_note = spec.modal_study->note;
    if (options.plots) run.study_plots.push_back(plot_modal_refinement(*run.modal_study, out, "study_modal"));
  }
  if (options.study && spec.hbm_study && results.hbm) {
    run.study_tables.push_back(run_hbm_harmonics_study(spec.analysis.hbm, results.hbm->prepared, *spec.hbm_study));
    run.study_note = spec.hbm_study->note;
    write_table_csv(run.study_tables.back(), out / "hbm_harmonics_study.csv");
    if (options.plots) run.study_plots.push_back(plot_hbm_harmonics_study(run.study_tables.back(), out, "study_harmonics"));
  }
  if (options.study && spec.time_study) {
    run.study_tables.push_back(run_time_step_study(model, spec.analysis.time, *spec.time_study));
    run.study_note = spec.time_study->note;
    write_table_csv(run.study_tables.back(), out / "time_step_study.csv");
    if (options.plots) run.study_plots.push_back(plot_time_step_study(run.study_tables.back(), out, "study_time_steps"));
  }
  if (options.study && spec.rom_study) {
    run.study_tables.push_back(run_rom_study(spec, model));
    run.study_note = spec.rom_study->note;
    write_table_csv(run.study_tables.back(), out / "rom_study.csv");
    if (options.plots) run.study_plots.push_back(plot_rom_study(run.study_tables.back(), out, "study_rom"));
  }
  if (options.study && spec.study) {
    run.study = run_refinement_study(spec);
    run.study_note = spec.study->note;
    if (options.plots) {
      run.study_plots.push_back(plot_refinement_error(*run.study, out, "study_error"));
      run.study_plots.push_back(plot_refinement_cost(*run.study, out, "study_cost"));
    }
  }
  bool all_pass = true;
  for (const CheckEntry& e : run.checks) all_pass = all_pass && e.pass;
  run.status = run.checks.empty() ? RunStatus::no_checks : (all_pass ? RunStatus::pass : RunStatus::fail);
}

}  // namespace

RunOutcome run_case(const fs::path& case_file, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  RunOutcome outcome;
  RunRecord& run = outcome.record;
  run.case_file = case_file;
  run.case_name = case_file.stem().string();
  run.title = run.case_name;
  outcome.out_dir = options.out_dir.value_or(fs::path("reports") / run.case_name);
  try {
    const toml::table case_table = read_case_table(case_file);
    const CaseSpec spec = parse_case_table(case_table, case_file);
    parse_calibration(case_table, case_file, spec);  // a bad [calibration] or data file fails here too, not only in `calibrate`
    run.case_name = spec.name;
    run.title = spec.title;
    run.description = spec.description;
    run.check_specs = spec.checks;
    outcome.out_dir = options.out_dir.value_or(fs::path("reports") / spec.name);
    fs::create_directories(outcome.out_dir);
    fs::remove(outcome.out_dir / "summary.json");  // a stale success must not survive a failed rerun
    const Model model = build_model(spec);
    describe_model(spec, model, run);
    try {
      analyse(spec, model, outcome.out_dir, options, run);
    } catch (const InputError& e) {
      // Errors found by the solvers concern the model as a whole: name the case they came from.
      const std::string what = e.what();
      throw InputError(what.starts_with(case_file.string()) ? what : fmt::format("{}: {}", case_file.string(), what));
    }
  } catch (const InputError& e) {
    run.status = RunStatus::bad_input;
    run.message = e.what();
  } catch (const SolverError& e) {
    run.status = RunStatus::solver_failed;
    run.message = e.what();
  } catch (const std::exception& e) {
    run.status = RunStatus::solver_failed;
    run.message = fmt::format("internal error: {}", e.what());
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  try {
    fs::create_directories(outcome.out_dir);
    write_report_md(run, outcome.out_dir / "report.md");
    write_summary_json(run, outcome.out_dir / "summary.json");
  } catch (const std::exception& e) {
    run.status = RunStatus::solver_failed;
    run.message = fmt::format("could not write the report: {}", e.what());
  }
  return outcome;
}

}  // namespace bb
