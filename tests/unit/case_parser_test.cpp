// Case files (cases/parse_case, cases/build_model): the thesis cases parse into the values they
// state, a minimal case gets the documented defaults, and malformed input fails with a message
// that names the key and the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/static_analysis.hpp"
#include "assembly/load_vector.hpp"
#include "cases/case_spec.hpp"
#include "cases/parse_calibration.hpp"
#include "common/errors.hpp"
#include "model/build_model.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

const fs::path kThesisCases = fs::path(BB_SOURCE_DIR) / "cases" / "thesis";

// Every shipped case keeps to the rules for names, labels and file keys (cases/README.md, "Names
// and labels"): tightening them must not refuse a case that validates today.
TEST(ShippedCases, EveryCaseAndItsCalibrationParse) {
  int parsed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(BB_SOURCE_DIR) / "cases")) {
    const fs::path& file = entry.path();
    if (file.extension() != ".toml" || file.string().find("/data/") != std::string::npos) continue;
    EXPECT_NO_THROW({
      const toml::table table = read_case_table(file);
      parse_calibration(table, file, parse_case_table(table, file));
    }) << file;
    ++parsed;
  }
  EXPECT_GE(parsed, 40);
}

TEST(ThesisCases, TableTwoCaseParsesIntoItsStatedValues) {
  const CaseSpec spec = parse_case_file(kThesisCases / "table02_q4_cantilever.toml");
  EXPECT_EQ(spec.name, "table02_q4_cantilever");
  EXPECT_EQ(spec.model.section.youngs_modulus, 2.0e11);
  EXPECT_EQ(spec.model.section.poisson_ratio, 0.25);
  EXPECT_EQ(spec.model.section.density, 8000.0);
  EXPECT_EQ(spec.model.section.thickness, 0.01);
  ASSERT_EQ(spec.model.mesh.kind, MeshSpec::Kind::mapped_quad);
  EXPECT_EQ(spec.model.mesh.element, ElementType::q4);
  EXPECT_EQ(spec.model.mesh.mapped.nx, 5);
  EXPECT_EQ(spec.model.mesh.mapped.ny, 2);
  EXPECT_EQ(spec.model.mesh.mapped.numbering, NodeNumbering::serpentine);
  EXPECT_EQ(spec.model.mesh.mapped.corners[2], Eigen::Vector2d(10.0, 2.0));
  ASSERT_EQ(spec.model.constraints.size(), 1u);
  EXPECT_EQ(spec.model.constraints[0].constraint.set, "clamp");
  EXPECT_EQ(spec.model.constraints[0].constraint.directions, (std::vector<Direction>{0, 1}));
  ASSERT_EQ(spec.model.loads.size(), 1u);
  EXPECT_EQ(spec.model.loads[0].load.total, -1.0e5);
  EXPECT_EQ(spec.model.loads[0].load.direction, 1);
  EXPECT_EQ(spec.model.loads[0].load.split, LoadSplit::consistent_edge);
  EXPECT_TRUE(std::holds_alternative<StaticSpec>(spec.analysis));
  ASSERT_EQ(spec.checks.size(), 2u);
  EXPECT_EQ(spec.checks[0].abs_tol, 2.0e-5);
  EXPECT_EQ(spec.checks[0].reference.filename(), "table02.csv");
  ASSERT_TRUE(spec.study.has_value());
  EXPECT_EQ(std::get<RefinementStudySpec>(*spec.study).levels.size(), 7u);
  EXPECT_EQ(std::get<RefinementStudySpec>(*spec.study).beam_length, 10.0);
  EXPECT_EQ(std::get<RefinementStudySpec>(*spec.study).beam_height, 2.0);
}

TEST(ThesisCases, TableFourCaseParsesIntoItsStatedValues) {
  const CaseSpec spec = parse_case_file(kThesisCases / "table04_cst_cantilever.toml");
  EXPECT_EQ(spec.model.section.youngs_modulus, 2.2e11);
  EXPECT_EQ(spec.model.section.poisson_ratio, 0.3);
  EXPECT_EQ(spec.model.section.density, 7730.0);
  EXPECT_EQ(spec.model.section.thickness, 0.1);
  EXPECT_EQ(spec.model.mesh.element, ElementType::cst);
  EXPECT_EQ(spec.model.mesh.mapped.nx, 5);
  EXPECT_EQ(spec.model.mesh.mapped.ny, 1);
  EXPECT_EQ(spec.model.mesh.mapped.diagonal, TriangleDiagonal::bottom_right_to_top_left);
  ASSERT_EQ(spec.model.loads.size(), 1u);
  EXPECT_EQ(spec.model.loads[0].load.set, "load_point");
  EXPECT_EQ(spec.model.loads[0].load.total, -1.0e4);
  EXPECT_EQ(spec.model.loads[0].load.split, LoadSplit::equal);
  ASSERT_TRUE(spec.study.has_value());
  EXPECT_EQ(std::get<RefinementStudySpec>(*spec.study).load_split, LoadSplit::consistent_edge);
}

