#include "fuzz_targets.hpp"

#include <unistd.h>

#include <array>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "analysis/run_analysis.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "common/errors.hpp"
#include "identify/measured_data.hpp"
#include "mesh/csv_mesh.hpp"
#include "mesh/abaqus_inp.hpp"
#include "mesh/gmsh_import.hpp"
#include "model/build_model.hpp"
#include "pipeline/calibrate_case.hpp"
#include "reduction/harwell_boeing.hpp"
#include "reduction/reduced_model_io.hpp"

namespace bb::fuzz {
namespace {

namespace fs = std::filesystem;

// A folder of this process for the input's files, emptied per input.
fs::path work_folder() {
  static const fs::path dir = fs::temp_directory_path() / ("bladebench_fuzz_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, std::string_view bytes) {
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::string_view> split(std::string_view all, size_t parts) {
  std::vector<std::string_view> out;
  const std::string_view sep(kSeparator);
  while (out.size() + 1 < parts) {
    const size_t at = all.find(sep);
    if (at == std::string_view::npos) break;
    out.push_back(all.substr(0, at));
    all.remove_prefix(at + sep.size());
  }
  out.push_back(all);
  while (out.size() < parts) out.emplace_back();
  return out;
}

// Runs `read`: InputError is the refusal of bad input; anything else escapes as a defect.
template <typename Fn>
void refuse_or_read(Fn&& read) {
  try {
    read();
  } catch (const InputError&) {
  }
}

}  // namespace

void case_file(const uint8_t* data, size_t size) {
  const fs::path file = work_folder() / "case.toml";
  write(file, {reinterpret_cast<const char*>(data), size});
  refuse_or_read([&] {
    const toml::table table = read_case_table(file);
    parse_calibration(table, file, parse_case_table(table, file));
  });
}

namespace {

// Nodes of a generated mesh, from its divisions (0 for meshes read from files).
double generated_nodes(const MeshSpec& m) {
  switch (m.kind) {
    case MeshSpec::Kind::mapped_quad:
      return (m.mapped.nx + 1.0) * (m.mapped.ny + 1.0);
    case MeshSpec::Kind::hex_blocks: {
      double n = 0.0;
      for (const HexBlockSpec& b : m.blocks) n += 8.0 * (b.nx + 1.0) * (b.ny + 1.0) * (b.nz + 1.0);
      return n;
    }
    default:
      return m.kind == MeshSpec::Kind::two_blade ? 1e4 * m.two_blade.refinement * m.two_blade.refinement : 0.0;
  }
}

}  // namespace

void case_run(const uint8_t* data, size_t size) {
  const fs::path file = work_folder() / "case.toml";
  write(file, {reinterpret_cast<const char*>(data), size});
  try {
    const CaseSpec spec = parse_case_table(read_case_table(file), file);
    if (generated_nodes(spec.model.mesh) > 2e4) return;  // the fuzzer's time, not a defect
    WorkLimits limits;
    limits.operations = 2e7;  // milliseconds of arithmetic, about a second under the sanitizers
    limits.bytes = 5e8;
    run_analysis(spec.analysis, build_model(spec.model), {}, limits);
  } catch (const InputError&) {
  } catch (const SolverError&) {
  }
}

void calibration(const uint8_t* data, size_t size) {
  const auto parts = split({reinterpret_cast<const char*>(data), size}, 3);
  const fs::path dir = work_folder();
  write(dir / "case.toml", parts[0]);
  for (int i = 1; i <= 2; ++i)  // one data file under the names a case may give it
    for (const char* ext : {".csv", ".uff", ".unv"}) write(dir / ("data" + std::to_string(i) + ext), parts[i]);
  try {
    const toml::table table = read_case_table(dir / "case.toml");
    const CaseSpec spec = parse_case_table(table, dir / "case.toml");
    const std::optional<CalibrationSpec> cal = parse_calibration(table, dir / "case.toml", spec);
    // The fuzzer's time, not a defect: large meshes and long fits.
    if (generated_nodes(spec.model.mesh) > 2e4 || (cal && static_cast<double>(cal->starts) * cal->max_iterations > 12.0)) return;
    WorkLimits limits;
    limits.operations = 2e7;
    limits.bytes = 5e8;
    calibrate_case(dir / "case.toml", {}, limits);
  } catch (const InputError&) {
  } catch (const SolverError&) {
  }
}

void measured_data(const uint8_t* data, size_t size) {
  if (size == 0) return;
  static constexpr std::array<DataKind, 4> kinds = {DataKind::peaks, DataKind::frf, DataKind::hysteresis,
                                                    DataKind::frf};
  const size_t pick = data[0] % 4;
  const fs::path file = work_folder() / (pick == 3 ? "data.uff" : "data.csv");
  write(file, {reinterpret_cast<const char*>(data) + 1, size - 1});
  refuse_or_read([&] { read_measured_data(file, kinds[pick]); });
}

void reduced_model(const uint8_t* data, size_t size) {
  const auto parts = split({reinterpret_cast<const char*>(data), size}, 3);
  const fs::path dir = work_folder();
  write(dir / "rom.toml", parts[0]);
  write(dir / "rom.K", parts[1]);
  write(dir / "rom.M", parts[2]);
  refuse_or_read([&] { read_reduced_model(dir / "rom.toml"); });
}

void csv_mesh(const uint8_t* data, size_t size) {
  if (size == 0) return;
  static constexpr std::array<ElementType, 5> types = {ElementType::q4, ElementType::cst, ElementType::hex8,
                                                       ElementType::hex8i, ElementType::hex20};
  const auto parts = split({reinterpret_cast<const char*>(data) + 1, size - 1}, 2);
  const fs::path dir = work_folder();
  write(dir / "nodes.csv", parts[0]);
  write(dir / "elements.csv", parts[1]);
  refuse_or_read([&] { read_csv_mesh(dir / "nodes.csv", dir / "elements.csv", types[data[0] % 5]); });
}

void gmsh_mesh(const uint8_t* data, size_t size) {
  const fs::path file = work_folder() / "mesh.msh";
  write(file, {reinterpret_cast<const char*>(data), size});
  refuse_or_read([&] { read_gmsh_msh41(file); });
}

void inp_deck(const uint8_t* data, size_t size) {
  const auto parts = split({reinterpret_cast<const char*>(data), size}, 2);
  const fs::path dir = work_folder();
  write(dir / "deck.inp", parts[0]);
  write(dir / "part.inp", parts[1]);
  refuse_or_read([&] { read_abaqus_inp(dir / "deck.inp", dir); });
}

void harwell_boeing(const uint8_t* data, size_t size) {
  if (size == 0) return;
  const auto parts = split({reinterpret_cast<const char*>(data) + 1, size - 1}, 2);
  const fs::path dir = work_folder();
  write(dir / "matrix.hb", parts[0]);
  write(dir / "dofs.mapping", parts[1]);
  const Eigen::Index n = data[0] % 16 + 1;
  refuse_or_read([&] { read_harwell_boeing(dir / "matrix.hb", n, "the fuzz input names them"); });
  refuse_or_read([&] { read_dof_map(dir / "dofs.mapping"); });
}

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {{"case_file", case_file},         {"case_run", case_run},         {"calibration", calibration},
                                          {"measured_data", measured_data}, {"reduced_model", reduced_model},
                                          {"csv_mesh", csv_mesh},           {"gmsh_mesh", gmsh_mesh},
                                          {"inp_deck", inp_deck},           {"harwell_boeing", harwell_boeing}};
  return all;
}

}  // namespace bb::fuzz
