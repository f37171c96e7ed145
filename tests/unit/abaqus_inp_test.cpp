// Abaqus / CalculiX deck reader (mesh/abaqus_inp): every keyword it reads on hand-written decks, the
// CalculiX export read back to the identical mesh, and each refusal naming its file and line.
// Units: SI.
#include "mesh/abaqus_inp.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "mesh/hex_block.hpp"
#include "report/calculix_export.hpp"

namespace bb::abaqus_inp_test {
namespace {

namespace fs = std::filesystem;

class Deck : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ =
        fs::temp_directory_path() / ("bladebench_inp_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = folder_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }
  InpDeck read(const std::string& text) { return read_abaqus_inp(write("deck.inp", text), folder_); }
  // The message of the refusal of `text`, which must name deck.inp and `line`.
  std::string refusal(const std::string& text, int line) {
    try {
      read(text);
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("deck.inp:" + std::to_string(line) + ":"), std::string::npos) << message;
      return message;
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return "";
  }

  fs::path folder_;
};

// Two hex8 bricks side by side along x, 1 m cubes; node id = 1 + i + 3 j (+ 6 on the top face).
const std::string kNodes =
    "*NODE, NSET=ALLN\n"
    "1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n4, 0., 1., 0.\n5, 1., 1., 0.\n6, 2., 1., 0.\n"
    "7, 0., 0., 1.\n8, 1., 0., 1.\n9, 2., 0., 1.\n10, 0., 1., 1.\n11, 1., 1., 1.\n12, 2., 1., 1.\n";

const std::string kTwoBricks = "*HEADING\ntwo bricks\n** a comment\n" + kNodes +
                               "*ELEMENT, TYPE=C3D8, ELSET=BRICKS\n"
                               "1, 1, 2, 5, 4, 7, 8, 11, 10\n"
                               "2, 2, 3, 6, 5,\n 8, 9, 12, 11\n"
                               "*NSET, NSET=base, GENERATE\n1, 6, 1\n"
                               "*NSET, NSET=TipNodes\n3, 6, 9, 12\n"
                               "*ELSET, ELSET=ALL\nBRICKS\n"
                               "*MATERIAL, NAME=Steel\n*ELASTIC\n2.1E+11, 0.3\n*DENSITY\n7850.\n"
                               "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n"
                               "*BOUNDARY\nBASE, ENCASTRE\n12, 2, 2, 1.e-3\n"
                               "*STEP\n*FREQUENCY\n10\n*NODE FILE\nU\n*END STEP\n";

TEST_F(Deck, ReadsEveryKeywordOfAHandWrittenDeck) {
  const InpDeck d = read(kTwoBricks);
  const Mesh& m = d.mesh;
  ASSERT_EQ(m.dim, 3);
  ASSERT_EQ(m.n_nodes(), 12);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].type, ElementType::hex8);
  EXPECT_EQ(m.blocks[0].ids, (std::vector<long>{1, 2}));
  const std::vector<long> second = {2, 3, 6, 5, 8, 9, 12, 11};  // continued on the next line
  for (int a = 0; a < 8; ++a)
    EXPECT_EQ(m.node_ids[static_cast<size_t>(m.blocks[0].conn(1, a))], second[static_cast<size_t>(a)]);
  EXPECT_DOUBLE_EQ(m.coords(m.index_of(12), 0), 2.0);
  EXPECT_EQ(d.node_sets.at("BASE"), (std::vector<int>{0, 1, 2, 3, 4, 5}));  // names compare upper-cased
  EXPECT_EQ(d.node_sets.at("TIPNODES").size(), 4u);
  ASSERT_EQ(d.materials.size(), 1u);
  EXPECT_EQ(*d.materials[0].youngs_modulus, 2.1e11);
  EXPECT_EQ(*d.materials[0].poisson_ratio, 0.3);
  EXPECT_EQ(*d.materials[0].density, 7850.0);
  ASSERT_EQ(d.boundaries.size(), 2u);
  EXPECT_EQ(d.boundaries[0].set, "BASE");
  EXPECT_EQ(d.boundaries[0].first, 1);
  EXPECT_EQ(d.boundaries[0].last, 3);
  EXPECT_EQ(d.boundaries[1].set, "INP_NODE_12");
  EXPECT_EQ(d.boundaries[1].first, 2);
  EXPECT_EQ(d.boundaries[1].value, 1e-3);
  EXPECT_EQ(d.node_sets.at("INP_NODE_12"), (std::vector<int>{m.index_of(12)}));
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("*FREQUENCY step is not run"), std::string::npos) << d.notes[0];
}

