// A measured-data file named by a case block (a calibration data block, a stepped sine): a CSV
// file, or a Universal File's dataset 58 picked by the block's `dataset` key, with a rig's force
// (reference) channel paired by `force_dataset` (identify/uff58.hpp).
#pragma once
#include <filesystem>
#include <optional>

#include "common/toml_reader.hpp"
#include "identify/measured_data.hpp"

namespace bb {

struct MeasuredFile {
  MeasuredData data;
  std::optional<long> dataset;  // the Universal File's response record, when picked
};

// Reads `file` as data of `kind`, with the block's keys `dataset` and `force_dataset`,
// `natural_frequency_hz` (the natural frequency a frequency column of ratios is relative to) and
// `phase_of` (what a frf file of phases alone, without an amplitude column, holds the phase of:
// "displacement", "velocity" or "acceleration"; required there, refused elsewhere). Throws
// InputError with file:line:key (then the file's own error) for a file that does not read, a
// dataset key on a CSV file or on data other than frf, a dataset beyond the file's, a force_dataset
// without dataset or equal to it, or records that do not pair.
// `phases_read`: the block uses the file's phases (a stepped sine reads only its frequencies and
// forces, so phases alone need no phase_of there).
MeasuredFile read_measured_file(TomlReader& r, const std::filesystem::path& file, DataKind kind,
                                bool phases_read = true);

}  // namespace bb
