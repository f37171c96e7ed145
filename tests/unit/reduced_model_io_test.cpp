// Reduced models (reduction/reduced_model, reduction/reduced_model_io): DOF names, validation,
// and the files that let an Ansys or NX export stand in for bladebench's own reduction. A write
// and read round-trips bit for bit; every malformed file is an InputError naming the file and,
// for a line-level fault, the line.
#include "reduction/reduced_model_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include "common/errors.hpp"
#include "reduction/reduced_model.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A 2-DOF model valid as it stands; tests spoil one thing at a time.
ReducedModel two_dof_model() {
  ReducedModel m;
  m.dofs = {{"T1", 0, 0}, {"", -1, 1}};
  m.stiffness.resize(2, 2);
  m.stiffness << 2.0, -1.0, -1.0, 3.0;
  m.mass.resize(2, 2);
  m.mass << 1.0, 0.1, 0.1, 1.0;
  return m;
}

// A random model with full-precision entries: K = B^T B singular (one rigid-body-like mode), M SPD.
ReducedModel random_model(int n) {
  std::mt19937 gen(20260421);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd b = Eigen::MatrixXd::NullaryExpr(n - 1, n, [&] { return u(gen); });
  // Columns 0 and 1 of B never overlap, so K(0, 1) is an exact zero the sparse file leaves out.
  for (int r = 0; r < n - 1; ++r) b(r, r % 2) = 0.0;
  const Eigen::MatrixXd c = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return u(gen); });
  ReducedModel m;
  m.stiffness = 1.0e7 * b.transpose() * b;
  m.mass = c.transpose() * c + Eigen::MatrixXd::Identity(n, n);
  m.stiffness = 0.5 * (m.stiffness + m.stiffness.transpose()).eval();
  m.mass = 0.5 * (m.mass + m.mass.transpose()).eval();
  const char* labels[] = {"T1", "T2", "root.7"};
  for (int i = 0; i < n - 3; ++i) m.dofs.push_back({labels[i / 3 % 3], i % 3, 0});
  for (int k = 1; k <= 3; ++k) m.dofs.push_back({"", -1, k});
  return m;
}

TEST(ReducedModel, DofNamesRoundTrip) {
  for (const ReducedDof& d : {ReducedDof{"T2", 0, 0}, ReducedDof{"root.7", 2, 0}, ReducedDof{"", -1, 3}})
    EXPECT_EQ(ReducedDof::parse(d.name()), d) << d.name();
  EXPECT_EQ((ReducedDof{"T2", 0, 0}.name()), "T2.x");
  EXPECT_EQ((ReducedDof{"", -1, 3}.name()), "mode 3");
  for (const char* bad : {"T2.w", "T2", ".x", "T 2.x", "mode 0", "mode -1", "mode", "mode 3x", "mode  3", "Mode 3"})
    EXPECT_FALSE(ReducedDof::parse(bad)) << bad;
}

TEST(ReducedModel, IndexOfFindsNodalDofsOnly) {
  ReducedModel m = random_model(9);
  EXPECT_EQ(m.index_of("T2", 1), 4);
  EXPECT_EQ(m.index_of("T2", 2), 5);
  EXPECT_FALSE(m.index_of("T3", 0));
  EXPECT_FALSE(m.index_of("", -1));  // a modal coordinate is not a node direction
}

TEST(ReducedModel, ValidationRejectsRepeatedNamesAndBadMatrices) {
  EXPECT_NO_THROW(validate_reduced_model(random_model(9), "rom"));
  ReducedModel repeated = two_dof_model();
  repeated.dofs[1] = repeated.dofs[0];
  EXPECT_TRUE(contains(input_error([&] { validate_reduced_model(repeated, "rom"); }), "'T1.x' appears twice"));
  ReducedModel small = two_dof_model();
  small.mass = Eigen::MatrixXd::Identity(3, 3);
  const std::string size_message = input_error([&] { validate_reduced_model(small, "rom"); });
  EXPECT_EQ(size_message.rfind("rom: ", 0), 0u) << size_message;
  EXPECT_TRUE(contains(size_message, "M is 3 x 3 but there are 2 DOFs")) << size_message;
  ReducedModel nan = two_dof_model();
  nan.stiffness(1, 1) = std::nan("");
  EXPECT_TRUE(contains(input_error([&] { validate_reduced_model(nan, "rom"); }), "not finite"));
}

