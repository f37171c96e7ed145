#include "analysis/frf_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>

#include "analysis/operating_deflection.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/seconds_since.hpp"
#include "forced/linear_model.hpp"
#include "frf/receptance.hpp"
#include "linalg/dense_eigen.hpp"
#include "reduction/reduced_model_io.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

// Not file-local: PreparedFrf, declared in the header, holds one.
// Full mesh: eq 3.32 over its lowest modes plus the static residual of the rest.
struct FullResponse {
  ModalReceptance receptance;
  Eigen::VectorXd force;  // amplitudes of the force DOFs

  Eigen::VectorXcd at(double omega) const { return receptance.at(omega) * force.cast<std::complex<double>>(); }
};

namespace {

FullResponse full_response(const Model& model, const FreeSystem& system, const FrfSpec& spec,
                           const ModalResult& modal) {
  FullResponse r;
  const auto n_modes = static_cast<Eigen::Index>(modal.shapes.size());
  const auto n_out = static_cast<Eigen::Index>(spec.responses.size());
  const auto n_in = static_cast<Eigen::Index>(spec.forces.size());
  auto shapes_at = [&](const PointDof& dof) {
    const int node = node_of_point(model, dof.point);
    Eigen::RowVectorXd row(n_modes);
    for (Eigen::Index k = 0; k < n_modes; ++k) row[k] = modal.shapes[static_cast<size_t>(k)](node, dof.direction);
    return row;
  };
  r.receptance.omega = kTwoPi * modal.frequencies_hz;
  r.receptance.zeta = modal_zetas(spec.damping, r.receptance.omega);
  r.receptance.shapes_out.resize(n_out, n_modes);
  r.receptance.shapes_in.resize(n_in, n_modes);
  r.force.resize(n_in);
  for (Eigen::Index i = 0; i < n_out; ++i)
    r.receptance.shapes_out.row(i) = shapes_at(spec.responses[static_cast<size_t>(i)]);
  for (Eigen::Index j = 0; j < n_in; ++j) {
    r.receptance.shapes_in.row(j) = shapes_at(spec.forces[static_cast<size_t>(j)].dof);
    r.force[j] = spec.forces[static_cast<size_t>(j)].amplitude;
  }
  if (spec.residual_flexibility) {
    if (r.receptance.omega.size() > 0 && r.receptance.omega.minCoeff() <= 0.0)
      throw InputError(
          "'analysis.residual_flexibility': the model has rigid-body modes; constrain it or set it to false");
    SpdFactorization factor(ordering_for_dimension(model.mesh.dim));
    const FactorStatus status = factor.factorize(system.stiffness);
    if (!status.ok)
      throw InputError(fmt::format("residual flexibility: the stiffness cannot be factored: {}", status.message));
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(system.dofs.n_free, n_in);
    for (Eigen::Index j = 0; j < n_in; ++j)
      unit(free_index(model, system, spec.forces[static_cast<size_t>(j)].dof), j) = 1.0;
    const Eigen::MatrixXd columns = factor.solve(unit);
    Eigen::MatrixXd flexibility(n_out, n_in);
    for (Eigen::Index i = 0; i < n_out; ++i)
      flexibility.row(i) = columns.row(free_index(model, system, spec.responses[static_cast<size_t>(i)]));
    r.receptance.residual =
        residual_flexibility(flexibility, r.receptance.shapes_out, r.receptance.shapes_in, r.receptance.omega);
  }
  return r;
}

}  // namespace

// Not file-local: PreparedFrf, declared in the header, holds one.
// A reduced model with its response function.
struct RomResponse {
  RomOutcome outcome;
  Eigen::MatrixXd damping;               // direct method
  std::optional<ModalReceptance> modal;  // modal method
  std::vector<int> out, in;              // reduced DOF indices
  Eigen::VectorXd force;
  std::vector<std::string> outputs;

  Eigen::VectorXcd at(double omega) const {
    if (modal) return modal->at(omega) * force.cast<std::complex<double>>();
    Eigen::VectorXcd y(static_cast<Eigen::Index>(out.size()));
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(outcome.model.size());
    for (size_t j = 0; j < in.size(); ++j) f[in[j]] += force[static_cast<Eigen::Index>(j)];
    const Eigen::VectorXcd x = direct_response(outcome.model.stiffness, damping, outcome.model.mass, omega, f);
    for (size_t i = 0; i < out.size(); ++i) y[static_cast<Eigen::Index>(i)] = x[out[i]];
    return y;
  }
};