TEST_F(Deck, HeaderOnlyGivesTypesAndMaterialWithoutTheLists) {
  const InpDeck d = read_abaqus_inp(write("deck.inp", kTwoBricks), folder_, true);
  EXPECT_EQ(d.mesh.n_nodes(), 0);
  ASSERT_EQ(d.mesh.blocks.size(), 1u);
  EXPECT_EQ(d.mesh.blocks[0].type, ElementType::hex8);
  ASSERT_EQ(d.materials.size(), 1u);
  EXPECT_EQ(*d.materials[0].youngs_modulus, 2.1e11);
}

// Abaqus writes a 20-node element as 16 numbers and 5 on the next line, without a trailing comma.
TEST_F(Deck, ReadsAHex20SplitAsAbaqusWritesIt) {
  std::string nodes = "*NODE\n";
  for (int i = 1; i <= 20; ++i) nodes += std::to_string(i) + ", " + std::to_string(i) + ".0, 0, 0\n";
  const InpDeck d = read(nodes +
                         "*ELEMENT, TYPE=C3D20R\n1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15\n"
                         "16, 17, 18, 19, 20\n");
  ASSERT_EQ(d.mesh.blocks.size(), 1u);
  EXPECT_EQ(d.mesh.blocks[0].type, ElementType::hex20);
  for (int a = 0; a < 20; ++a) EXPECT_EQ(d.mesh.blocks[0].conn(0, a), a);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("C3D20R"), std::string::npos);
}

TEST_F(Deck, ReadsAPlaneDeckWithItsThickness) {
  const InpDeck d = read(
      "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPS4, ELSET=P\n1, 1, 2, 3, 4\n"
      "*MATERIAL, NAME=AL\n*ELASTIC\n7e10, 0.33\n*SOLID SECTION, ELSET=P, MATERIAL=AL\n0.005\n");
  EXPECT_EQ(d.mesh.dim, 2);
  EXPECT_EQ(d.mesh.blocks[0].type, ElementType::q4);
  EXPECT_EQ(*d.thickness, 0.005);
  EXPECT_FALSE(d.materials[0].density.has_value());
}

TEST_F(Deck, FollowsIncludesInsideTheFolderOnly) {
  write("mesh/nodes.inp", kNodes);
  const InpDeck d = read("*INCLUDE, INPUT=mesh/nodes.inp\n*ELEMENT, TYPE=C3D8\n1, 1, 2, 5, 4, 7, 8, 11, 10\n");
  EXPECT_EQ(d.mesh.n_nodes(), 8);
  write("../outside_" + folder_.filename().string() + ".inp", kNodes);
  const std::string message = refusal("*INCLUDE, INPUT=../outside_" + folder_.filename().string() + ".inp\n", 1);
  EXPECT_NE(message.find("outside the case's folder"), std::string::npos) << message;
  fs::remove(folder_.parent_path() / ("outside_" + folder_.filename().string() + ".inp"));
  write("loop.inp", "*INCLUDE, INPUT=deck.inp\n");
  try {
    read("*INCLUDE, INPUT=loop.inp\n");
    ADD_FAILURE() << "an include loop was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loop.inp:1: *INCLUDE of"), std::string::npos) << e.what();
  }
}

TEST_F(Deck, RefusesWhatItDoesNotReadNamingTheLine) {
  const std::string element = "*ELEMENT, TYPE=C3D8\n1, 1, 2, 5, 4, 7, 8, 11, 10\n";
  struct Case {
    std::string deck;
    int line;
    std::string says;
  };
  const std::vector<Case> cases = {
      {kNodes + "*ELEMENT, TYPE=C3D10\n1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10\n", 14, "C3D10 is not one bladebench has"},
      {kNodes + element + "*STEP\n*STATIC\n*CLOAD\n3, 1, 1.\n*END STEP\n", 18, "*CLOAD is not read"},
      {kNodes + element + "*TIE, NAME=T\nA, B\n", 16, "*TIE is not read"},
      {kNodes + element + "*NSET, NSET=S\n1, 99\n", 16, "node set S names node 99"},
      {"*NODE\n1, 0, 0, 0\n1, 1, 0, 0\n", 3, "node 1 is defined twice"},
      {kNodes + element + "*MATERIAL, NAME=M\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n1, 2, 3, 4, 5, 6, 7, 8, 9\n", 17,
       "isotropic"},
      {kNodes + element + "*MATERIAL, NAME=M\n*ELASTIC\n2e11, 0.3, 20.\n", 18, "no temperature"},
      {kNodes + element + "*MATERIAL, NAME=M\n*ELASTIC\n2e11, 0.3\n2e11, 0.3\n", 17, "temperature-dependent"},
      {kNodes + element + "*SOLID SECTION, ELSET=E, MATERIAL=M\n", 16, "material M is not defined"},
      {kNodes + element + "*BOUNDARY\n1, 4, 6\n", 17, "DOFs 4 to 6"},
      {kNodes + element + "*BOUNDARY\nNOSUCH, 1, 3\n", 17, "node set NOSUCH is not defined"},
      {"*NODE\n1, 2.1D11, 0, 0\n", 2, "a finite number"},
      {kNodes + "*ELEMENT, TYPE=C3D8\n1, 1, 2, 5, 4, 7, 8, 11\n", 15, "the last element has 8 of its 9"},
      {kNodes + element + "*ELEMENT, TYPE=C3D8\n1, 2, 3, 6, 5, 8, 9, 12, 11\n", 17, "element 1 is defined twice"},
      {kNodes + "*ELEMENT, TYPE=C3D8\n1, 1, 2, 5, 4, 7, 8, 11, 77\n", 15, "names node 77"},
      {kNodes + element + "*NSET, NSET=G, GENERATE\n5, 1\n", 17, "needs first <= last"},
  };
  for (const Case& c : cases) {
    const std::string message = refusal(c.deck, c.line);
    EXPECT_NE(message.find(c.says), std::string::npos) << message;
  }
}