class ReducedModelIo : public test::TempFolderTest {
 protected:
  // A sidecar for the 2-DOF model naming the matrix files K.<ext> and M.<ext>.
  std::filesystem::path sidecar(const std::string& format, const std::string& ext,
                                const std::string& dofs = R"(["T1.x", "mode 1"])",
                                const std::string& extra = "") const {
    return write(fmt_sidecar(format, ext, dofs, extra), "rom.toml");
  }
  static std::string fmt_sidecar(const std::string& format, const std::string& ext, const std::string& dofs,
                                 const std::string& extra) {
    return "[reduced_model]\nformat = \"" + format + "\"\nstiffness = \"K." + ext + "\"\nmass = \"M." + ext +
           "\"\ndofs = " + dofs + "\n" + extra;
  }
  // The 2-DOF model's M, valid, so tests can spoil K alone.
  void write_good_mass_mtx() const {
    write("%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 1.0\n2 1 0.1\n2 2 1.0\n", "M.mtx");
  }
  // Reads the sidecar and returns the InputError message.
  std::string read_error(const std::filesystem::path& file) const {
    return input_error([&] { read_reduced_model(file); });
  }
};

TEST_F(ReducedModelIo, WriteThenReadIsBitwiseIdentical) {
  const ReducedModel model = random_model(12);
  const std::filesystem::path file = dir_ / "blade_rom.toml";
  write_reduced_model(model, file);
  std::ifstream k_file(dir_ / "blade_rom.K.mtx");
  std::string header;
  std::getline(k_file, header);
  EXPECT_EQ(header, "%%MatrixMarket matrix coordinate real symmetric");
  EXPECT_TRUE(std::filesystem::exists(dir_ / "blade_rom.M.mtx"));
  const ReducedModel back = read_reduced_model(file);
  EXPECT_EQ(back.dofs, model.dofs);
  ASSERT_EQ(back.stiffness.rows(), model.stiffness.rows());
  ASSERT_EQ(back.mass.rows(), model.mass.rows());
  // Bitwise, not approximately: %.17g and a correctly rounded parse reproduce every double.
  EXPECT_EQ(std::memcmp(back.stiffness.data(), model.stiffness.data(), sizeof(double) * model.stiffness.size()), 0);
  EXPECT_EQ(std::memcmp(back.mass.data(), model.mass.data(), sizeof(double) * model.mass.size()), 0);
  EXPECT_EQ(back.recovery.size(), 0);
}

TEST_F(ReducedModelIo, ReadsDenseCsvWithComments) {
  write("# K of the 2-DOF model [N/m]\n2, -1   # first row\n\n-1 ,3\n", "K.csv");
  write("1.0,0.1\r\n0.1,1.0\r\n", "M.csv");
  const ReducedModel m = read_reduced_model(sidecar("csv", "csv"));
  EXPECT_EQ(m.stiffness, two_dof_model().stiffness);
  EXPECT_EQ(m.mass, two_dof_model().mass);
  EXPECT_EQ(m.dofs, two_dof_model().dofs);
}

TEST_F(ReducedModelIo, ReadsGeneralCoordinateAndArrayMatrixMarket) {
  write("%%MatrixMarket matrix coordinate real general\n% full storage\n2 2 4\n1 1 2\n2 1 -1\n1 2 -1\n2 2 3\n",
        "K.mtx");
  write("%%MatrixMarket matrix array real general\n2 2\n1.0\n0.1\n0.1\n1.0\n", "M.mtx");
  const ReducedModel m = read_reduced_model(sidecar("matrix_market", "mtx"));
  EXPECT_EQ(m.stiffness, two_dof_model().stiffness);
  EXPECT_EQ(m.mass, two_dof_model().mass);
}

