#include "reduction/cached_craig_bampton.hpp"

#include <nlohmann/json.hpp>

#include "cache/cbor_matrix.hpp"
#include "cache/model_cache.hpp"

namespace bb {
namespace {

using nlohmann::json;

json encode(const ReducedModel& m, const CraigBamptonTiming& t) {
  json dofs = json::array();
  for (const ReducedDof& d : m.dofs) dofs.push_back({d.label, d.direction, d.mode});
  return {{"stiffness", matrix_to_json(m.stiffness)},
          {"mass", matrix_to_json(m.mass)},
          {"recovery", matrix_to_json(m.recovery)},
          {"fixed_interface_frequencies_hz", matrix_to_json(m.fixed_interface_frequencies_hz)},
          {"dofs", dofs},
          {"timing", {t.constraint_modes_seconds, t.fixed_interface_seconds, t.projection_seconds}}};
}

ReducedModel decode(const json& j, CraigBamptonTiming& t) {
  ReducedModel m;
  m.stiffness = matrix_from_json(j.at("stiffness"));
  m.mass = matrix_from_json(j.at("mass"));
  m.recovery = matrix_from_json(j.at("recovery"));
  m.fixed_interface_frequencies_hz = matrix_from_json(j.at("fixed_interface_frequencies_hz"));
  for (const json& d : j.at("dofs"))
    m.dofs.push_back({d.at(0).get<std::string>(), d.at(1).get<int>(), d.at(2).get<int>()});
  const json& times = j.at("timing");
  t.constraint_modes_seconds = times.at(0).get<double>();
  t.fixed_interface_seconds = times.at(1).get<double>();
  t.projection_seconds = times.at(2).get<double>();
  return m;
}

}  // namespace

ReducedModel cached_craig_bampton(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const std::vector<int>& masters, const std::vector<ReducedDof>& master_names,
                                  const CraigBamptonOptions& options, const ModelCacheSettings* cache,
                                  CraigBamptonTiming* timing) {
  CraigBamptonTiming local;
  CraigBamptonTiming& t = timing ? *timing : local;
  CraigBamptonTiming stored;  // the phase times of the run that stored a loaded entry
  CacheUse use;
  ReducedModel m = through_model_cache<ReducedModel>(
      cache, "craig_bampton",
      [&](ContentKey& key) {
        key.add(stiffness).add(mass);
        for (size_t i = 0; i < masters.size(); ++i) key.add(std::int64_t{masters[i]}).add(master_names[i].name());
        key.add(std::int64_t{options.n_modes}).add(std::int64_t{static_cast<int>(options.ordering)});
        key.add(options.shift_frequency_hz).add(options.modes_below_hz);
        if (options.eigensolver == Eigensolver::slepc) key.add(std::string_view("slepc"));
      },
      [&] { return craig_bampton(stiffness, mass, masters, master_names, options, &t); },
      [&](const ReducedModel& built) { return encode(built, t); },
      [&](const json& j) {
        ReducedModel loaded = decode(j, stored);
        validate_reduced_model(loaded, "the model cache");
        const bool band = options.modes_below_hz > 0.0;
        if ((band ? loaded.size() < static_cast<int>(masters.size())
                  : loaded.size() != static_cast<int>(masters.size()) + options.n_modes) ||
            loaded.recovery.rows() != stiffness.rows())
          throw std::runtime_error("its sizes do not match the model");
        return loaded;
      },
      use);
  if (use.outcome == CacheUse::Outcome::loaded) t = stored;
  t.cache = use;
  return m;
}

}  // namespace bb
