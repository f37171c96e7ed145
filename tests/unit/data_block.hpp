// A [[calibration.data]] block built in a test: a measured-data file matched to a result table.
#pragma once
#include <filesystem>
#include <map>
#include <string>

#include "cases/parse_calibration.hpp"

namespace bb::test {

inline CalibrationData data_block(const std::filesystem::path& file, DataKind kind, const std::string& table,
                                  std::map<std::string, std::string> columns) {
  CalibrationData d;
  d.name = file.stem().string();
  d.data = read_measured_data(file, kind);
  d.table = table;
  d.columns = std::move(columns);
  return d;
}

// The frf block of the response A.x in the table frf_1, as the harmonic balance names its columns.
inline CalibrationData frf_block(const std::filesystem::path& file) {
  return data_block(file, DataKind::frf, "frf_1",
                    {{"frequency", "frequency_hz"}, {"amplitude", "A.x_amp_m"}, {"phase", "A.x_phase_deg"}});
}

}  // namespace bb::test
