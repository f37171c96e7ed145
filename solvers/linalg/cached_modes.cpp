#include "linalg/cached_modes.hpp"

#include <nlohmann/json.hpp>

#include <chrono>

#include "cache/cbor_matrix.hpp"
#include "cache/model_cache.hpp"

namespace bb {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

ModalSolution cached_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const ModalOptions& options, CacheUse* use) {
  CacheUse local;
  CacheUse& u = use ? *use : local;
  auto t0 = Clock::now();
  if (!model_cache_settings()) {
    ModalSolution s = lowest_modes(stiffness, mass, options);
    u.build_seconds = seconds_since(t0);
    return s;
  }
  ContentKey key("modes");
  key.add(program_fingerprint()).add(stiffness).add(mass);
  key.add(std::int64_t{options.n_modes}).add(options.shift_frequency_hz).add(std::int64_t{options.max_iterations});
  key.add(options.tolerance).add(std::int64_t{options.subspace_size}).add(std::int64_t{static_cast<int>(options.ordering)});
  key.add(std::int64_t{options.verify_count}).add(options.cluster_tolerance).add(std::int64_t{options.max_reruns});

  CacheEntry entry(key);
  t0 = Clock::now();
  if (const auto payload = entry.load()) {
    try {
      const json j = json::from_cbor(*payload);
      ModalSolution s;
      s.eigenvalues = matrix_from_json(j.at("eigenvalues"));
      s.shapes = matrix_from_json(j.at("shapes"));
      if (s.shapes.rows() != stiffness.rows() || s.shapes.cols() != s.eigenvalues.size() ||
          s.eigenvalues.size() < options.n_modes)
        throw std::runtime_error("its sizes do not match the model");
      s.iterations = j.at("iterations").get<int>();
      s.converged_modes = j.at("converged_modes").get<int>();
      s.max_residual = j.at("max_residual").get<double>();
      s.sturm_count = j.at("sturm_count").get<int>();
      s.sturm_shift = j.at("sturm_shift").get<double>();
      s.lanczos_runs = j.at("lanczos_runs").get<int>();
      s.sturm_seconds = j.at("sturm_seconds").get<double>();
      u.build_seconds = j.at("solve_seconds").get<double>();
      u.outcome = CacheUse::Outcome::loaded;
      u.seconds = seconds_since(t0);
      return s;
    } catch (const std::exception& e) {
      entry.discard(e.what());
    }
  }
  t0 = Clock::now();
  ModalSolution s = lowest_modes(stiffness, mass, options);
  u.build_seconds = seconds_since(t0);
  t0 = Clock::now();
  const json j = {{"eigenvalues", matrix_to_json(s.eigenvalues)},
                  {"shapes", matrix_to_json(s.shapes)},
                  {"iterations", s.iterations},
                  {"converged_modes", s.converged_modes},
                  {"max_residual", s.max_residual},
                  {"sturm_count", s.sturm_count},
                  {"sturm_shift", s.sturm_shift},
                  {"lanczos_runs", s.lanczos_runs},
                  {"sturm_seconds", s.sturm_seconds},
                  {"solve_seconds", u.build_seconds}};
  const bool stored = entry.store(json::to_cbor(j), u.build_seconds);
  u.seconds = seconds_since(t0);
  u.outcome = stored ? CacheUse::Outcome::stored : CacheUse::Outcome::not_stored;
  u.note = entry.note();
  return s;
}

}  // namespace bb
