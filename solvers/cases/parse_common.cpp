#include "cases/parse_common.hpp"

namespace bb {

Direction parse_direction(TomlReader& r, const std::string& key, const std::string& value) {
  if (value == "x") return 0;
  if (value == "y") return 1;
  if (value == "z") return 2;
  r.fail(key, fmt::format("unknown direction '{}'; expected x, y or z", value));
}

LoadSplit parse_split(TomlReader& r, const std::string& key) {
  return r.choice(key, {"equal", "consistent"}) == "equal" ? LoadSplit::equal : LoadSplit::consistent_edge;
}

}  // namespace bb