TEST_F(Deck, RefusesAnElementWithoutASectionWhenTheDeckHasSections) {
  const std::string deck = kNodes +
                           "*ELEMENT, TYPE=C3D8, ELSET=A\n1, 1, 2, 5, 4, 7, 8, 11, 10\n"
                           "*ELEMENT, TYPE=C3D8, ELSET=B\n2, 2, 3, 6, 5, 8, 9, 12, 11\n"
                           "*MATERIAL, NAME=M\n*ELASTIC\n2e11, 0.3\n*SOLID SECTION, ELSET=A, MATERIAL=M\n";
  EXPECT_NE(refusal(deck, 17).find("element 2 lies in no *SOLID SECTION"), std::string::npos);
}

// The CalculiX export read back gives the model's mesh: coordinates to the 14 digits a number longer
// than ccx's 20-character field is cut to (report/calculix_export), the connectivity in the same node
// order exactly, the constraints' sets and directions, the material.
TEST_F(Deck, ReadsTheCalculixExportBackToTheSameMesh) {
  for (const ElementType type : {ElementType::hex8, ElementType::hex8i, ElementType::hex20}) {
    HexBlockSpec spec;
    spec.corners = {Eigen::Vector3d(0, 0, 0),        Eigen::Vector3d(0.3, 0.01, 0), Eigen::Vector3d(0.31, 0.1, 0),
                    Eigen::Vector3d(0, 0.1, 0.02),   Eigen::Vector3d(0, 0, 0.05),   Eigen::Vector3d(0.3, 0, 0.05),
                    Eigen::Vector3d(0.3, 0.1, 0.05), Eigen::Vector3d(0, 0.1, 0.05)};
    spec.nx = 5, spec.ny = 2, spec.nz = 1;
    spec.element = type;
    Model model;
    model.mesh = generate_hex_block(spec);
    model.section = {.youngs_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850.0, .thickness = 0.0};
    for (int i = 0; i < model.mesh.n_nodes(); ++i)
      if (std::abs(model.mesh.coords(i, 0)) < 1e-12) model.node_sets["root"].push_back(i);
    model.constraints = {{.set = "root", .directions = {0, 1, 2}, .value = 0.0}};
    const fs::path file = folder_ / "export.inp";
    write_calculix_frequency_deck(model, 4, file);
    const InpDeck d = read_abaqus_inp(file, folder_);
    ASSERT_EQ(d.mesh.n_nodes(), model.mesh.n_nodes());
    ASSERT_EQ(d.mesh.coords.rows(), model.mesh.coords.rows());
    // Half a unit of the 14th digit of the largest coordinate (0.31 m).
    EXPECT_LE((d.mesh.coords - model.mesh.coords).cwiseAbs().maxCoeff(), 5e-14 * 0.31) << element_name(type);
    ASSERT_EQ(d.mesh.blocks.size(), 1u);
    EXPECT_EQ(d.mesh.blocks[0].type, type);
    EXPECT_EQ(d.mesh.blocks[0].conn, model.mesh.blocks[0].conn);
    ASSERT_EQ(d.boundaries.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(d.node_sets.at(d.boundaries[static_cast<size_t>(k)].set), model.node_sets.at("root"));
      EXPECT_EQ(d.boundaries[static_cast<size_t>(k)].first, k + 1);
    }
    EXPECT_EQ(*d.materials.at(0).youngs_modulus, 2.1e11);
    EXPECT_EQ(*d.materials.at(0).density, 7850.0);
  }
}

}  // namespace
}  // namespace bb::abaqus_inp_test