namespace {

RomResponse reduced_response(const Model& model, const FreeSystem& system, const FrfSpec& spec, const RomSpec& rom,
                             const ModelCacheSettings* cache) {
  const auto t0 = Clock::now();
  RomResponse r;
  r.outcome.name = rom.name;
  r.outcome.model = build_reduced_model(model, system, rom, &r.outcome.timing, cache);
  const ReducedModel& m = r.outcome.model;
  const std::vector<FrfForce>& forces = rom.forces.empty() ? spec.forces : rom.forces;
  const std::vector<PointDof>& responses = rom.responses.empty() ? spec.responses : rom.responses;
  auto index = [&](const PointDof& dof) {
    const auto i = m.index_of(dof.point, dof.direction);
    if (!i)
      throw InputError(fmt::format(
          "'analysis.rom' '{}': the reduced model has no DOF {} (add the point to its masters)", rom.name, dof.name()));
    return *i;
  };
  for (const PointDof& dof : responses) {
    r.out.push_back(index(dof));
    r.outputs.push_back(dof.name());
  }
  r.force.resize(static_cast<Eigen::Index>(forces.size()));
  for (size_t j = 0; j < forces.size(); ++j) {
    r.in.push_back(index(forces[j].dof));
    r.force[static_cast<Eigen::Index>(j)] = forces[j].amplitude;
  }
  const DenseEigen<double> eig = symmetric_eigen(m.stiffness, m.mass);
  if (!eig.ok) throw SolverError(fmt::format("reduced model '{}': its eigenproblem failed", rom.name));
  const Eigen::VectorXd omega = eig.values.array().max(0.0).sqrt();
  r.outcome.frequencies_hz = omega / kTwoPi;
  if (rom.method == RomSpec::Method::modal) {
    ModalReceptance h;
    h.omega = omega;
    h.zeta = modal_zetas(spec.damping, omega);
    h.shapes_out.resize(static_cast<Eigen::Index>(r.out.size()), omega.size());
    h.shapes_in.resize(static_cast<Eigen::Index>(r.in.size()), omega.size());
    for (size_t i = 0; i < r.out.size(); ++i)
      h.shapes_out.row(static_cast<Eigen::Index>(i)) = eig.vectors.row(r.out[i]);
    for (size_t j = 0; j < r.in.size(); ++j) h.shapes_in.row(static_cast<Eigen::Index>(j)) = eig.vectors.row(r.in[j]);
    r.modal = std::move(h);
  } else {
    r.damping = damping_matrix(spec.damping, m);
  }
  r.outcome.setup_seconds = seconds_since(t0);
  return r;
}

ResultTable frf_table(const FrfOutcome& o) {
  ResultTable t;
  t.name = "frf";
  t.columns = {"point", "frequency_hz"};
  for (const FrfCurveSet& c : o.curves)
    for (const std::string& out : c.outputs) {
      t.columns.push_back(fmt::format("{}.{}.amp_m", c.model, out));
      t.columns.push_back(fmt::format("{}.{}.phase_deg", c.model, out));
    }
  const auto n = static_cast<Eigen::Index>(o.sweep.frequency_hz.size());
  t.values.resize(n, static_cast<Eigen::Index>(t.columns.size()));
  for (Eigen::Index i = 0; i < n; ++i) {
    t.values(i, 0) = static_cast<double>(i + 1);
    t.values(i, 1) = o.sweep.frequency_hz[static_cast<size_t>(i)];
    Eigen::Index col = 2;
    for (Eigen::Index k = 0; k < o.sweep.response.cols(); ++k) {
      const std::complex<double> x = o.sweep.response(i, k);
      t.values(i, col++) = std::abs(x);
      t.values(i, col++) = std::arg(x) * 180.0 / std::numbers::pi;
    }
  }
  return t;
}

struct ModelPeak {
  double frequency_hz;
  double amplitude;
  std::string output;
};

// Peaks of every output of one model above the floor; key 100 r + k: the k-th peak of the r-th
// output (1-based).
ResultTable peak_table(const FrfOutcome& o, const FrfCurveSet& c, double prominence, double floor,
                       std::vector<ModelPeak>& all) {
  const double largest =
      o.sweep.response.middleCols(c.first_column, static_cast<Eigen::Index>(c.outputs.size())).cwiseAbs().maxCoeff();
  ResultTable t;
  t.name = "peaks_" + c.model;
  t.columns = {"peak", "frequency_hz", "amplitude_m"};
  std::vector<std::array<double, 3>> rows;
  std::vector<std::string> names;
  for (size_t r = 0; r < c.outputs.size(); ++r) {
    const Eigen::VectorXd amplitude = o.sweep.response.col(c.first_column + static_cast<Eigen::Index>(r)).cwiseAbs();
    const std::vector<Peak> peaks = find_peaks(o.sweep.frequency_hz, amplitude, prominence);
    size_t k = 0;
    for (const Peak& peak : peaks) {
      if (peak.amplitude < floor * largest) continue;
      rows.push_back({static_cast<double>(100 * (r + 1) + ++k), peak.frequency_hz, peak.amplitude});
      names.push_back(c.outputs[r]);
      all.push_back({peak.frequency_hz, peak.amplitude, c.outputs[r]});
    }
  }
  t.values.resize(static_cast<Eigen::Index>(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i)
    for (Eigen::Index j = 0; j < 3; ++j) t.values(static_cast<Eigen::Index>(i), j) = rows[i][static_cast<size_t>(j)];
  t.add_text_column("response", names);
  return t;
}

// Which full-mesh mode each peak belongs to (Table IX): peaks of several outputs within 0.2 % are
// one resonance; each resonance names the nearest mode within the match tolerance, nearest first,
// so of a close IP / OOP pair merged into one peak only one mode is "seen". Rows: the modes inside
// the sweep.
ResultTable peak_match_table(const std::string& model, std::vector<ModelPeak> peaks, const ModalResult& modal,
                             const std::vector<ModeLabel>& labels, double tolerance, double f_min, double f_max) {
  std::sort(peaks.begin(), peaks.end(),
            [](const ModelPeak& a, const ModelPeak& b) { return a.frequency_hz < b.frequency_hz; });
  std::vector<ModelPeak> resonances;
  std::vector<std::string> seen_in;
  for (const ModelPeak& p : peaks) {
    if (!resonances.empty() && p.frequency_hz <= resonances.back().frequency_hz * 1.002) {
      if (p.amplitude > resonances.back().amplitude) {
        resonances.back().frequency_hz = p.frequency_hz;
        resonances.back().amplitude = p.amplitude;
      }
      seen_in.back() += " " + p.output;
      continue;
    }
    resonances.push_back(p);
    seen_in.push_back(p.output);
  }
  const Eigen::VectorXd& f = modal.frequencies_hz;
  struct Candidate {
    double distance;
    size_t peak;
    Eigen::Index mode;
  };
  std::vector<Candidate> candidates;
  for (size_t p = 0; p < resonances.size(); ++p)
    for (Eigen::Index k = 0; k < f.size(); ++k) {
      const double d = std::abs(resonances[p].frequency_hz / f[k] - 1.0);
      if (d <= tolerance) candidates.push_back({d, p, k});
    }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  std::vector<int> peak_of_mode(static_cast<size_t>(f.size()), -1);
  std::vector<bool> peak_used(resonances.size(), false);
  for (const Candidate& c : candidates) {
    if (peak_used[c.peak] || peak_of_mode[static_cast<size_t>(c.mode)] >= 0) continue;
    peak_used[c.peak] = true;
    peak_of_mode[static_cast<size_t>(c.mode)] = static_cast<int>(c.peak);
  }
  ResultTable t;
  t.name = "peak_match_" + model;
  t.columns = {"mode", "full_frequency_hz", "peak_frequency_hz", "rel_error", "visible"};
  std::vector<Eigen::Index> rows;  // the modes inside the sweep
  for (Eigen::Index k = 0; k < f.size(); ++k)
    if (f[k] >= f_min && f[k] <= f_max) rows.push_back(k);
  t.values = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), 5);
  std::vector<std::string> pair, type, outputs;
  for (size_t i = 0; i < rows.size(); ++i) {
    const Eigen::Index k = rows[i];
    const auto row = static_cast<Eigen::Index>(i);
    const int p = peak_of_mode[static_cast<size_t>(k)];
    t.values(row, 0) = static_cast<double>(k + 1);
    t.values(row, 1) = f[k];
    if (p >= 0) {
      t.values(row, 2) = resonances[static_cast<size_t>(p)].frequency_hz;
      t.values(row, 3) = resonances[static_cast<size_t>(p)].frequency_hz / f[k] - 1.0;
      t.values(row, 4) = 1.0;
    }
    outputs.push_back(p >= 0 ? seen_in[static_cast<size_t>(p)] : "-");
    pair.push_back(labels.empty() ? "-" : labels[static_cast<size_t>(k)].pair);
    type.push_back(labels.empty() ? "-" : labels[static_cast<size_t>(k)].type);
  }
  t.add_text_column("pair", pair);
  t.add_text_column("type", type);
  t.add_text_column("seen_in", outputs);
  return t;
}

