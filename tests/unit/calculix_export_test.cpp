// CalculiX deck export (report/calculix_export): the structure of the .inp on tiny hexahedral
// models, read back line by line. No ccx is needed; bench/calculix_compare.sh runs ccx on real
// cases. Units: SI.
#include "report/calculix_export.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "mesh/hex_block.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// A 2 x 1 x 1 m box of nx x 1 x 1 elements, clamped in xyz on x = 0 and held along z on x = 2.
Model box_model(ElementType type, int nx) {
  HexBlockSpec spec;
  spec.corners = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(2, 1, 0),
                  Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(2, 0, 1),
                  Eigen::Vector3d(2, 1, 1), Eigen::Vector3d(0, 1, 1)};
  spec.nx = nx;
  spec.element = type;
  Model model;
  model.mesh = generate_hex_block(spec);
  model.section = {.youngs_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850.0, .thickness = 0.0};
  for (int i = 0; i < model.mesh.n_nodes(); ++i) {
    if (std::abs(model.mesh.coords(i, 0)) < 1e-12) model.node_sets["root"].push_back(i);
    if (std::abs(model.mesh.coords(i, 0) - 2.0) < 1e-12) model.node_sets["tip end"].push_back(i);
  }
  model.constraints = {{.set = "root", .directions = {0, 1, 2}, .value = 0.0},
                       {.set = "tip end", .directions = {2}, .value = 0.0}};
  return model;
}

class CalculixDeck : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    file_ = fs::temp_directory_path() /
            ("bladebench_calculix_" + std::string(info->name()) + "_" + std::to_string(getpid()) + ".inp");
  }
  void TearDown() override { fs::remove(file_); }

  std::vector<std::string> write(const Model& model, int n_modes, const CalculixCyclic* cyclic = nullptr) {
    write_calculix_frequency_deck(model, n_modes, file_, nullptr, cyclic);
    std::ifstream in(file_);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }

  fs::path file_;
};

// Index of the first line that starts with `prefix`, or -1.
long find_line(const std::vector<std::string>& lines, const std::string& prefix, size_t from = 0) {
  for (size_t i = from; i < lines.size(); ++i)
    if (lines[i].rfind(prefix, 0) == 0) return static_cast<long>(i);
  return -1;
}

// The integers of one data record starting at line `at`, following continuation lines (a line
// ending in a comma); `at` is advanced past the record.
std::vector<long> read_record(const std::vector<std::string>& lines, size_t& at) {
  std::vector<long> values;
  bool more = true;
  while (more && at < lines.size()) {
    const std::string& line = lines[at++];
    more = !line.empty() && line.back() == ',';
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, ',');)
      if (field.find_first_not_of(' ') != std::string::npos) values.push_back(std::stol(field));
  }
  return values;
}

// Data records between keyword line `keyword_at` and the next keyword.
std::vector<std::vector<long>> records_after(const std::vector<std::string>& lines, long keyword_at) {
  std::vector<std::vector<long>> records;
  size_t at = static_cast<size_t>(keyword_at) + 1;
  while (at < lines.size() && lines[at].rfind('*', 0) != 0) records.push_back(read_record(lines, at));
  return records;
}

TEST_F(CalculixDeck, Hex20ConnectivityIsWrittenInMeshOrderOneBased) {
  const Model model = box_model(ElementType::hex20, 2);
  const auto lines = write(model, 5);
  const long at = find_line(lines, "*ELEMENT, TYPE=C3D20");
  ASSERT_GE(at, 0);
  EXPECT_EQ(find_line(lines, "*ELEMENT", static_cast<size_t>(at) + 1), -1) << "one block, one *ELEMENT keyword";
  const auto elements = records_after(lines, at);
  ASSERT_EQ(elements.size(), 2u);
  for (size_t e = 0; e < elements.size(); ++e) {
    ASSERT_EQ(elements[e].size(), 21u) << "element number and 20 nodes";
    EXPECT_EQ(elements[e][0], static_cast<long>(e + 1));
    for (int a = 0; a < 20; ++a)
      EXPECT_EQ(elements[e][static_cast<size_t>(a) + 1],
                model.mesh.blocks[0].conn(static_cast<Eigen::Index>(e), a) + 1L);
  }
}

