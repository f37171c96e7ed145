// [mesh] kind = "inp": an Abaqus / CalculiX deck as the case's mesh, its material and thickness.
#pragma once
#include <filesystem>

#include "common/toml_reader.hpp"
#include "mesh/abaqus_inp.hpp"
#include "model/model_spec.hpp"

namespace bb {

// A deck's element type is the deck's: `element`, when given, must name it.
// `header`: the deck's keywords and small data (mesh/abaqus_inp.hpp, header only).
void parse_inp_mesh(TomlReader& r, MeshSpec& m, const std::filesystem::path& folder, InpDeck& header);
// A deck's one material, checked as [material] is, its messages naming the deck's lines.
void material_from_deck(const InpDeck& deck, ModelSpec& spec, bool needs_mass);

}  // namespace bb