ResultTable rom_frequency_table(const RomOutcome& rom) {
  ResultTable t = frequency_table(rom.frequencies_hz);
  t.name = "rom_frequencies_" + rom.name;
  return t;
}

}  // namespace

struct PreparedFrf {
  std::optional<ModalResult> full_modal;
  std::vector<ModeLabel> labels;
  std::optional<FullResponse> full;
  std::vector<RomResponse> roms;
  std::vector<FrfCurveSet> curves;
  int columns = 0;
  double full_setup_seconds = 0.0;
};

std::shared_ptr<const PreparedFrf> prepare_frf(const Model& model, const FrfSpec& spec, const ModelsBuilt& built,
                                               const ModelCacheSettings* cache) {
  auto p = std::make_shared<PreparedFrf>();
  const int models = (spec.full_model ? 1 : 0) + static_cast<int>(spec.roms.size());
  int done = 0;
  if (built) built(done, models);
  // A model of matrices only has no mesh to assemble.
  FreeSystem system;
  if (model.mesh.n_nodes() > 0) system = assemble_free_system(model);
  // Every named point first: a typo must not wait for the eigensolver.
  // Points of reduced models read from files name their DOFs, not mesh nodes.
  if (spec.full_model) {
    for (const FrfForce& f : spec.forces) free_index(model, system, f.dof);
    for (const PointDof& d : spec.responses) free_index(model, system, d);
  }
  for (const RomSpec& rom : spec.roms) {
    if (rom.masters.empty()) continue;
    for (const std::string& point : rom.masters) node_of_point(model, point);
    for (const FrfForce& f : rom.forces.empty() ? spec.forces : rom.forces) free_index(model, system, f.dof);
    for (const PointDof& d : rom.responses.empty() ? spec.responses : rom.responses) free_index(model, system, d);
  }
  if (spec.full_model) {
    const auto t0 = Clock::now();
    ModeSelection lowest;
    lowest.lowest = spec.full_modes;
    ModalOptions options;
    options.ordering = ordering_for_dimension(model.mesh.dim);
    p->full_modal = solve_modal(model, system, lowest, options, cache);
    if (spec.pairs) p->labels = label_mode_pairs(model, *p->full_modal, *spec.pairs);
    p->full = full_response(model, system, spec, *p->full_modal);
    p->full_setup_seconds = seconds_since(t0);
    std::vector<std::string> outputs;
    for (const PointDof& d : spec.responses) outputs.push_back(d.name());
    p->curves.push_back({"full", outputs, p->columns});
    p->columns += static_cast<int>(outputs.size());
    if (built) built(++done, models);
  }
  for (const RomSpec& rom : spec.roms) {
    p->roms.push_back(reduced_response(model, system, spec, rom, cache));
    p->curves.push_back({rom.name, p->roms.back().outputs, p->columns});
    p->columns += static_cast<int>(p->roms.back().outputs.size());
    if (built) built(++done, models);
  }
  return p;
}

