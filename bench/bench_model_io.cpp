// Models in and results out at the size of a production blade: a 100 000-node hex20 mesh (a
// 29 x 29 x 29 block, 24 389 elements, 105 300 nodes) written as a CalculiX deck by the export and
// read back by the deck reader (mesh/abaqus_inp), and the .vtu of 20 mode shapes over it
// (mesh/vtu_writer). Issue 72's targets: under 2 s each. The shapes are made up: the cost does not
// depend on the values. The deck goes to the system's temporary folder.
//
// Measurement only: nothing here asserts a time. Counters: nodes, bytes of the file.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "mesh/abaqus_inp.hpp"
#include "mesh/hex_block.hpp"
#include "mesh/vtu_writer.hpp"
#include "model/model.hpp"
#include "report/calculix_export.hpp"

namespace {

namespace fs = std::filesystem;

struct IoScene {
  bb::Model model;
  fs::path folder;
  fs::path deck;
  ~IoScene() {
    std::error_code ignored;
    fs::remove_all(folder, ignored);
  }
};

const IoScene& io_scene() {
  static const IoScene s = [] {
    IoScene out;
    bb::HexBlockSpec spec;
    spec.corners = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d(0.3, 0.1, 0),
                    Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0, 0, 0.05), Eigen::Vector3d(0.3, 0, 0.05),
                    Eigen::Vector3d(0.3, 0.1, 0.05), Eigen::Vector3d(0, 0.1, 0.05)};
    spec.nx = spec.ny = spec.nz = 29;
    spec.element = bb::ElementType::hex20;
    out.model.mesh = bb::generate_hex_block(spec);
    out.model.section = {.youngs_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850.0, .thickness = 0.0};
    for (int i = 0; i < out.model.mesh.n_nodes(); ++i)
      if (out.model.mesh.coords(i, 0) == 0.0) out.model.node_sets["root"].push_back(i);
    out.model.constraints = {{.set = "root", .directions = {0, 1, 2}, .value = 0.0}};
    out.folder = fs::temp_directory_path() / ("bladebench_bench_io_" + std::to_string(getpid()));
    fs::create_directories(out.folder);
    out.deck = out.folder / "block.inp";
    bb::write_calculix_frequency_deck(out.model, 20, out.deck);
    return out;
  }();
  return s;
}

void BM_ReadInpHex20(benchmark::State& state) {
  const IoScene& s = io_scene();
  int nodes = 0;
  for (auto _ : state) {
    const bb::InpDeck deck = bb::read_abaqus_inp(s.deck, s.folder);
    nodes = deck.mesh.n_nodes();
    benchmark::DoNotOptimize(deck.mesh.coords.data());
  }
  state.counters["nodes"] = nodes;
  state.counters["bytes"] = static_cast<double>(fs::file_size(s.deck));
}
BENCHMARK(BM_ReadInpHex20)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_WriteVtu20ModesHex20(benchmark::State& state) {
  const IoScene& s = io_scene();
  const Eigen::MatrixXd& x = s.model.mesh.coords;
  bb::VtkContent content;
  for (int k = 1; k <= 20; ++k) {
    Eigen::MatrixXd shape(x.rows(), 3);
    for (Eigen::Index n = 0; n < x.rows(); ++n)
      shape.row(n) << std::sin(k * x(n, 0)), std::cos(k * x(n, 1)), 1e-3 * k * x(n, 2);
    content.point_arrays.push_back({"mode_" + std::to_string(k), shape, {"x", "y", "z"}});
  }
  content.field_arrays.push_back({"frequency_hz", std::vector<double>(20, 100.0)});
  const fs::path file = s.folder / "modes.vtu";
  for (auto _ : state) bb::write_vtu(file, s.model.mesh, content);
  state.counters["nodes"] = static_cast<double>(x.rows());
  state.counters["bytes"] = static_cast<double>(fs::file_size(file));
}
BENCHMARK(BM_WriteVtu20ModesHex20)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
