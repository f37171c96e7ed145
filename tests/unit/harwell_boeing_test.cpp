// Harwell-Boeing reader and DOF maps (reduction/harwell_boeing): fixed-width fields as Fortran cuts
// them, both symmetric storages, and the header checked against the data.
#include "reduction/harwell_boeing.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/errors.hpp"

namespace bb::harwell_boeing_test {
namespace {

namespace fs = std::filesystem;

class HarwellBoeing : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = fs::temp_directory_path() /
            ("bladebench_hb_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
             std::to_string(getpid()));
  }
  void TearDown() override { fs::remove(file_); }
  const fs::path& write(const std::string& text) {
    std::ofstream(file_) << text;
    return file_;
  }
  std::string refusal(const std::string& text, Eigen::Index n) {
    try {
      read_harwell_boeing(write(text), n, "the test names 3 DOFs");
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return "";
  }
  fs::path file_;
};

// The 3 x 3 matrix [[4, -1, 0], [-1, 4, -2], [0, -2, 5]] as RSA (lower triangle by columns).
const std::string kHeader =
    "a 3 x 3 test matrix                                                     TEST    \n"
    "             5             1             1             3             0\n"
    "RSA                        3             3             5             0\n"
    "(4I4)           (5I4)           (2E12.4)            \n";
const std::string kPointers = "   1   3   5   6\n";
const std::string kIndices = "   1   2   2   3   3\n";
// Values that touch (-1.0000E+00 fills its 12 characters after a 1-blank pad) and a D exponent.
const std::string kValues = "  4.0000E+00 -1.0000E+00\n  4.0000D+00 -2.0000E+00\n  5.0000E+00\n";

TEST_F(HarwellBoeing, ReadsFixedWidthFieldsAndMirrorsTheTriangle) {
  const Eigen::MatrixXd a = read_harwell_boeing(write(kHeader + kPointers + kIndices + kValues), 3, "");
  Eigen::Matrix3d expected;
  expected << 4, -1, 0, -1, 4, -2, 0, -2, 5;
  EXPECT_EQ(a, expected);
}

TEST_F(HarwellBoeing, ReadsTouchingValuesAndTheUpperTriangleAlike) {
  // The upper triangle by columns (column 2: rows 1, 2; column 3: rows 2, 3), values with no blank between.
  const std::string header =
      "upper                                                                   UP      \n"
      "             3             1             1             1             0\n"
      "RSA                        3             3             5             0\n"
      "(4I4)           (5I4)           (5E11.4)            \n";
  const Eigen::MatrixXd a = read_harwell_boeing(
      write(header +
            "   1   2   4   6\n   1   1   2   2   3\n 4.0000E+00-1.0000E+00 4.0000E+00-2.0000E+00 5.0000E+00\n"),
      3, "");
  Eigen::Matrix3d expected;
  expected << 4, -1, 0, -1, 4, -2, 0, -2, 5;
  EXPECT_EQ(a, expected);
}

TEST_F(HarwellBoeing, RefusesAHeaderThatDisagreesWithItsData) {
  struct Case {
    std::string text, says;
  };
  std::string wrong_total = kHeader;
  wrong_total.replace(wrong_total.find("             5"), 14, "             6");
  std::string wrong_type = kHeader;
  wrong_type.replace(wrong_type.find("RSA"), 3, "CSA");
  const Case cases[] = {
      {wrong_total + kPointers + kIndices + kValues, "TOTCRD 6 is not"},
      {wrong_type + kPointers + kIndices + kValues, "matrix type 'CSA'"},
      {kHeader + "   1   3   5   7\n" + kIndices + kValues, "do not run from 1 up to NNZERO + 1 = 6"},
      {kHeader + kPointers + "   1   2   2   4   3\n" + kValues, "row index 4 of column 2 is out of 1..3"},
      {kHeader + kPointers + "   1   2   3   2   3\n" + kValues, "repeats or runs backwards"},
      {kHeader + kPointers + kIndices + "  4.0000E+00 -1.0000E+00\n  4.0000E+00\n", "values: field 2 is empty"},
      {kHeader + kPointers + kIndices + "  4.0000E+00 -1.0000E+00\n  4.0000E+00 -2.0000E+00\n",
       "ends inside the values"},
      {kHeader + kPointers + kIndices + kValues + "  1.0\n", "data after the 5 cards"},
      {kHeader + kPointers + "   1   2   2   1   3\n" + kValues, "repeats or runs backwards"},
  };
  for (const Case& c : cases) {
    const std::string message = refusal(c.text, 3);
    EXPECT_NE(message.find(c.says), std::string::npos) << message;
    EXPECT_NE(message.find(file_.string()), std::string::npos) << message;
  }
  EXPECT_NE(refusal(kHeader + kPointers + kIndices + kValues, 4).find("3 x 3, but the test names 3 DOFs"),
            std::string::npos);
}

TEST_F(HarwellBoeing, RefusesAnRsaFileWithBothTrianglesAndAnUnsymmetricRua) {
  const std::string both =
      "both                                                                    BOTH    \n"
      "             3             1             1             1             0\n"
      "RSA                        2             2             3             0\n"
      "(3I4)           (3I4)           (3E12.4)            \n"
      "   1   3   4\n   1   2   1\n  1.0000E+00  2.0000E+00  3.0000E+00\n";
  EXPECT_NE(refusal(both, 2).find("entries on both sides of the diagonal"), std::string::npos);
  std::string rua = both;
  rua.replace(rua.find("RSA"), 3, "RUA");
  EXPECT_NE(refusal(rua, 2).find("the RUA matrix is not symmetric: entries (2, 1) and (1, 2) differ by 1"),
            std::string::npos);
}

TEST_F(HarwellBoeing, ReadsAnsysAndCsvDofMapsAndRefusesRotations) {
  const auto ansys =
      read_dof_map(write(" Matrix Eqn   Node   DOF\n     1   7   UX\n     2   7   UZ\n     3  12   UY\n"));
  ASSERT_EQ(ansys.size(), 3u);
  EXPECT_EQ(ansys[0].name(), "7.x");
  EXPECT_EQ(ansys[1].name(), "7.z");
  EXPECT_EQ(ansys[2].name(), "12.y");
  const auto csv = read_dof_map(write("node,direction\n101,x\n102,UY\n"));
  ASSERT_EQ(csv.size(), 2u);
  EXPECT_EQ(csv[1].name(), "102.y");
  for (const auto& [text, says] :
       {std::pair{" Matrix Eqn Node DOF\n 1 7 ROTX\n", "translations"},
        std::pair{" Matrix Eqn Node DOF\n 2 7 UX\n", "equation 2 where 1 comes next"},
        std::pair{"node,direction\n7,x\n7,x\n", "DOF 7.x is listed twice"}, std::pair{"eqn,node\n1,7\n", "header"}}) {
    try {
      read_dof_map(write(text));
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace bb::harwell_boeing_test
