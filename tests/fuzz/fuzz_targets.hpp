// Fuzz targets: each feeds arbitrary bytes to one reader of user input, as a file, and accepts
// only two outcomes: the input is read, or it is refused with InputError (exit 2 in the CLI). Any
// other exception, a crash or a sanitizer report is a defect. Built as libFuzzer programs with
// ASan + UBSan (tests/fuzz/CMakeLists.txt, option BLADEBENCH_FUZZ, clang), and replayed on the
// committed regression inputs by the default tests (fuzz_regressions_test.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace bb::fuzz {

// Multi-file inputs are split at this line: "@@\n".
inline constexpr const char* kSeparator = "\n@@\n";

void case_file(const uint8_t* data, size_t size);  // TOML case: parse_case_table + parse_calibration
// TOML case parsed, its model built and its analysis run (every type) under a work bound of 2e7;
// SolverError is a verdict too (exit 3). Generated meshes above 20 000 nodes are passed over.
void case_run(const uint8_t* data, size_t size);
// A case with [calibration] @@ its first data file @@ its second (written as data1 / data2 with
// each extension a case may name), calibrated under the same bound per evaluation; fits of more
// than 12 iterations in all are passed over.
void calibration(const uint8_t* data, size_t size);
void measured_data(const uint8_t* data, size_t size);  // byte 0 picks peaks / frf / hysteresis CSV or a .uff
void reduced_model(const uint8_t* data, size_t size);  // sidecar @@ K @@ M (Matrix Market or CSV)
void csv_mesh(const uint8_t* data, size_t size);       // byte 0 picks the element; nodes @@ elements
void gmsh_mesh(const uint8_t* data, size_t size);      // a Gmsh .msh file
void inp_deck(const uint8_t* data, size_t size);       // an Abaqus / CalculiX deck @@ a file it may *INCLUDE (part.inp)
void harwell_boeing(const uint8_t* data, size_t size);  // byte 0 picks n (1-16); a matrix file @@ a DOF map

struct Target {
  const char* name;
  void (*run)(const uint8_t*, size_t);
};
const std::vector<Target>& targets();

}  // namespace bb::fuzz