TEST_F(CalculixDeck, NodesAreNumberedByInternalIndexWithTheirCoordinates) {
  const Model model = box_model(ElementType::hex20, 1);
  const auto lines = write(model, 5);
  const long at = find_line(lines, "*NODE");
  ASSERT_GE(at, 0);
  size_t row = static_cast<size_t>(at) + 1;
  for (int i = 0; i < model.mesh.n_nodes(); ++i, ++row) {
    std::stringstream ss(lines[row]);
    std::string field;
    std::getline(ss, field, ',');
    EXPECT_EQ(std::stol(field), i + 1L);
    for (int d = 0; d < 3; ++d) {
      std::getline(ss, field, ',');
      EXPECT_DOUBLE_EQ(std::stod(field), model.mesh.coords(i, d));
    }
  }
  EXPECT_EQ(lines[row].front(), '*') << "exactly one line per node";
}

TEST_F(CalculixDeck, EveryConstrainedSetHasAnNsetAndItsDirectionsInBoundary) {
  const Model model = box_model(ElementType::hex20, 2);
  const auto lines = write(model, 5);
  const long root = find_line(lines, "*NSET, NSET=N_ROOT");
  const long tip = find_line(lines, "*NSET, NSET=N_TIP_END");
  ASSERT_GE(root, 0);
  ASSERT_GE(tip, 0);
  for (const auto& [at, set] : {std::pair{root, "root"}, std::pair{tip, "tip end"}}) {
    std::vector<long> expected;
    for (const int i : model.node_sets.at(set)) expected.push_back(i + 1L);
    std::vector<long> written;
    for (const auto& r : records_after(lines, at)) written.insert(written.end(), r.begin(), r.end());
    EXPECT_EQ(written, expected) << set;
  }
  const long boundary = find_line(lines, "*BOUNDARY");
  ASSERT_GE(boundary, 0);
  const std::vector<std::string> expected = {"N_ROOT, 1, 1", "N_ROOT, 2, 2", "N_ROOT, 3, 3", "N_TIP_END, 3, 3"};
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(lines[static_cast<size_t>(boundary) + 1 + k], expected[k]);
  EXPECT_EQ(lines[static_cast<size_t>(boundary) + 1 + expected.size()].front(), '*');
}

TEST_F(CalculixDeck, MaterialSectionAndFrequencyStepAreComplete) {
  const auto lines = write(box_model(ElementType::hex20, 1), 7);
  const long elastic = find_line(lines, "*ELASTIC");
  const long density = find_line(lines, "*DENSITY");
  const long frequency = find_line(lines, "*FREQUENCY");
  ASSERT_GE(find_line(lines, "*MATERIAL, NAME=MAT"), 0);
  ASSERT_GE(elastic, 0);
  ASSERT_GE(density, 0);
  ASSERT_GE(frequency, 0);
  EXPECT_EQ(lines[static_cast<size_t>(elastic) + 1], "210000000000, 0.3");
  EXPECT_EQ(lines[static_cast<size_t>(density) + 1], "7850");
  EXPECT_GE(find_line(lines, "*SOLID SECTION, ELSET=E1, MATERIAL=MAT"), 0);
  EXPECT_LT(find_line(lines, "*STEP"), frequency);
  EXPECT_EQ(lines[static_cast<size_t>(frequency) + 1], "7");
  EXPECT_EQ(lines.back(), "*END STEP");
}

