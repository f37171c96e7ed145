#include "cases/parse_bladed_disk.hpp"

#include "cases/parse_dimensions.hpp"

namespace bb {

void parse_bladed_disk(TomlReader& r, MeshSpec& m) {
  m.kind = MeshSpec::Kind::bladed_disk;
  if (m.dim() != 3) r.fail("element", "kind 'bladed_disk' needs a solid element (hex8, hex8i, hex20)");
  BladedDiskDimensions& d = m.bladed_disk;
  d.sectors = static_cast<int>(r.integer("sectors", 3, 1000));
  d.refinement = static_cast<int>(r.optional_integer("refinement", 1, 64).value_or(d.refinement));
  d.chord_divisions = static_cast<int>(r.optional_integer("chord_divisions", 2, 1000).value_or(d.chord_divisions));
  d.airfoil_divisions =
      static_cast<int>(r.optional_integer("airfoil_divisions", 1, 1000).value_or(d.airfoil_divisions));
  parse_dimensions(r, d, bladed_disk_dimension_fields(), "sectors");
}

}  // namespace bb
