#include "cases/parse_inp.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "cases/parse_common.hpp"
#include "common/errors.hpp"
#include "mesh/element_topology.hpp"

namespace bb {

void parse_inp_mesh(TomlReader& r, MeshSpec& m, const std::filesystem::path& folder, InpDeck& header) {
  m.kind = MeshSpec::Kind::inp;
  m.inp_file = r.input_file("file", folder);
  m.inp_folder = folder;
  header = read_abaqus_inp(m.inp_file, folder, true);
  const ElementType type = header.mesh.blocks.front().type;
  for (const ElementBlock& b : header.mesh.blocks)
    if (b.type != type)
      r.fail("file", fmt::format("the deck holds {} and {} elements; a bladebench mesh holds one element type",
                                 topology(type).calculix, topology(b.type).calculix));
  std::vector<std::string> names;
  for (ElementType t : element_types()) names.emplace_back(element_name(t));
  if (r.has("element") && element_type_named(r.choice("element", names)) != type)
    r.fail("element", fmt::format("the deck's elements are {} ({}); leave 'element' out or name that type",
                                  topology(type).calculix, element_name(type)));
  m.element = type;
}

void material_from_deck(const InpDeck& deck, ModelSpec& spec, bool needs_mass) {
  const std::string where = spec.mesh.inp_file.string();
  if (deck.materials.empty())
    throw InputError(fmt::format("{}: the deck has no *SOLID SECTION naming a *MATERIAL: give [material] in the case",
                                 spec.mesh.at.where()));
  if (deck.materials.size() > 1)
    throw InputError(
        fmt::format("{}: the deck's sections name {} materials ({} at {}, {} at {}); bladebench's model has one", where,
                    deck.materials.size(), deck.materials[0].name, deck.materials[0].where, deck.materials[1].name,
                    deck.materials[1].where));
  const InpMaterial& m = deck.materials.front();
  auto fail = [&](const std::string& message) {
    throw InputError(fmt::format("{}: *MATERIAL {}: {}", m.where, m.name, message));
  };
  if (!m.youngs_modulus) fail("has no *ELASTIC");
  if (!(*m.youngs_modulus > 0)) fail(fmt::format("Young's modulus must be > 0, found {}", *m.youngs_modulus));
  if (!(*m.poisson_ratio > -1 && *m.poisson_ratio < 0.5))
    fail(fmt::format("Poisson's ratio must lie in (-1, 0.5), found {}", *m.poisson_ratio));
  if (m.density && !(*m.density >= 0)) fail(fmt::format("the density must be >= 0, found {}", *m.density));
  if (needs_mass && !(m.density.value_or(0.0) > 0))
    fail("needs a *DENSITY > 0 for a modal analysis or a forced response");
  spec.section.youngs_modulus = *m.youngs_modulus;
  spec.section.poisson_ratio = *m.poisson_ratio;
  spec.section.density = m.density.value_or(0.0);
}

}  // namespace bb
