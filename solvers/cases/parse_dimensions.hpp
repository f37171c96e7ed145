// [mesh.dimensions] of a parametric article: any subset of its named dimensions (the others keep
// their documented defaults), then its own validation, an impossible dimension reported at the
// line that set it.
#pragma once
#include <optional>
#include <string>

#include "articles/dimension_error.hpp"
#include "common/toml_reader.hpp"

namespace bb {

// `fields` lists {name, member pointer}; `fallback_key` is blamed when no key set the dimension.
template <class Dimensions, class Fields>
void parse_dimensions(TomlReader& r, Dimensions& d, const Fields& fields, const std::string& fallback_key = {}) {
  std::optional<TomlReader> dims;
  if (const toml::table* table = r.optional_table("dimensions")) {
    dims.emplace(*table, r.path() + ".dimensions", r.file());
    for (const auto& f : fields)
      if (auto v = dims->optional_number(f.name)) d.*f.member = *v;
    dims->finish();
  }
  try {
    d.validate();
  } catch (const DimensionError& e) {
    if (dims && dims->has(e.name())) dims->fail(e.name(), e.what());
    r.fail(r.has(e.name()) ? e.name() : fallback_key, e.what());
  }
}

}  // namespace bb