const std::vector<FrfCurveSet>& frf_curves(const PreparedFrf& prepared) { return prepared.curves; }

Eigen::VectorXcd frf_respond(const PreparedFrf& p, size_t curve, double frequency_hz) {
  const double omega = kTwoPi * frequency_hz;
  if (p.full && curve == 0) return p.full->at(omega);
  return p.roms.at(p.full ? curve - 1 : curve).at(omega);
}

FrfOutcome sweep_frf(const PreparedFrf& p, const FrfSpec& spec) {
  FrfOutcome o;
  o.full_modal = p.full_modal;
  o.full_setup_seconds = p.full_setup_seconds;
  o.curves = p.curves;
  const std::vector<ModeLabel>& labels = p.labels;
  const std::optional<FullResponse>& full = p.full;
  const std::vector<RomResponse>& roms = p.roms;
  if (o.full_modal) {
    ResultTable frequencies = frequency_table(o.full_modal->frequencies_hz);
    if (!labels.empty()) add_mode_labels(frequencies, labels);
    o.tables.emplace("frequencies", std::move(frequencies));
  }
  std::vector<double> curve_seconds(p.curves.size(), 0.0);  // each model's share of the sweep
  const ResponseAt response = [&](double f_hz) {
    Eigen::VectorXcd y(p.columns);
    for (size_t c = 0; c < p.curves.size(); ++c) {
      const auto t0 = Clock::now();
      const FrfCurveSet& curve = p.curves[c];
      y.segment(curve.first_column, static_cast<Eigen::Index>(curve.outputs.size())) = frf_respond(p, c, f_hz);
      curve_seconds[c] += seconds_since(t0);
    }
    return y;
  };
  o.sweep = spec.adaptive ? adaptive_sweep(response, spec.f_min, spec.f_max, spec.step, spec.min_step)
                          : sweep(response, fixed_grid(spec.f_min, spec.f_max, spec.step));
  const size_t first_rom = full ? 1 : 0;
  if (full) o.full_sweep_seconds = curve_seconds[0];
  for (size_t i = 0; i < roms.size(); ++i) {
    o.roms.push_back(roms[i].outcome);
    o.roms.back().sweep_seconds = curve_seconds[first_rom + i];
  }
  o.tables.emplace("frf", frf_table(o));
  for (const FrfCurveSet& c : o.curves) {
    std::vector<ModelPeak> peaks;
    ResultTable t = peak_table(o, c, spec.peak_prominence, spec.peak_floor, peaks);
    o.tables.emplace(t.name, std::move(t));
    if (o.full_modal) {
      ResultTable match =
          peak_match_table(c.model, peaks, *o.full_modal, labels, spec.match_tolerance, spec.f_min, spec.f_max);
      o.tables.emplace(match.name, std::move(match));
    }
  }
  for (const RomOutcome& r : o.roms) {
    ResultTable t = rom_frequency_table(r);
    o.tables.emplace(t.name, std::move(t));
  }

  // Linearity (Fig 3.25): the first model's first output, swept again at each force level.
  if (!spec.force_levels.empty() && !o.curves.empty()) {
    ResultTable t;
    t.name = "linearity";
    t.columns = {"level", "force_n", "peak_amplitude_m", "compliance_m_per_n", "compliance_ratio"};
    t.values.resize(static_cast<Eigen::Index>(spec.force_levels.size()), 5);
    double first_compliance = 0.0;
    // The first model with its first force set to `level`: a copy, so the prepared models stay as they are.
    auto first_output_at_level = [&](auto model, double level) {
      model.force[0] = level;
      Eigen::VectorXd amplitude(static_cast<Eigen::Index>(o.sweep.frequency_hz.size()));
      for (size_t i = 0; i < o.sweep.frequency_hz.size(); ++i)
        amplitude[static_cast<Eigen::Index>(i)] = std::abs(model.at(kTwoPi * o.sweep.frequency_hz[i])[0]);
      return amplitude;
    };
    for (size_t l = 0; l < spec.force_levels.size(); ++l) {
      Eigen::VectorXd amplitude = full ? first_output_at_level(*full, spec.force_levels[l])
                                       : first_output_at_level(roms.front(), spec.force_levels[l]);
      const double peak = amplitude.maxCoeff();
      const double compliance = peak / spec.force_levels[l];
      if (l == 0) first_compliance = compliance;
      const auto row = static_cast<Eigen::Index>(l);
      t.values.row(row) << static_cast<double>(l + 1), spec.force_levels[l], peak, compliance,
          compliance / first_compliance;
      o.level_forces.push_back(spec.force_levels[l]);
      o.level_amplitudes.push_back(std::move(amplitude));
    }
    o.tables.emplace("linearity", std::move(t));
  }
  return o;
}

FrfOutcome run_frf(const Model& model, const FrfSpec& spec, const ModelsBuilt& built, const ModelCacheSettings* cache) {
  return sweep_frf(*prepare_frf(model, spec, built, cache), spec);
}

}  // namespace bb
