// Small pieces every case-file parser shares: directions, load splits, arrays of tables.
#pragma once
#include <fmt/format.h>

#include <string>

#include "common/toml_reader.hpp"
#include "linalg/modal_solver.hpp"
#include "model/model.hpp"

namespace bb {

// "x", "y" or "z".
Direction parse_direction(TomlReader& r, const std::string& key, const std::string& value);
// "equal" or "consistent".
LoadSplit parse_split(TomlReader& r, const std::string& key);
// `eigensolver = "spectra" | "slepc"` (default spectra); slepc in a build without it is refused here.
Eigensolver parse_eigensolver(TomlReader& r);
// `out_of_core = true | false` (default false), only with eigensolver = "slepc".
bool parse_out_of_core(TomlReader& r, Eigensolver eigensolver);

// fn(reader) for each [[key]] table of `top`; a non-table entry is an error.
template <typename Fn>
void for_each_table_in_array(TomlReader& top, const std::string& key, Fn fn) {
  if (!top.has(key)) return;
  const toml::array& arr = top.array(key);
  int index = 0;
  for (const toml::node& n : arr) {
    if (!n.is_table()) top.fail(key, fmt::format("write entries as [[{}]] tables", key));
    fn(TomlReader(*n.as_table(), fmt::format("{}[{}]", key, index++), top.file()));
  }
}

}  // namespace bb
