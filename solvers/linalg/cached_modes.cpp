#include "linalg/cached_modes.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cache/cbor_matrix.hpp"
#include "cache/model_cache.hpp"

namespace bb {

ModalSolution cached_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const ModalOptions& options, const ModelCacheSettings* cache, CacheUse* use) {
  using nlohmann::json;
  CacheUse local;
  CacheUse& used = use ? *use : local;
  std::string subset;
  ModalSolution result = through_model_cache<ModalSolution>(
      cache, "modes",
      [&](ContentKey& key) {
        key.add(stiffness).add(mass);
        // Not the number of modes: an entry holding more serves a request for fewer (leading_modes).
        key.add(options.shift_frequency_hz).add(std::int64_t{options.max_iterations});
        key.add(options.tolerance).add(std::int64_t{options.subspace_size});
        key.add(std::int64_t{static_cast<int>(options.ordering)}).add(std::int64_t{options.verify_count});
        key.add(options.cluster_tolerance).add(std::int64_t{options.max_reruns});
        if (options.eigensolver == Eigensolver::slepc) key.add(std::string_view("slepc"));
      },
      [&] { return lowest_modes(stiffness, mass, options); },
      [](const ModalSolution& s) {
        return json{{"eigenvalues", matrix_to_json(s.eigenvalues)},
                    {"shapes", matrix_to_json(s.shapes)},
                    {"iterations", s.iterations},
                    {"converged_modes", s.converged_modes},
                    {"max_residual", s.max_residual},
                    {"sturm_count", s.sturm_count},
                    {"sturm_shift", s.sturm_shift},
                    {"lanczos_runs", s.lanczos_runs},
                    {"sturm_seconds", s.sturm_seconds}};
      },
      [&](const json& j) {
        ModalSolution s;
        s.eigenvalues = matrix_from_json(j.at("eigenvalues"));
        s.shapes = matrix_from_json(j.at("shapes"));
        if (s.shapes.rows() != stiffness.rows() || s.shapes.cols() != s.eigenvalues.size())
          throw std::runtime_error("its sizes do not match the model");
        s.iterations = j.at("iterations").get<int>();
        s.converged_modes = j.at("converged_modes").get<int>();
        s.max_residual = j.at("max_residual").get<double>();
        s.sturm_count = j.at("sturm_count").get<int>();
        s.sturm_shift = j.at("sturm_shift").get<double>();
        s.lanczos_runs = j.at("lanczos_runs").get<int>();
        s.sturm_seconds = j.at("sturm_seconds").get<double>();
        std::optional<ModalSolution> wanted = leading_modes(s, options);
        if (wanted && wanted->eigenvalues.size() < s.eigenvalues.size())
          subset = fmt::format("the lowest {} of {} stored modes", wanted->eigenvalues.size(), s.eigenvalues.size());
        return wanted;
      },
      used);
  if (used.outcome == CacheUse::Outcome::loaded) used.note = subset;
  return result;
}

}  // namespace bb
