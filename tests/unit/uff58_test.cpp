// Universal File dataset 58 (identify/uff58): round trip of an FRF, units from the records, and a
// refusal naming the record for every malformed part.
#include "identify/uff58.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "identify/measured_data.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "bladebench_uff58_test";
  fs::create_directories(dir);
  return dir / name;
}

// A hand-written file in the layout of the format's description: complex single precision, even
// spacing, receptance in mm/N (labels), 4 points from 100 Hz by 10 Hz, and a dataset 151 to skip.
std::string even_mm_per_n() {
  return "    -1\n   151\nmodel\n    -1\n"
         "    -1\n    58\nFRF T2 / F\nrig 3\n24-Nov-26\nNONE\nNONE\n"
         "    4         1    1         0 NONE               2   1 NONE               7   3\n"
         "         5         4         1  1.00000E+02  1.00000E+01  0.00000E+00\n"
         "        18    0    0    0 Frequency            Hz                  \n"
         "         8    1    0    0 Displacement         mm                  \n"
         "        13    0    1    0 Force                N                   \n"
         "         0    0    0    0 NONE                 NONE                \n"
         "  1.00000E-03  0.00000E+00  0.00000E+00 -2.00000E-03 -1.00000E-03  0.00000E+00\n"
         "  5.00000E-04  5.00000E-04\n"
         "    -1\n";
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

TEST(Uff58, ReadsUnitsFromTheRecordsAndConvertsToSi) {
  const fs::path file = scratch("even.uff");
  write(file, even_mm_per_n());
  const MeasuredData d = read_measured_data(file, DataKind::frf);
  ASSERT_EQ(d.rows(), 4);
  EXPECT_EQ(d.column("frequency")[3], 130.0);
  EXPECT_EQ(d.units.at("amplitude").dimension, Dimension::compliance);
  EXPECT_NEAR(d.column("amplitude")[0], 1e-6, 1e-18);  // 1e-3 mm/N
  EXPECT_NEAR(d.column("amplitude")[1], 2e-6, 1e-18);
  EXPECT_NEAR(d.column("phase")[1], -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(d.column("amplitude")[3], std::hypot(5e-7, 5e-7), 1e-18);
  const auto f = read_uff58(file);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].function_type, 4);
  EXPECT_EQ(f[0].response_node, 2);
  EXPECT_EQ(f[0].reference_direction, 3);
}

// A rig's several levels in one file: dataset 58 number k is the k-th curve, the others skipped.
TEST(Uff58, EachDatasetOfAFileIsItsOwnCurve) {
  const fs::path file = scratch("two_levels.uff");
  std::string second = even_mm_per_n().substr(even_mm_per_n().find("    -1\n    58"));
  const std::string first_value = "  1.00000E-03  0.00000E+00";
  second.replace(second.find(first_value), first_value.size(), "  4.00000E-03  0.00000E+00");
  write(file, even_mm_per_n() + second);
  const std::vector<Uff58Function> functions = read_uff58(file);
  ASSERT_EQ(functions.size(), 2u);
  const MeasuredData one = uff58_frf(functions[0], file, 1), two = uff58_frf(functions[1], file, 2);
  EXPECT_NEAR(one.column("amplitude")[0], 1e-6, 1e-18);
  EXPECT_NEAR(two.column("amplitude")[0], 4e-6, 1e-18);
  EXPECT_EQ(two.column("amplitude")[1], one.column("amplitude")[1]);
  EXPECT_GT(two.lines[0], one.lines[0]) << "rows point into their own dataset";
}

TEST(Uff58, WrittenFrfReadsBackToThirteenDigits) {
  MeasuredData d;
  d.kind = DataKind::frf;
  const Eigen::Index n = 50;
  Eigen::VectorXd f(n), a(n), p(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    f[i] = 140.0 + 0.5 * static_cast<double>(i);
    a[i] = 1e-6 / std::abs(std::complex<double>(1.0 - std::pow(f[i] / 175.0, 2), 0.02 * f[i] / 175.0));
    p[i] = -std::atan2(0.02 * f[i] / 175.0, 1.0 - std::pow(f[i] / 175.0, 2));
  }
  d.columns = {{"frequency", f}, {"amplitude", a}, {"phase", p}};
  d.units = {{"frequency", *parse_unit("Hz")}, {"amplitude", *parse_unit("m/N")}, {"phase", *parse_unit("rad")}};
  const fs::path file = scratch("round_trip.unv");
  write_uff58_frf(d, file, "round trip");
  const MeasuredData back = read_measured_data(file, DataKind::frf);
  ASSERT_EQ(back.rows(), n);
  EXPECT_EQ(back.units.at("amplitude").dimension, Dimension::compliance);
  for (Eigen::Index i = 0; i < n; ++i) {
    EXPECT_NEAR(back.column("frequency")[i], f[i], 1e-9 * f[i]);
    EXPECT_NEAR(back.column("amplitude")[i], a[i], 1e-12 * a[i]);
    EXPECT_NEAR(back.column("phase")[i], p[i], 1e-11);
  }
}