TEST_F(ReducedModelIo, RejectsANonSymmetricStiffness) {
  write("%%MatrixMarket matrix coordinate real general\n2 2 4\n1 1 2\n2 1 -1\n1 2 -1.5\n2 2 3\n", "K.mtx");
  write_good_mass_mtx();
  const std::filesystem::path file = sidecar("matrix_market", "mtx");
  const std::string message = read_error(file);
  EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
  EXPECT_TRUE(contains(message, "K is not symmetric")) << message;
}

TEST_F(ReducedModelIo, RejectsAnIndefiniteStiffness) {
  write("%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 1\n2 1 3\n2 2 1\n", "K.mtx");
  write_good_mass_mtx();
  const std::string message = read_error(sidecar("matrix_market", "mtx"));
  EXPECT_TRUE(contains(message, "rom.toml: K is indefinite")) << message;
}

TEST_F(ReducedModelIo, RejectsAMassThatIsNotPositiveDefinite) {
  write("2, -1\n-1, 3\n", "K.csv");
  write("1, 1\n1, 1\n", "M.csv");  // singular: the two DOFs share one inertia
  const std::string message = read_error(sidecar("csv", "csv"));
  EXPECT_TRUE(contains(message, "rom.toml: M is not positive definite")) << message;
}

TEST_F(ReducedModelIo, RejectsAMatrixWhoseSizeDisagreesWithTheDofs) {
  write("%%MatrixMarket matrix coordinate real symmetric\n% comment\n3 3 1\n1 1 1\n", "K.mtx");
  write_good_mass_mtx();
  const std::string message = read_error(sidecar("matrix_market", "mtx"));
  EXPECT_TRUE(contains(message, "K.mtx:3: matrix is 3 x 3 but the sidecar names 2 DOFs")) << message;
}

TEST_F(ReducedModelIo, RejectsABadMatrixMarketHeader) {
  for (const char* header :
       {"%%MatrixMarket matrix coordinate complex general", "%%MatrixMarket matrix array real symmetric", "2 2 3",
        "%%MatrixMarket matrix coordinate real hermitian"}) {
    write(std::string(header) + "\n2 2 3\n1 1 2\n2 1 -1\n2 2 3\n", "K.mtx");
    write_good_mass_mtx();
    const std::string message = read_error(sidecar("matrix_market", "mtx"));
    EXPECT_TRUE(contains(message, "K.mtx:1: unsupported Matrix Market header")) << message;
  }
}

TEST_F(ReducedModelIo, RefusesMoreDofsThanADenseMatrixMayHoldBeforeAllocating) {
  // 20001 names in a small file would ask for two dense 20001 x 20001 matrices (6.4 GB).
  std::string dofs = "[";
  for (int i = 1; i <= 20001; ++i) dofs += "\"mode " + std::to_string(i) + "\",";
  write_good_mass_mtx();
  write("%%MatrixMarket matrix coordinate real symmetric\n20001 20001 1\n1 1 1.0\n", "K.mtx");
  const std::string message = read_error(sidecar("matrix_market", "mtx", dofs + "]"));
  EXPECT_TRUE(contains(message, "rom.toml:5: 'reduced_model.dofs': names 20001 DOFs")) << message;
  EXPECT_TRUE(contains(message, "at most 10000")) << message;
}

TEST_F(ReducedModelIo, RejectsAnEntryIndexOutOfRange) {
  write("%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2\n3 1 -1\n2 2 3\n", "K.mtx");
  write_good_mass_mtx();
  const std::string message = read_error(sidecar("matrix_market", "mtx"));
  EXPECT_TRUE(contains(message, "K.mtx:4: entry (3, 1) is out of range")) << message;
}