TEST_F(CalculixDeck, Hex8AndHex8iMapToC3D8AndC3D8I) {
  const auto hex8 = write(box_model(ElementType::hex8, 3), 4);
  const long at = find_line(hex8, "*ELEMENT, TYPE=C3D8,");
  ASSERT_GE(at, 0);
  const auto elements = records_after(hex8, at);
  ASSERT_EQ(elements.size(), 3u);
  EXPECT_EQ(elements[2].size(), 9u);
  EXPECT_GE(find_line(write(box_model(ElementType::hex8i, 1), 4), "*ELEMENT, TYPE=C3D8I,"), 0);
}

TEST_F(CalculixDeck, NonzeroPrescribedDisplacementIsRejected) {
  Model model = box_model(ElementType::hex20, 1);
  model.constraints[1].value = 1e-3;
  EXPECT_THROW(write_calculix_frequency_deck(model, 5, file_), InputError);
  EXPECT_FALSE(fs::exists(file_)) << "nothing written for a rejected model";
}

TEST_F(CalculixDeck, PlaneMeshAndNoModesAreRejected) {
  Model plane;
  plane.mesh.dim = 2;
  EXPECT_THROW(write_calculix_frequency_deck(plane, 5, file_), InputError);
  EXPECT_THROW(write_calculix_frequency_deck(box_model(ElementType::hex20, 1), 0, file_), InputError);
}

// A cyclic sector: the faces tied with the right one dependent, its clamped nodes left out (ccx
// refuses an SPC on the dependent side of an MPC), the nodal diameters selected in the step.
TEST_F(CalculixDeck, CyclicSectorTiesItsFacesWithoutConstrainedDependentNodes) {
  Model model = box_model(ElementType::hex8, 2);
  model.constraints.pop_back();                          // the tip end free
  model.node_sets["left"] = model.node_sets.at("root");  // 4 nodes, all clamped
  std::vector<int>& right_nodes = model.node_sets["right"];
  right_nodes = model.node_sets.at("tip end");  // 4 free nodes and 2 clamped ones
  right_nodes.push_back(model.node_sets.at("root")[0]);
  right_nodes.push_back(model.node_sets.at("root")[1]);
  const CalculixCyclic cyclic{12, "left", "right", 0, 6};
  const std::vector<std::string> lines = write(model, 8, &cyclic);
  auto at = [&](const std::string& text) {
    for (size_t i = 0; i < lines.size(); ++i)
      if (lines[i] == text) return i;
    ADD_FAILURE() << "no line '" << text << "'";
    return lines.size();
  };
  const size_t left = at("*NSET, NSET=CYCLIC_LEFT"), right = at("*NSET, NSET=CYCLIC_RIGHT");
  ASSERT_LT(left + 1, lines.size());
  EXPECT_EQ(std::count(lines[left + 1].begin(), lines[left + 1].end(), ','), 3);    // the independent face whole
  EXPECT_EQ(std::count(lines[right + 1].begin(), lines[right + 1].end(), ','), 3);  // the free four only
  EXPECT_EQ(lines[right + 2], "*SURFACE, NAME=S_CYCLIC_RIGHT, TYPE=NODE");
  const size_t tie = at("*TIE, NAME=CYCLIC, CYCLIC SYMMETRY");
  EXPECT_EQ(lines[tie + 1], "S_CYCLIC_RIGHT, S_CYCLIC_LEFT");
  const size_t model_line = at("*CYCLIC SYMMETRY MODEL, N=12, NGRAPH=1, TIE=CYCLIC");
  EXPECT_EQ(lines[model_line + 1], "0., 0., 0., 0., 0., 1.");
  const size_t select = at("*SELECT CYCLIC SYMMETRY MODES, NMIN=0, NMAX=6");
  EXPECT_EQ(lines[select - 1], "8");
  EXPECT_LT(model_line, at("*STEP"));
  // A node constrained in some directions only cannot be tied nor left out.
  model.constraints.push_back({.set = "tip end", .directions = {2}, .value = 0.0});
  EXPECT_THROW(write(model, 8, &cyclic), InputError);
}

}  // namespace
}  // namespace bb
