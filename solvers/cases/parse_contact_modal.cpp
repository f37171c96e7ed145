#include "cases/parse_contact_modal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace bb {
namespace {

// A strictly increasing list of finite values above `lower` (or at it, when `allow_lower`).
std::vector<double> increasing_list(TomlReader& r, const std::string& key, double lower, bool allow_lower) {
  std::vector<double> v = r.number_array(key);
  if (v.empty()) r.fail(key, "needs at least one value");
  if (v.size() > 100) r.fail(key, fmt::format("{} values exceed the limit of 100", v.size()));
  for (size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]) || v[i] < lower || (!allow_lower && v[i] == lower))
      r.fail(key, fmt::format("value {} is {}: each must be a finite number {} {}", i + 1, v[i],
                              allow_lower ? ">=" : ">", lower));
    if (i > 0 && !(v[i] > v[i - 1])) r.fail(key, "values must increase strictly");
  }
  return v;
}

}  // namespace

ContactModalSpec parse_contact_modal(TomlReader& r) {
  ContactModalSpec s;
  s.at = r.location();
  const long modes = r.integer("modes");
  if (modes < 1 || modes > 1000) r.fail("modes", fmt::format("must lie in 1..1000, found {}", modes));
  s.modes = static_cast<int>(modes);
  s.interferences = increasing_list(r, "interference_m", 0.0, true);
  s.penalty_factors = increasing_list(r, "penalty_factor", 0.0, false);
  if (s.interferences.size() * s.penalty_factors.size() > 400)
    r.fail("penalty_factor", fmt::format("{} x {} grid points exceed the limit of 400", s.interferences.size(),
                                         s.penalty_factors.size()));
  s.sticking = r.choice("tangential", {"stick", "frictionless"}, "stick") == "stick";
  if (r.has("tangential_ratio")) {
    if (!s.sticking) r.fail("tangential_ratio", "applies to tangential = \"stick\" only");
    s.tangential_ratio = r.number("tangential_ratio");
    if (!(s.tangential_ratio > 0) || !std::isfinite(s.tangential_ratio))
      r.fail("tangential_ratio", fmt::format("must be a positive finite number, found {}", s.tangential_ratio));
  }
  if (r.has("roughness_m")) {
    s.roughness = r.number("roughness_m");
    if (!(s.roughness >= 0) || !std::isfinite(s.roughness))
      r.fail("roughness_m", fmt::format("must be a finite length >= 0 (0: the linear penalty law), found {}",
                                        s.roughness));
  }
  if (const auto n = r.optional_integer("max_status_iterations")) {
    if (*n < 1 || *n > 1000) r.fail("max_status_iterations", fmt::format("must lie in 1..1000, found {}", *n));
    s.max_status_iterations = static_cast<int>(*n);
  }
  s.prestress = r.boolean("prestress", true);
  s.glued_reference = r.boolean("glued_reference", true);
  if (r.has("state_point")) {
    const std::vector<double> v = r.number_array("state_point");
    if (v.size() != 2) r.fail("state_point", "expected [interference_m, penalty_factor], a point of the grid");
    const auto i = std::find(s.interferences.begin(), s.interferences.end(), v[0]);
    const auto j = std::find(s.penalty_factors.begin(), s.penalty_factors.end(), v[1]);
    if (i == s.interferences.end() || j == s.penalty_factors.end())
      r.fail("state_point", fmt::format("[{}, {}] is not a point of the grid", v[0], v[1]));
    s.state_interference = static_cast<int>(i - s.interferences.begin());
    s.state_penalty = static_cast<int>(j - s.penalty_factors.begin());
  }
  s.options.shift_frequency_hz = r.optional_number("shift_hz").value_or(s.options.shift_frequency_hz);
  return s;
}

}  // namespace bb