TEST(ThesisCases, TableTwoModelResolvesTheClampAndTipSetsOnTheMesh) {
  const Model model = build_model(parse_case_file(kThesisCases / "table02_q4_cantilever.toml").model);
  EXPECT_EQ(model.mesh.n_nodes(), 18);
  EXPECT_EQ(model.mesh.n_elements(), 10);
  ASSERT_EQ(model.node_sets.at("clamp").size(), 3u);
  ASSERT_EQ(model.node_sets.at("tip").size(), 3u);
  for (int n : model.node_sets.at("clamp")) EXPECT_EQ(model.mesh.coords(n, 0), 0.0);
  for (int n : model.node_sets.at("tip")) EXPECT_EQ(model.mesh.coords(n, 0), 10.0);
  // Node 18 is the top tip corner (Table II); the tip load bends the beam downwards there.
  const StaticSolution sol = solve_static(model);
  const int n18 = model.mesh.index_of(18);
  ASSERT_GE(n18, 0);
  EXPECT_LT(sol.displacements(n18, 1), 0.0);
  EXPECT_GT(sol.displacements(n18, 0), 0.0) << "the top fibre at the tip moves towards +x under a downward load";
}

TEST(ThesisCases, TableFourLoadPointIsTheSingleTopTipNodeSeven) {
  const Model model = build_model(parse_case_file(kThesisCases / "table04_cst_cantilever.toml").model);
  ASSERT_EQ(model.node_sets.at("load_point").size(), 1u);
  EXPECT_EQ(model.mesh.node_ids[static_cast<size_t>(model.node_sets.at("load_point")[0])], 7);
}

// A minimal valid case; tests insert, replace or remove lines, then write it to a private folder.
const std::string kMinimalCase = R"([case]
name = "minimal"

[material]
E = 2.0e11
nu = 0.3
rho = 7800.0

[section]
thickness = 0.1

[mesh]
kind = "mapped_quad"
element = "q4"
corners = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]
nx = 4
ny = 2

[sets.left]
x = 0.0

[sets.right]
x = 2.0

[[bc]]
set = "left"
dofs = ["x", "y"]

[[load]]
set = "right"
direction = "y"
total = -1000.0
split = "consistent"

[analysis]
type = "static"
)";

class CaseFile : public test::TempFolderTest {
 protected:
  // The case with `line` inserted after the first line equal to `after`; returns its 1-based line.
  static std::string insert_after(const std::string& text, const std::string& after, const std::string& line,
                                  int& line_no) {
    const size_t at = text.find(after + "\n");
    EXPECT_NE(at, std::string::npos) << after;
    const size_t end = at + after.size() + 1;
    line_no = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
    return text.substr(0, end) + line + "\n" + text.substr(end);
  }
  static std::string replace(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  }
  // The InputError message parse_case_file throws, or "" when it does not throw.
  static std::string error_of(const fs::path& file) {
    try {
      parse_case_file(file);
    } catch (const InputError& e) {
      return e.what();
    }
    return {};
  }
};

TEST_F(CaseFile, MinimalCaseParsesWithTheDocumentedDefaults) {
  const CaseSpec spec = parse_case_file(write(kMinimalCase));
  EXPECT_EQ(spec.name, "minimal");
  EXPECT_EQ(spec.title, "minimal");
  EXPECT_EQ(spec.model.mesh.mapped.numbering, NodeNumbering::rows);
  EXPECT_EQ(spec.model.mesh.mapped.diagonal, TriangleDiagonal::bottom_left_to_top_right);
  EXPECT_EQ(spec.model.mesh.mapped.first_node_id, 1);
  EXPECT_EQ(spec.model.mesh.mapped.first_element_id, 1);
  ASSERT_EQ(spec.model.sets.size(), 2u);
  EXPECT_EQ(spec.model.constraints[0].constraint.value, 0.0);
  EXPECT_EQ(spec.model.constraints[0].at.line, 25);
  EXPECT_FALSE(spec.study.has_value());
  EXPECT_TRUE(spec.checks.empty());
  // And it runs: a downward tip load on a cantilever gives a downward tip.
  const Model model = build_model(spec.model);
  const StaticSolution sol = solve_static(model);
  for (int n : model.node_sets.at("right")) EXPECT_LT(sol.displacements(n, 1), 0.0);
}

