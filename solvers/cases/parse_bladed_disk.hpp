// [mesh] with kind = "bladed_disk": one sector of the parametric bladed disk
// (articles/bladed_disk.hpp), its divisions in [mesh] and its dimensions in [mesh.dimensions].
#pragma once
#include "common/toml_reader.hpp"
#include "model/model_spec.hpp"

namespace bb {

// Throws InputError naming the key (or the dimension) that makes the sector impossible.
void parse_bladed_disk(TomlReader& r, MeshSpec& m);

}  // namespace bb