// A rig's stepped sine with a force that drifts, as two channels: the force record (reference)
// and the displacement record. Paired, they give each point's force, its phase, and the
// response's phase to the force, as a CSV file with force columns would; the force record alone is
// not an FRF, and two records at other frequencies are refused.
TEST(Uff58, AForceRecordAndAResponseRecordGiveAForcePerPoint) {
  MeasuredData d;
  d.kind = DataKind::frf;
  const Eigen::Index n = 20;
  Eigen::VectorXd f(n), a(n), p(n), force(n), force_phase(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    f[i] = 80.0 - 0.05 * static_cast<double>(i);  // stepped down
    force[i] = 0.1 * (1.0 + 0.25 * std::sin(0.7 * static_cast<double>(i)));
    force_phase[i] = 0.3 * std::cos(static_cast<double>(i));
    a[i] = 1e-5 * force[i] / (1.0 + 0.01 * static_cast<double>(i));
    p[i] = -0.1 * static_cast<double>(i);
  }
  d.columns = {{"frequency", f}, {"amplitude", a}, {"phase", p}, {"force", force}, {"force_phase", force_phase}};
  d.units = {{"frequency", *parse_unit("Hz")},
             {"amplitude", *parse_unit("m")},
             {"phase", *parse_unit("rad")},
             {"force", *parse_unit("N")},
             {"force_phase", *parse_unit("rad")}};
  const fs::path file = scratch("two_channels.uff");
  write_uff58_frf(d, file, "drifting force");
  const std::vector<Uff58Function> records = read_uff58(file);
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].ordinate_unit.dimension, Dimension::force);
  const MeasuredData back = uff58_response_with_force(records[1], 2, records[0], 1, file);
  ASSERT_EQ(back.rows(), n);
  for (Eigen::Index i = 0; i < n; ++i) {
    EXPECT_NEAR(back.column("frequency")[i], f[i], 1e-9 * f[i]);
    EXPECT_NEAR(back.column("amplitude")[i], a[i], 1e-12 * a[i]);
    EXPECT_NEAR(back.column("force")[i], force[i], 1e-12 * force[i]);
    EXPECT_NEAR(back.column("force_phase")[i], force_phase[i], 1e-11);
    EXPECT_NEAR(back.column("phase")[i], p[i], 1e-11) << "the response's phase to the force";
  }
  EXPECT_THROW((void)uff58_frf(records[0], file, 1), InputError);
  Uff58Function shifted = records[0];
  shifted.abscissa[3] += 0.01;
  try {
    (void)uff58_response_with_force(records[1], 2, shifted, 1, file);
    ADD_FAILURE() << "records at other frequencies were paired";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dataset 58 #1, record 12, value 4"), std::string::npos) << e.what();
  }
}

// An accelerance (specific data type 12, no unit label: SI) reads as the receptance it implies:
// each value divided by w^2 at its own frequency, the phase moved by -180 degrees.
TEST(Uff58, AnAccelerometersFrfReadsAsTheReceptanceItImplies) {
  std::string text = even_mm_per_n();
  const std::string from = "         8    1    0    0 Displacement         mm";
  text.replace(text.find(from), from.size(), "        12    0    0    0 Acceleration         NONE");
  const fs::path file = scratch("accelerance.uff");
  write(file, text);
  const MeasuredData d = read_measured_data(file, DataKind::frf);
  EXPECT_EQ(d.derivative, 2);
  EXPECT_EQ(d.units.at("amplitude").dimension, Dimension::compliance);
  const double raw[] = {1e-3, 2e-3, 1e-3, std::hypot(5e-4, 5e-4)};  // |value| in m/s^2/N
  const double phase[] = {0.0, -std::numbers::pi / 2, std::numbers::pi, std::numbers::pi / 4};
  for (Eigen::Index i = 0; i < 4; ++i) {
    const double w = 2 * std::numbers::pi * (100.0 + 10.0 * static_cast<double>(i));
    EXPECT_NEAR(d.column("amplitude")[i], raw[i] / (w * w), 1e-6 * raw[i] / (w * w)) << i;
    EXPECT_NEAR(std::remainder(d.column("phase")[i] - (phase[i] - std::numbers::pi), 2 * std::numbers::pi), 0.0, 1e-6)
        << i;
  }
}

// Each malformation of the even_mm_per_n file, and the words its message must contain.
TEST(Uff58, MalformedFilesNameTheRecord) {
  const std::string good = even_mm_per_n();
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {replace("         5         4         1", "         3         4         1"), "record 7: ordinate data type"},
      {replace("         5         4         1", "         5         5         1"),
       "record 12: 8 numbers where record 7 announces 5 complex values"},
      {replace("  5.00000E-04  5.00000E-04\n", "  5.00000E-04  nan\n"), "record 12: value 'nan'"},
      {replace("         8    1    0    0 Displacement         mm",
               "        15    0    0    0 Pressure             NONE"),
       "record 9: the ordinate is not a displacement, velocity, acceleration or force (specific data type 15"},
      {replace("Frequency            Hz", "Frequency            furlong"), "record 8: unit label 'furlong'"},
      {replace("    58\nFRF", "   58b\nFRF"), "binary dataset 58b"},
      {replace("    4         1    1", "    x         1    1"), "record 6: function type"},
      {"    -1\n   151\nmodel\n    -1\n", "no dataset 58"},
  };
  for (const auto& [text, expect] : cases) {
    const fs::path file = scratch("bad.uff");
    write(file, text);
    try {
      read_measured_data(file, DataKind::frf);
      ADD_FAILURE() << "accepted; expected: " << expect;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    }
  }
  const fs::path file = scratch("peaks.uff");
  write(file, good);
  EXPECT_THROW(read_measured_data(file, DataKind::peaks), InputError);
}

}  // namespace
}  // namespace bb