TEST_F(ReducedModelIo, RejectsAnUpperTriangleEntryInASymmetricFile) {
  write("%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2\n1 2 -1\n2 2 3\n", "K.mtx");
  write_good_mass_mtx();
  EXPECT_TRUE(contains(read_error(sidecar("matrix_market", "mtx")), "K.mtx:4: entry (1, 2) is above the diagonal"));
}

TEST_F(ReducedModelIo, RejectsNaNAndMalformedNumbersWithTheirLine) {
  write("%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2\n2 1 -1\n2 2 nan\n", "K.mtx");
  write_good_mass_mtx();
  const std::string message = read_error(sidecar("matrix_market", "mtx"));
  EXPECT_TRUE(contains(message, "K.mtx:5: value 'nan' is not finite")) << message;

  write("2, -1\n-1, 3\n", "K.csv");
  write("1.0, 0.1\n# second row\n0.1, 1.O\n", "M.csv");  // letter O for zero
  const std::string csv = read_error(sidecar("csv", "csv"));
  EXPECT_TRUE(contains(csv, "M.csv:3: column 2 '1.O' is not a number")) << csv;
}

TEST_F(ReducedModelIo, RejectsTooFewOrTooManyEntries) {
  write_good_mass_mtx();
  write("%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2\n2 2 3\n", "K.mtx");
  const std::string few = read_error(sidecar("matrix_market", "mtx"));
  EXPECT_TRUE(contains(few, "K.mtx:4: found 2 entries, the size line announces 3")) << few;
  write("%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 2\n2 2 3\n2 1 -1\n", "K.mtx");
  const std::string many = read_error(sidecar("matrix_market", "mtx"));
  EXPECT_TRUE(contains(many, "K.mtx:5: more entries than the 2")) << many;

  write("2, -1\n-1, 3\n", "K.csv");
  write("1.0, 0.1\n0.1\n", "M.csv");
  const std::string short_row = read_error(sidecar("csv", "csv"));
  EXPECT_TRUE(contains(short_row, "M.csv:2: found 1 values in the row, expected 2")) << short_row;
  write("1.0, 0.1\n0.1, 1.0\n0, 0\n", "M.csv");
  const std::string extra_row = read_error(sidecar("csv", "csv"));
  EXPECT_TRUE(contains(extra_row, "M.csv:3: more than 2 rows")) << extra_row;
}

TEST_F(ReducedModelIo, SidecarErrorsNameTheSidecarAndTheField) {
  write("2, -1\n-1, 3\n", "K.csv");
  write("1.0, 0.1\n0.1, 1.0\n", "M.csv");
  const std::string unknown = read_error(sidecar("csv", "csv", R"(["T1.x", "mode 1"])", "damping = 0.01\n"));
  EXPECT_TRUE(contains(unknown, "rom.toml:6: 'reduced_model.damping': unknown key")) << unknown;
  const std::string bad_dof = read_error(sidecar("csv", "csv", R"(["T1.x", "mode one"])"));
  EXPECT_TRUE(contains(bad_dof, "'reduced_model.dofs': entry 2 'mode one' is not a DOF name")) << bad_dof;
  const std::string format = read_error(sidecar("hdf5", "csv"));
  EXPECT_TRUE(contains(format, "'reduced_model.format': unknown value 'hdf5'")) << format;
  const std::string repeated = read_error(sidecar("csv", "csv", R"(["T1.x", "T1.x"])"));
  EXPECT_TRUE(contains(repeated, "rom.toml: DOF 'T1.x' appears twice")) << repeated;
  std::filesystem::remove(dir_ / "M.csv");
  const std::string missing = read_error(sidecar("csv", "csv"));
  EXPECT_TRUE(contains(missing, "rom.toml:4: 'reduced_model.mass': matrix file")) << missing;
}

}  // namespace
}  // namespace bb
