#include "pipeline/run_fidelity.hpp"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>

#include "cases/parse_fidelity.hpp"
#include "common/constants.hpp"
#include "common/errors.hpp"
#include "common/power_law.hpp"
#include "model/build_model.hpp"

namespace bb {
namespace {

// A relative difference this small is the solvers' own rounding (their tolerances are 1e-9 to
// 1e-10): the axis no longer changes the result (the event-resolved AFT's samples), and a power law
// through such noise means nothing.
constexpr double kUnchanged = 1e-8;

// Unknowns of one solve: harmonic coefficients of the balance, steps x DOFs of a time period, or
// the nodal DOFs of a mesh.
double unknowns(const AnalysisSpec& spec, const Model& model, const AnalysisResults& results) {
  if (const auto* h = std::get_if<HbmOutcome>(&results.outcome))
    return static_cast<double>(h->prepared.model.mass.rows()) * (2.0 * std::get<HbmSpec>(spec).harmonics + 1.0);
  if (const auto* t = std::get_if<TimeOutcome>(&results.outcome))
    return static_cast<double>(t->prepared.model.mass.rows()) * std::get<TimeSpec>(spec).steps_per_period;
  return static_cast<double>(model.mesh.n_nodes()) * model.mesh.dim;
}

struct LevelRun {
  CaseSpec spec;
  std::unique_ptr<Model> model;
  AnalysisResults results;
  double seconds = 0.0;
  double unknowns = 0.0;
  std::string failure;  // the solver's message when these levels gave no trustworthy answer
};

class Climber {
 public:
  Climber(const CaseSpec& spec, const HbmProgress& progress, const WorkLimits& limits, const ModelCacheSettings* cache)
      : base_(spec), f_(*spec.fidelity), progress_(progress), limits_(limits), cache_(cache) {}

  // The run at these level indices, computed once.
  LevelRun& at(const std::vector<int>& index) {
    auto it = runs_.find(index);
    if (it != runs_.end()) return *it->second;
    auto run = std::make_unique<LevelRun>();
    run->spec = base_;
    for (size_t a = 0; a < f_.axes.size(); ++a)
      apply_fidelity_level(run->spec, f_.axes[a], f_.axes[a].levels[static_cast<size_t>(index[a])]);
    if (progress_) progress_(fmt::format("fidelity: {}", settings_of(index)));
    const auto t0 = std::chrono::steady_clock::now();
    run->model = std::make_unique<Model>(build_model(run->spec.model));
    // A level too coarse to solve (a sweep that cannot reach the steady state, say) is a level whose
    // error is unbounded: the climb records it and goes on.
    try {
      run->results = run_analysis(run->spec.analysis, *run->model, progress_, limits_, cache_);
    } catch (const SolverError& e) {
      run->failure = e.what();
    }
    run->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run->unknowns = run->failure.empty() ? unknowns(run->spec.analysis, *run->model, run->results) : kNan;
    return *runs_.emplace(index, std::move(run)).first->second;
  }

  const ResultTable& table(const LevelRun& run) const {
    const auto it = run.results.tables.find(f_.result);
    if (it == run.results.tables.end()) {
      std::string names;
      for (const auto& [name, t] : run.results.tables) names += (names.empty() ? "" : ", ") + name;
      throw InputError(fmt::format("{}: fidelity.result: the analysis has no table '{}'; it has: {}", f_.at.where(),
                                   f_.result, names));
    }
    return it->second;
  }

  std::string settings_of(const std::vector<int>& index) const {
    std::string s;
    for (size_t a = 0; a < f_.axes.size(); ++a)
      s += fmt::format("{}{} = {}", s.empty() ? "" : ", ", f_.axes[a].path,
                       f_.axes[a].levels[static_cast<size_t>(index[a])]);
    return s;
  }

  LevelRun& run(const std::vector<int>& index) { return *runs_.at(index); }
  // "settings: message" of every run whose solve failed.
  std::vector<std::string> failures() const {
    std::vector<std::string> out;
    for (const auto& [index, run] : runs_)
      if (!run->failure.empty()) out.push_back(fmt::format("{}: {}", settings_of(index), run->failure));
    return out;
  }

