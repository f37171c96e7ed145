#include "reduction/cached_craig_bampton.hpp"

#include <nlohmann/json.hpp>

#include <chrono>

#include "cache/cbor_matrix.hpp"
#include "cache/model_cache.hpp"

namespace bb {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::vector<std::uint8_t> encode(const ReducedModel& m, const CraigBamptonTiming& t) {
  json dofs = json::array();
  for (const ReducedDof& d : m.dofs) dofs.push_back({d.label, d.direction, d.mode});
  const json j = {{"stiffness", matrix_to_json(m.stiffness)},
                  {"mass", matrix_to_json(m.mass)},
                  {"recovery", matrix_to_json(m.recovery)},
                  {"fixed_interface_frequencies_hz", matrix_to_json(m.fixed_interface_frequencies_hz)},
                  {"dofs", dofs},
                  {"timing", {t.constraint_modes_seconds, t.fixed_interface_seconds, t.projection_seconds}}};
  return json::to_cbor(j);
}

ReducedModel decode(const std::vector<std::uint8_t>& payload, CraigBamptonTiming& t) {
  const json j = json::from_cbor(payload);
  ReducedModel m;
  m.stiffness = matrix_from_json(j.at("stiffness"));
  m.mass = matrix_from_json(j.at("mass"));
  m.recovery = matrix_from_json(j.at("recovery"));
  m.fixed_interface_frequencies_hz = matrix_from_json(j.at("fixed_interface_frequencies_hz"));
  for (const json& d : j.at("dofs")) m.dofs.push_back({d.at(0).get<std::string>(), d.at(1).get<int>(), d.at(2).get<int>()});
  const json& times = j.at("timing");
  t.constraint_modes_seconds = times.at(0).get<double>();
  t.fixed_interface_seconds = times.at(1).get<double>();
  t.projection_seconds = times.at(2).get<double>();
  return m;
}

}  // namespace

ReducedModel cached_craig_bampton(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                                  const std::vector<int>& masters, const std::vector<ReducedDof>& master_names,
                                  const CraigBamptonOptions& options, CraigBamptonTiming* timing) {
  CraigBamptonTiming local;
  CraigBamptonTiming& t = timing ? *timing : local;
  if (!model_cache_settings()) return craig_bampton(stiffness, mass, masters, master_names, options, &t);
  t.cache.outcome = CacheUse::Outcome::not_stored;

  ContentKey key("craig_bampton");
  key.add(program_fingerprint()).add(stiffness).add(mass);
  for (size_t i = 0; i < masters.size(); ++i)
    key.add(std::int64_t{masters[i]}).add(master_names[i].name());
  key.add(std::int64_t{options.n_modes}).add(std::int64_t{static_cast<int>(options.ordering)});
  key.add(options.shift_frequency_hz);

  CacheEntry entry(key);
  auto t0 = Clock::now();
  if (const auto payload = entry.load()) {
    try {
      CraigBamptonTiming stored;
      ReducedModel m = decode(*payload, stored);
      validate_reduced_model(m, entry.file().string());
      if (m.size() != static_cast<int>(masters.size()) + options.n_modes || m.recovery.rows() != stiffness.rows())
        throw std::runtime_error("its sizes do not match the model");
      t = stored;
      t.cache.outcome = CacheUse::Outcome::loaded;
      t.cache.seconds = seconds_since(t0);
      t.cache.build_seconds = stored.constraint_modes_seconds + stored.fixed_interface_seconds + stored.projection_seconds;
      return m;
    } catch (const std::exception& e) {
      entry.discard(e.what());
    }
  }
  ReducedModel m = craig_bampton(stiffness, mass, masters, master_names, options, &t);
  t.cache.build_seconds = t.constraint_modes_seconds + t.fixed_interface_seconds + t.projection_seconds;
  t0 = Clock::now();
  const bool stored = entry.store(encode(m, t), t.cache.build_seconds);
  t.cache.seconds = seconds_since(t0);
  t.cache.outcome = stored ? CacheUse::Outcome::stored : CacheUse::Outcome::not_stored;
  t.cache.note = entry.note();
  return m;
}

}  // namespace bb
