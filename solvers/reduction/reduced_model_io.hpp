// Reduced models on disk: two matrix files (Matrix Market or CSV) and a TOML sidecar that names
// them and every DOF, so matrices exported from Ansys or NX can replace bladebench's own:
//
//   [reduced_model]
//   format = "matrix_market"        # or "csv": dense, comma-separated, no header, '#' comments;
//                                   # or "harwell_boeing" (RSA / RUA, an Ansys HBMAT export)
//   stiffness = "rom.K.mtx"         # relative to the sidecar
//   mass = "rom.M.mtx"
//   dofs = ["R.x", "R.y", "R.z", ..., "mode 1", ..., "mode 10"]
//   # or instead of dofs: dof_map = "rom.mapping" (reduction/harwell_boeing.hpp: Ansys's .mapping or
//   # a CSV node,direction; node 7's UX is the DOF "7.x")
#pragma once
#include <filesystem>

#include "reduction/reduced_model.hpp"

namespace bb {

// Writes `sidecar` and, next to it, <stem>.K.mtx / <stem>.M.mtx (full precision). The recovery
// matrix is not written. Throws InputError for a model validate_reduced_model rejects (only the
// lower triangles are stored, so it would not read back) or a file that cannot be written.
void write_reduced_model(const ReducedModel& model, const std::filesystem::path& sidecar);

// Throws InputError naming the file and line (or the sidecar field) of anything malformed,
// and everything validate_reduced_model rejects.
ReducedModel read_reduced_model(const std::filesystem::path& sidecar);

}  // namespace bb