TEST_F(CaseFile, ModalAnalysisReadsModesAndShift) {
  const CaseSpec spec =
      parse_case_file(write(replace(kMinimalCase, "type = \"static\"", "type = \"modal\"\nmodes = 4\nshift_hz = 2.5")));
  EXPECT_TRUE(std::holds_alternative<ModalSpec>(spec.analysis));
  EXPECT_EQ(std::get<ModalSpec>(spec.analysis).modes.lowest, 4);
  EXPECT_EQ(std::get<ModalSpec>(spec.analysis).options.shift_frequency_hz, 2.5);
}

// The [[load]] forms besides the nodal total: each reaches the model as its typed load, and the
// static run applies them (the resultant of each is its closed form).
TEST_F(CaseFile, DistributedAndBodyLoadsParseIntoTheirTypedLoads) {
  const std::string loads = R"([[load]]
type = "pressure"
edges = "right"
pressure = -2.0e6

[[load]]
type = "traction"
edges = "right"
traction = [0.0, 5.0e5]

[[load]]
type = "gravity"
acceleration = [0.0, -9.81]

[[load]]
type = "centrifugal"
speed = 100.0
axis = [0.0, 0.0, 1.0]
origin = [-1.0, 0.5]
)";
  const CaseSpec spec = parse_case_file(write(replace(kMinimalCase, "[analysis]", loads + "\n[analysis]")));
  ASSERT_EQ(spec.model.loads.size(), 1u);  // the nodal total is unchanged
  ASSERT_EQ(spec.model.surface_loads.size(), 2u);
  EXPECT_EQ(spec.model.surface_loads[0].load.kind, SurfaceLoad::Kind::pressure);
  EXPECT_EQ(spec.model.surface_loads[0].load.pressure, -2.0e6);
  EXPECT_EQ(spec.model.surface_loads[0].key, "load[1].edges");
  EXPECT_EQ(spec.model.surface_loads[1].load.traction, Eigen::Vector3d(0.0, 5.0e5, 0.0));
  ASSERT_EQ(spec.model.body_loads.size(), 2u);
  EXPECT_EQ(spec.model.body_loads[0].load.acceleration, Eigen::Vector3d(0.0, -9.81, 0.0));
  EXPECT_EQ(spec.model.body_loads[1].load.kind, BodyLoad::Kind::centrifugal);
  EXPECT_EQ(spec.model.body_loads[1].load.origin, Eigen::Vector3d(-1.0, 0.5, 0.0));
  const Model model = build_model(spec.model);
  const Eigen::VectorXd f = load_vector(model);
  double fx = 0, fy = 0;
  for (Eigen::Index i = 0; i < f.size(); i += 2) {
    fx += f[i];
    fy += f[i + 1];
  }
  // Edge x = 2, height 1, thickness 0.1: the pull 2e6 Pa gives +2e5 N along x, the traction +5e4 N
  // along y; the 2 x 1 x 0.1 m plate of 7800 kg/m^3 weighs 1560 kg x 9.81; spinning about (-1, 0.5)
  // its centroid (1, 0.5) lies 2 m off the axis: 1560 kg x 100^2 x 2 m along +x.
  const double mass = 7800.0 * 2.0 * 1.0 * 0.1;
  EXPECT_NEAR(fx, 2e5 + mass * 1e4 * 2.0, 1e-6 * mass * 1e4);
  EXPECT_NEAR(fy, -1000.0 + 5e4 - mass * 9.81, 1e-6 * mass * 9.81);
}

TEST_F(CaseFile, UnknownKeyIsRejectedNamingTheKeyAndItsLine) {
  int line = 0;
  const fs::path file = write(insert_after(kMinimalCase, "ny = 2", "nxx = 5", line));
  const std::string msg = error_of(file);
  ASSERT_FALSE(msg.empty()) << "a typo must not pass silently";
  EXPECT_NE(msg.find("nxx"), std::string::npos) << msg;
  EXPECT_NE(msg.find(":" + std::to_string(line) + ":"), std::string::npos) << "line " << line << ": " << msg;
  EXPECT_NE(msg.find("unknown key"), std::string::npos) << msg;
}