 private:
  const CaseSpec& base_;
  const FidelitySpec& f_;
  HbmProgress progress_;
  WorkLimits limits_;
  const ModelCacheSettings* cache_;
  std::map<std::vector<int>, std::unique_ptr<LevelRun>> runs_;
};

// The level as the abscissa of the power law e = C x^-p: the count itself, or 1 / tolerance.
double fidelity_abscissa(const FidelityAxisSpec& axis, int level) {
  const double v = axis.levels[static_cast<size_t>(level)];
  return axis.setting == FidelitySetting::steady_tolerance ? 1.0 / v : v;
}

struct FrontierRow {
  std::vector<int> index;
  size_t axis = 0;
  double difference = kNan;  // against the next finer level of the axis
  double estimated_error = kNan;
};

}  // namespace

double relative_difference(const ResultTable& coarse, const ResultTable& fine, const std::vector<std::string>& columns,
                           const std::string& key) {
  const auto key_of = [&](const ResultTable& t) {
    if (key.empty()) return 0;
    const auto k = t.column_index(key);
    if (!k) throw InputError(fmt::format("fidelity.key: table '{}' has no column '{}'", t.name, key));
    return *k;
  };
  const int kc = key_of(coarse), kf = key_of(fine);
  // Rows pair by equal keys (to 1e-9 relative: frequencies of one grid computed twice), once for
  // every column.
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;  // (coarse row, fine row)
  for (Eigen::Index r = 0; r < fine.values.rows(); ++r) {
    const double k = fine.values(r, kf);
    for (Eigen::Index rc = 0; rc < coarse.values.rows(); ++rc)
      if (std::abs(coarse.values(rc, kc) - k) <= 1e-9 * std::max(1.0, std::abs(k))) {
        pairs.emplace_back(rc, r);
        break;
      }
  }
  double worst = 0.0;
  for (const std::string& c : columns) {
    const auto ic = coarse.column_index(c), jf = fine.column_index(c);
    if (!ic || !jf) throw InputError(fmt::format("fidelity.columns: table '{}' has no column '{}'", fine.name, c));
    if (pairs.empty())
      throw InputError(fmt::format("fidelity: no row of table '{}' pairs between two levels (keys differ)", fine.name));
    double scale = 0.0;
    for (Eigen::Index r = 0; r < fine.values.rows(); ++r)
      if (std::isfinite(fine.values(r, *jf))) scale = std::max(scale, std::abs(fine.values(r, *jf)));
    // A value below 1e-6 of the column's largest is a numerical zero (a rigid-body mode's 3e-5 Hz
    // against 200 Hz): its change is measured on the column's scale, not on itself.
    const double zero = 1e-6 * scale;
    for (const auto& [rc, r] : pairs) {
      const double a = coarse.values(rc, *ic), b = fine.values(r, *jf);
      if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
      const double d = std::abs(a - b);
      worst = std::max(worst, std::abs(b) > zero ? d / std::abs(b) : (scale > 0 ? d / scale : d));
    }
  }
  return worst;
}

FidelityChoice run_with_fidelity(const CaseSpec& spec, FidelityMode mode, const HbmProgress& progress,
                                 const WorkLimits& limits, const ModelCacheSettings* cache) {
  if (!spec.fidelity) throw InputError(fmt::format("{}: --fidelity needs a [fidelity] section", spec.file.string()));
  const FidelitySpec& f = *spec.fidelity;
  const size_t n_axes = f.axes.size();
  Climber climber(spec, progress, limits, cache);
  // Differences between two runs; a missing column or key names the [fidelity] section.
  const auto difference = [&](const LevelRun& coarse, const LevelRun& fine) {
    if (!coarse.failure.empty() || !fine.failure.empty()) return std::numeric_limits<double>::infinity();
    try {
      return relative_difference(climber.table(coarse), climber.table(fine), f.columns, f.key);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", f.at.where(), e.what()));
    }
  };
  std::vector<FrontierRow> rows;
  std::vector<int> index(n_axes, 0);
  std::vector<double> axis_error(n_axes, kNan);
  if (mode == FidelityMode::reference)
    for (size_t a = 0; a < n_axes; ++a) index[a] = static_cast<int>(f.axes[a].levels.size()) - 1;
  if (mode == FidelityMode::automatic) {
    // From the cheapest combination: probe every axis one level finer, estimate each axis's error,
    // and refine the axis with the largest estimate, until their sum meets the target.
    std::vector<std::vector<double>> history(n_axes);  // differences of each axis along the climb
    while (true) {
      climber.at(index);
      double total = 0.0;
      size_t worst = n_axes;
      std::vector<double> estimate(n_axes, kNan);
      for (size_t a = 0; a < n_axes; ++a) {
        const bool finest = index[a] + 1 == static_cast<int>(f.axes[a].levels.size());
        const int i = index[a];
        const auto x = [&](int j) { return fidelity_abscissa(f.axes[a], j); };
        if (finest) {
          // No finer level: the power law through the last three levels, extrapolated one level on
          // (NaN when fewer than two differences were met on the way).
          const auto& h = history[a];
          estimate[a] = kNan;
          if (!h.empty() && h.back() <= kUnchanged) {
            estimate[a] = 0.0;
          } else if (h.size() >= 2 && i >= 2) {
            const double e_before = power_law_error({x(i - 2), x(i - 1), x(i)}, h[h.size() - 2], h.back());
            estimate[a] = std::isfinite(e_before) ? std::max(0.0, e_before - h.back()) : e_before;
          }
        } else {
          std::vector<int> finer = index;
          ++finer[a];
          const double d = difference(climber.run(index), climber.at(finer));
          rows.push_back({finer, a, d, kNan});
          if (!climber.run(finer).failure.empty()) {
            // The finer level does not solve: this axis cannot be refined, and its error is unknown.
            estimate[a] = std::numeric_limits<double>::infinity();
            total += estimate[a];
            continue;
          }
          history[a].resize(static_cast<size_t>(i));  // d_0 .. d_(i-1): the differences below level i
          if (d <= kUnchanged) {
            estimate[a] = d;
          } else if (!history[a].empty()) {
            estimate[a] = power_law_error({x(i - 1), x(i), x(i + 1)}, history[a].back(), d);
          } else if (i + 2 < static_cast<int>(f.axes[a].levels.size())) {
            // One difference fixes no order: probe a second level on, e(x_i) = d_i + e(x_(i+1)).
            std::vector<int> two_on = finer;
            ++two_on[a];
            const double d_next = difference(climber.run(finer), climber.at(two_on));
            rows.push_back({two_on, a, d_next, kNan});
            estimate[a] = d + power_law_error({x(i), x(i + 1), x(i + 2)}, d, d_next);
          } else {
            estimate[a] = d;  // two levels only: the difference is all there is
          }
          history[a].push_back(d);
          if (worst == n_axes || !(estimate[a] <= estimate[worst])) worst = a;
        }
        total += estimate[a];
      }
      rows.push_back({index, n_axes, kNan, total});
      axis_error = estimate;
      if (total <= f.target || worst == n_axes) break;
      ++index[worst];
    }
  } else {
    climber.at(index);
    rows.push_back({index, n_axes, kNan, kNan});
  }
  FidelityChoice choice;
  LevelRun& chosen = climber.run(index);
  if (!chosen.failure.empty())
    throw SolverError(fmt::format("fidelity {}: the run at {} failed: {}", fidelity_mode_name(mode),
                                  climber.settings_of(index), chosen.failure));
  difference(chosen, chosen);  // fast and reference too: the columns must exist
  choice.spec = chosen.spec;
  choice.model = std::move(*chosen.model);
  choice.results = std::move(chosen.results);
  choice.settings = climber.settings_of(index);
  choice.estimated_error = 0.0;
  for (double e : axis_error) choice.estimated_error += e;
  if (mode != FidelityMode::automatic) choice.estimated_error = kNan;
  choice.met = mode == FidelityMode::automatic && choice.estimated_error <= f.target;
  // frontier: the combinations the climb stood on (axis "combined", with the summed estimate) and
  // the one-level-finer probes of each axis (with their difference to the combination below).
  std::vector<std::string> cols = {"run",        "level",           "unknowns", "seconds",
                                   "difference", "estimated_error", "chosen",   "failed"};
  for (const FidelityAxisSpec& axis : f.axes) cols.push_back(axis.path);
  std::vector<std::vector<double>> values;
  std::vector<std::string> axis_names;
  for (size_t k = 0; k < rows.size(); ++k) {
    const FrontierRow& r = rows[k];
    const LevelRun& run = climber.run(r.index);
    const bool combined = r.axis == n_axes;
    const bool is_chosen = combined && r.index == index && k + 1 == rows.size();
    std::vector<double> row = {static_cast<double>(values.size() + 1),
                               combined ? kNan : f.axes[r.axis].levels[static_cast<size_t>(r.index[r.axis])],
                               run.unknowns,
                               run.seconds,
                               r.difference,
                               r.estimated_error,
                               is_chosen ? 1.0 : 0.0,
                               run.failure.empty() ? 0.0 : 1.0};
    for (size_t a = 0; a < n_axes; ++a) row.push_back(f.axes[a].levels[static_cast<size_t>(r.index[a])]);
    values.push_back(row);
    axis_names.push_back(combined ? std::string("combined") : f.axes[r.axis].path);
  }
  choice.failures = climber.failures();
  choice.frontier = table_from_rows("frontier", cols, values);
  choice.frontier.add_text_column("axis", axis_names);
  return choice;
}

}  // namespace bb
