#include "study/rotating_fidelity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "analysis/rotating_analysis.hpp"
#include "common/constants.hpp"
#include "ffrf/elastic_basis.hpp"
#include "ffrf/rotating_body.hpp"
#include "ffrf/rotating_modes.hpp"

namespace bb {
namespace {

using Clock = std::chrono::steady_clock;

struct Level {
  std::string model;
  int unknowns = 0;
  double seconds = 0.0;
  Eigen::VectorXd mean;    // the first set's mean displacement per direction
  Eigen::VectorXd motion;  // its largest |u| per direction over the run (empty: no time run)
  double frequency_hz = kNan;
  bool diverged = false;
};

Level time_level(const Model& model, RotatingSpec spec, const std::string& name, const WorkLimits& limits) {
  Level l;
  l.model = name;
  const auto t0 = Clock::now();
  try {
    const RotatingOutcome o = run_rotating(model, spec, limits);
    const ResultTable& d = o.tables.at("deflection");
    l.mean.resize(o.dim);
    l.motion.resize(o.dim);
    for (int k = 0; k < o.dim; ++k) {
      l.mean[k] = d.values(0, *d.column_index(fmt::format("mean_u{}_m", "xyz"[k])));
      l.motion[k] = o.set_histories.col(k).cwiseAbs().maxCoeff();
    }
    l.unknowns = o.basis_size;
    // The frequency the run oscillates at (its own dynamics, the basis's included), not the modes of
    // the separate modal eigenproblem.
    if (const auto t = o.tables.find("oscillation"); t != o.tables.end() && t->second.values.rows() > 0)
      l.frequency_hz = t->second.values(0, *t->second.column_index("measured_hz"));
  } catch (const ffrf::DivergenceError&) {
    l.diverged = true;
  }
  l.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return l;
}

// The static centrifugal deflection with the pre-stressed rotating modes: no time run at all.
Level static_level(const Model& model, const RotatingSpec& spec) {
  Level l;
  l.model = "static deflection + rotating modes";
  const auto t0 = Clock::now();
  const ffrf::RotatingBody body = ffrf::build_rotating_body(model, {spec.axis_direction, spec.axis_point});
  const double speed = spec.profile == RotatingSpec::Profile::torque ? spec.initial_speed : spec.speed;
  const ffrf::StaticDeflection s = ffrf::centrifugal_deflection(body, speed, {.stiffening = true});
  const Eigen::VectorXd all = ffrf::expand_to_global(body, s.displacement);
  const std::vector<int>& nodes = model.node_sets.at(spec.histories.front());
  l.mean = Eigen::VectorXd::Zero(model.mesh.dim);
  for (int n : nodes) l.mean += all.segment(n * model.mesh.dim, model.mesh.dim) / static_cast<double>(nodes.size());
  const ffrf::ElasticBasis basis = ffrf::make_elastic_basis(body, {ffrf::BasisKind::modal, spec.basis_modes, {}, true});
  const ffrf::ProjectedBody projected = ffrf::project(body, basis);
  l.frequency_hz = ffrf::rotating_modes(projected, speed, {.n_modes = 1, .stiffening = true, .coriolis = spec.coriolis})
                       .frequencies_hz[0];
  l.unknowns = body.n_free();
  l.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return l;
}

double relative(double value, double reference) {
  return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
}

}  // namespace

ResultTable run_rotating_fidelity_study(const Model& model, const RotatingSpec& spec,
                                        const RotatingFidelityStudySpec& study, const StudyProgress& progress,
                                        const WorkLimits& limits) {
  // static, linear, one per basis size, and the nodal reference
  const int total = 3 + static_cast<int>(study.basis_modes.size());
  std::vector<Level> levels;
  const auto done = [&] {
    if (progress) progress(static_cast<int>(levels.size()), total);
  };
  if (progress) progress(0, total);
  levels.push_back(static_level(model, spec));
  done();
  RotatingSpec linear = spec;
  linear.stiffening = false;
  linear.compare_stiffening = false;
  linear.modal_basis = true;
  linear.basis_modes = *std::max_element(study.basis_modes.begin(), study.basis_modes.end());
  levels.push_back(time_level(model, linear, fmt::format("no stiffening, {} modes", linear.basis_modes), limits));
  done();
  for (int n : study.basis_modes) {
    RotatingSpec modal = spec;
    modal.stiffening = true;
    modal.compare_stiffening = false;
    modal.modal_basis = true;
    modal.basis_modes = n;
    levels.push_back(time_level(model, modal, fmt::format("stiffening, {} modes", n), limits));
    done();
  }
  RotatingSpec nodal = spec;
  nodal.stiffening = true;
  nodal.compare_stiffening = false;
  nodal.modal_basis = false;
  levels.push_back(time_level(model, nodal, "stiffening, every free DOF (reference)", limits));
  done();
  const Level& ref = levels.back();
  // The compared components: the largest mean and the largest motion of the reference.
  Eigen::Index mean_dir = 0, motion_dir = 0;
  ref.mean.cwiseAbs().maxCoeff(&mean_dir);
  if (ref.motion.size() > 0) ref.motion.maxCoeff(&motion_dir);
  std::vector<std::vector<double>> rows;
  std::vector<std::string> names;
  for (const Level& l : levels) {
    const bool has_mean = !l.diverged && l.mean.size() > 0, has_motion = !l.diverged && l.motion.size() > 0;
    rows.push_back({static_cast<double>(rows.size() + 1), static_cast<double>(l.unknowns), l.seconds,
                    has_mean ? relative(l.mean[mean_dir], ref.mean[mean_dir]) : kNan,
                    has_motion && ref.motion.size() > 0 ? relative(l.motion[motion_dir], ref.motion[motion_dir]) : kNan,
                    std::isfinite(l.frequency_hz) && !l.diverged ? relative(l.frequency_hz, ref.frequency_hz) : kNan,
                    l.diverged ? 1.0 : 0.0});
    names.push_back(l.model);
  }
  ResultTable t = table_from_rows(
      "rotating_fidelity",
      {"level", "unknowns", "seconds", "mean_error", "motion_error", "frequency_error", "diverged"}, rows);
  t.add_text_column("model", names);
  return t;
}

}  // namespace bb