TEST_F(CaseFile, UnknownKeyInsideAnArrayOfTablesIsRejectedNamingTheKeyAndItsLine) {
  int line = 0;
  const fs::path file = write(insert_after(kMinimalCase, "dofs = [\"x\", \"y\"]", "valeu = 1.0", line));
  const std::string msg = error_of(file);
  ASSERT_FALSE(msg.empty());
  EXPECT_NE(msg.find("valeu"), std::string::npos) << msg;
  EXPECT_NE(msg.find(":" + std::to_string(line) + ":"), std::string::npos) << "line " << line << ": " << msg;
}

TEST_F(CaseFile, UnknownTopLevelTableIsRejected) {
  const std::string msg = error_of(write(kMinimalCase + "\n[solver]\ntolerance = 1e-9\n"));
  EXPECT_NE(msg.find("solver"), std::string::npos) << msg;
}

TEST_F(CaseFile, MissingRequiredKeyIsNamed) {
  const std::string msg = error_of(write(replace(kMinimalCase, "thickness = 0.1\n", "")));
  EXPECT_NE(msg.find("thickness"), std::string::npos) << msg;
}

TEST_F(CaseFile, ValueOfTheWrongTypeIsNamedWithItsLine) {
  const std::string msg = error_of(write(replace(kMinimalCase, "nx = 4", "nx = 4.5")));
  EXPECT_NE(msg.find("nx"), std::string::npos) << msg;
  EXPECT_NE(msg.find(":16:"), std::string::npos) << msg;
}

// Every number and integer of a case passes one reader (common/toml_reader): a float key may be
// written as any integer, an integer never wraps, and no magnitude beyond SI reason passes.
TEST_F(CaseFile, NumbersAreReadOnceWithTheirRangeChecked) {
  const CaseSpec big = parse_case_file(write(replace(kMinimalCase, "E = 2.0e11", "E = 9223372036854775807")));
  EXPECT_DOUBLE_EQ(big.model.section.youngs_modulus, 9223372036854775807.0);
  for (const char* wraps : {"nx = 2147483648", "nx = 4294967300", "nx = -9223372036854775808"}) {
    const std::string msg = error_of(write(replace(kMinimalCase, "nx = 4", wraps)));
    EXPECT_NE(msg.find("'mesh.nx'"), std::string::npos) << wraps << ": " << msg;
    EXPECT_NE(msg.find("out of range"), std::string::npos) << wraps << ": " << msg;
  }
  for (const char* extreme : {"E = 1e101", "E = 1e-320", "E = -1e300"}) {
    const std::string msg = error_of(write(replace(kMinimalCase, "E = 2.0e11", extreme)));
    EXPECT_NE(msg.find("'material.E'"), std::string::npos) << extreme << ": " << msg;
  }
  EXPECT_EQ(error_of(write(replace(kMinimalCase, "E = 2.0e11", "E = 1e100"))), "");
}

TEST_F(CaseFile, PoissonRatioOutsidePhysicalRangeIsRejected) {
  EXPECT_NE(error_of(write(replace(kMinimalCase, "nu = 0.3", "nu = 0.5"))).find("nu"), std::string::npos);
  EXPECT_NE(error_of(write(replace(kMinimalCase, "nu = 0.3", "nu = -1.0"))).find("nu"), std::string::npos);
}

TEST_F(CaseFile, ClockwiseCornersAreRejected) {
  const std::string msg = error_of(write(replace(kMinimalCase, "[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]",
                                                 "[[0.0, 0.0], [0.0, 1.0], [2.0, 1.0], [2.0, 0.0]]")));
  EXPECT_NE(msg.find("corners"), std::string::npos) << msg;
}

TEST_F(CaseFile, ModalAnalysisWithoutDensityIsRejected) {
  const std::string text =
      replace(replace(kMinimalCase, "rho = 7800.0\n", ""), "type = \"static\"", "type = \"modal\"\nmodes = 3");
  EXPECT_NE(error_of(write(text)).find("rho"), std::string::npos);
}

TEST_F(CaseFile, MissingFileIsAnInputError) { EXPECT_THROW(parse_case_file(dir_ / "does_not_exist.toml"), InputError); }

TEST_F(CaseFile, ConstraintOnAnUnknownSetIsRejectedWhenBuildingTheModel) {
  const CaseSpec spec = parse_case_file(write(replace(kMinimalCase, "set = \"left\"", "set = \"lefft\"")));
  try {
    build_model(spec.model);
    FAIL() << "unknown set must be rejected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lefft"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb
