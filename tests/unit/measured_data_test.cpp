// Measured data (identify/measured_data): files of each kind are read into SI with the header's
// units, and every malformed file is refused with a message naming the file, line and column.
#include "identify/measured_data.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
constexpr double pi = std::numbers::pi;

// The message of the InputError that reading `file` throws ("" and a test failure if none).
std::string refusal(const fs::path& file, DataKind kind) {
  try {
    read_measured_data(file, kind);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << file << " was read without complaint";
  return "";
}

void expect_contains(const std::string& message, std::initializer_list<std::string> parts) {
  for (const auto& part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(MeasuredDataUnits, KnownSymbolsConvertToSiWithFrequenciesInHertz) {
  const auto expect_unit = [](const char* symbol, Dimension dim, double to_si) {
    const auto unit = parse_unit(symbol);
    ASSERT_TRUE(unit.has_value()) << symbol;
    EXPECT_EQ(unit->symbol, symbol);
    EXPECT_EQ(unit->dimension, dim) << symbol;
    EXPECT_NEAR(unit->to_si, to_si, 1e-15 * to_si) << symbol;
  };
  expect_unit("m", Dimension::length, 1.0);
  expect_unit("mm", Dimension::length, 1e-3);
  expect_unit("um", Dimension::length, 1e-6);
  expect_unit("\xC2\xB5m", Dimension::length, 1e-6);  // micro sign
  expect_unit("\xCE\xBCm", Dimension::length, 1e-6);  // Greek mu
  expect_unit("nm", Dimension::length, 1e-9);
  expect_unit("kN", Dimension::force, 1e3);
  expect_unit("mN", Dimension::force, 1e-3);
  expect_unit("Hz", Dimension::frequency, 1.0);
  expect_unit("kHz", Dimension::frequency, 1e3);
  expect_unit("rad/s", Dimension::frequency, 1.0 / (2.0 * pi));
  expect_unit("rpm", Dimension::frequency, 1.0 / 60.0);
  expect_unit("deg", Dimension::angle, pi / 180.0);
  expect_unit("rad", Dimension::angle, 1.0);
  expect_unit("um/N", Dimension::compliance, 1e-6);
  expect_unit("\xC2\xB5m/N", Dimension::compliance, 1e-6);
  expect_unit("nm/N", Dimension::compliance, 1e-9);
  expect_unit("N/mm", Dimension::stiffness, 1e3);
  expect_unit("N/um", Dimension::stiffness, 1e6);
  expect_unit("ms", Dimension::time, 1e-3);
  expect_unit("-", Dimension::dimensionless, 1.0);
  expect_unit("1", Dimension::dimensionless, 1.0);
  expect_unit("mm/s", Dimension::velocity, 1e-3);
  expect_unit("\xC2\xB5m/s", Dimension::velocity, 1e-6);
  expect_unit("m/s^2", Dimension::acceleration, 1.0);
  expect_unit("g", Dimension::acceleration, 9.80665);
  expect_unit("mm/s/N", Dimension::mobility, 1e-3);
  expect_unit("g/N", Dimension::accelerance, 9.80665);
  expect_unit("m/s^2/N", Dimension::accelerance, 1.0);
}

TEST(MeasuredDataUnits, UnknownSymbolsAreRefused) {
  for (const char* symbol : {"", "um/n", "hz", "Um", "furlong", "ft/s", "m/s2", "G", "N m"})
    EXPECT_FALSE(parse_unit(symbol)) << symbol;
}

TEST(MeasuredDataUnits, ColumnSuffixesGiveTheDimensionLongestFirst) {
  EXPECT_EQ(column_dimension("frequency_hz"), Dimension::frequency);
  EXPECT_EQ(column_dimension("T2.x_amp_m"), Dimension::length);
  EXPECT_EQ(column_dimension("relative_tangential_m"), Dimension::length);
  EXPECT_EQ(column_dimension("oop_amp_per_n"), Dimension::compliance);
  EXPECT_EQ(column_dimension("tip_m_per_n"), Dimension::compliance);
  EXPECT_EQ(column_dimension("tangential_force_n"), Dimension::force);
  EXPECT_EQ(column_dimension("fe_n"), Dimension::force);
  EXPECT_EQ(column_dimension("stick_slope_n_per_m"), Dimension::stiffness);
  EXPECT_EQ(column_dimension("phase_deg"), Dimension::angle);
  EXPECT_EQ(column_dimension("phase_rad"), Dimension::angle);
  EXPECT_EQ(column_dimension("time_s"), Dimension::time);
  EXPECT_FALSE(column_dimension("label"));
  EXPECT_FALSE(column_dimension("converged"));
  EXPECT_DOUBLE_EQ(column_to_si("phase_deg"), pi / 180.0);
  EXPECT_EQ(column_to_si("phase_rad"), 1.0);
  EXPECT_EQ(column_to_si("oop_amp_per_n"), 1.0);
  EXPECT_STREQ(dimension_name(Dimension::compliance), "compliance");
  EXPECT_STREQ(data_kind_name(DataKind::hysteresis), "hysteresis");
}

using MeasuredDataFile = test::TempFolderTest;

TEST_F(MeasuredDataFile, FrfIsReadInSiWhateverTheColumnOrderCommentsAndBlankLines) {
  const auto file = write(
      "# rig: shaker table 2, 2026-11-20\n"
      "\n"
      "  phase [deg] ,amplitude [um/N],frequency [rad/s], amplitude_sigma [nm/N]\r\n"
      "-90, 2.5, 628.3185307179587, 50\r\n"
      "# a comment between rows\n"
      "   \n"
      "-180,0.5e1 ,1256.6370614359173,+100\n",
      "rig.csv");
  const MeasuredData d = read_measured_data(file, DataKind::frf);
  EXPECT_EQ(d.file, file);
  EXPECT_EQ(d.kind, DataKind::frf);
  ASSERT_EQ(d.rows(), 2);
  EXPECT_EQ(d.lines, (std::vector<int>{4, 7}));
  EXPECT_EQ(d.where(1), file.string() + ":7");
  EXPECT_NEAR(d.column("frequency")(0), 100.0, 1e-12);
  EXPECT_NEAR(d.column("frequency")(1), 200.0, 1e-12);
  EXPECT_DOUBLE_EQ(d.column("amplitude")(0), 2.5e-6);
  EXPECT_DOUBLE_EQ(d.column("amplitude")(1), 5e-6);
  EXPECT_DOUBLE_EQ(d.column("phase")(0), -pi / 2.0);
  EXPECT_DOUBLE_EQ(d.column("phase")(1), -pi);
  EXPECT_DOUBLE_EQ(d.column("amplitude_sigma")(1), 1e-7);
  EXPECT_FALSE(d.has("phase_sigma"));
  EXPECT_THROW(d.column("phase_sigma"), std::out_of_range);
  EXPECT_EQ(d.units.at("amplitude").symbol, "um/N");
  EXPECT_EQ(d.units.at("amplitude").dimension, Dimension::compliance);
  EXPECT_EQ(d.units.at("frequency").symbol, "rad/s");
}

TEST_F(MeasuredDataFile, PeaksAreReadWithForcesInNewtonsAndFrequenciesInHertz) {
  const auto file = write(
      "frequency [kHz], force [kN], amplitude [\xC2\xB5m], frequency_sigma [Hz]\n"
      "0.3124, 0.001, 18.2, 0.5\n"
      "0.3111, 0.002, 29.5, 0.5\n",
      "peaks.csv");
  const MeasuredData d = read_measured_data(file, DataKind::peaks);
  ASSERT_EQ(d.rows(), 2);
  EXPECT_DOUBLE_EQ(d.column("force")(0), 1.0);
  EXPECT_DOUBLE_EQ(d.column("force")(1), 2.0);
  EXPECT_DOUBLE_EQ(d.column("frequency")(0), 312.4);
  EXPECT_DOUBLE_EQ(d.column("amplitude")(1), 29.5e-6);
  EXPECT_DOUBLE_EQ(d.column("frequency_sigma")(1), 0.5);
  EXPECT_EQ(d.units.at("amplitude").dimension, Dimension::length);
}

// A rig's accelerometer and velocity transducer: x e^{i w t} with |x| = 2.5 um/N at -30 deg is
// an accelerance w^2 |x| at 150 deg and a mobility w |x| at 60 deg; both read back as that
// compliance, each row through its own frequency, the sigma alike.
TEST_F(MeasuredDataFile, VelocityAndAccelerationAreReadAsTheDisplacementTheyImply) {
  const double x = 2.5e-6, phase = -30.0;
  const double f[] = {80.0, 120.0};
  std::string acceleration = "frequency [Hz], amplitude [g/N], phase [deg], amplitude_sigma [m/s^2/N]\n";
  std::string velocity = "frequency [Hz], amplitude [mm/s/N], phase [deg]\n";
  for (double hz : f) {
    const double w = 2.0 * pi * hz;
    acceleration +=
        fmt::format("{:.17g}, {:.17g}, {:.17g}, {:.17g}\n", hz, w * w * x / 9.80665, phase + 180.0, 0.1 * w * w * x);
    velocity += fmt::format("{:.17g}, {:.17g}, {:.17g}\n", hz, w * x * 1e3, phase + 90.0);
  }
  for (const auto& [text, derivative] : {std::pair{acceleration, 2}, std::pair{velocity, 1}}) {
    const MeasuredData d = read_measured_data(write(text, fmt::format("d{}.csv", derivative)), DataKind::frf);
    EXPECT_EQ(d.derivative, derivative);
    EXPECT_EQ(d.units.at("amplitude").dimension, Dimension::compliance);
    for (Eigen::Index r = 0; r < 2; ++r) {
      EXPECT_NEAR(d.column("amplitude")(r), x, 1e-15 * x) << derivative;
      EXPECT_NEAR(d.column("phase")(r), phase * pi / 180.0, 1e-14) << derivative;
      if (d.has("amplitude_sigma")) {
        EXPECT_NEAR(d.column("amplitude_sigma")(r), 0.1 * x, 1e-15 * x);
      }
    }
  }
  // Peaks of an acceleration in g: each level at its own peak frequency, the phase wrapped.
  const MeasuredData peaks = read_measured_data(write("force [N], frequency [Hz], amplitude [g]\n"
                                                      "10, 100, 2\n"
                                                      "20, 50, 2\n",
                                                      "peaks_g.csv"),
                                                DataKind::peaks);
  EXPECT_EQ(peaks.units.at("amplitude").dimension, Dimension::length);
  EXPECT_NEAR(peaks.column("amplitude")(0), 2 * 9.80665 / std::pow(2 * pi * 100, 2), 1e-18);
  EXPECT_NEAR(peaks.column("amplitude")(1), 4 * peaks.column("amplitude")(0), 1e-18);
  const MeasuredData wrapped = read_measured_data(
      write("frequency [Hz], amplitude [m/s^2], phase [deg]\n10, 1, -170\n20, 1, 180\n", "wrap.csv"), DataKind::frf);
  EXPECT_NEAR(wrapped.column("phase")(0), 10.0 * pi / 180.0, 1e-14);  // -170 - 180 = -350 = 10 deg
  EXPECT_NEAR(wrapped.column("phase")(1), 0.0, 1e-14);
}

// A rig's phase-only curve (no amplitude column): the phases are kept as written until the case
// says what they are of; then an acceleration's phase is moved by -180 degrees like any other.
TEST_F(MeasuredDataFile, PhasesAloneAreReadAndMovedOnlyWhenTheCaseSaysWhatTheyAreOf) {
  const auto file = write("frequency [Hz], phase [deg], phase_sigma [deg]\n80, 150, 1\n90, 120, 1\n", "phase.csv");
  MeasuredData d = read_measured_data(file, DataKind::frf);
  EXPECT_FALSE(d.has("amplitude"));
  EXPECT_EQ(d.derivative, 0);
  EXPECT_NEAR(d.column("phase")(0), 150.0 * pi / 180.0, 1e-14);
  phase_to_displacement(d, 2);
  EXPECT_EQ(d.derivative, 2);
  EXPECT_NEAR(d.column("phase")(0), -30.0 * pi / 180.0, 1e-14);
  EXPECT_NEAR(d.column("phase")(1), -60.0 * pi / 180.0, 1e-14);
  // Neither an amplitude nor a phase: nothing to compare.
  expect_contains(refusal(write("frequency [Hz], force [N]\n80, 1\n", "none.csv"), DataKind::frf),
                  {"none.csv:1: missing column 'amplitude", "or 'phase [<angle unit>]' for a curve of phases alone"});
}

// Frequencies as ratios to a stated natural frequency: held in Hz (their sigma alike), and the
// velocity or acceleration each row converts through is at that frequency.
TEST_F(MeasuredDataFile, FrequencyRatiosAreReadInHertzThroughTheStatedNaturalFrequency) {
  const auto file = write("frequency [-], amplitude [m/s], phase [deg]\n0.5, 1, 0\n1.5, 1, 0\n", "ratio.csv");
  expect_contains(refusal(file, DataKind::frf),
                  {"ratio.csv:1: column 'frequency' holds ratios ('-'): give the natural frequency"});
  const MeasuredData d = read_measured_data(file, DataKind::frf, {.natural_frequency_hz = 100.0});
  EXPECT_TRUE(d.frequency_ratio);
  EXPECT_EQ(d.units.at("frequency").dimension, Dimension::frequency);
  EXPECT_DOUBLE_EQ(d.column("frequency")(0), 50.0);
  EXPECT_DOUBLE_EQ(d.column("frequency")(1), 150.0);
  EXPECT_NEAR(d.column("amplitude")(0), 1.0 / (2.0 * pi * 50.0), 1e-15);
  const MeasuredData peaks = read_measured_data(
      write("force [N], frequency [1], amplitude [m], frequency_sigma [-]\n1, 0.98, 1e-5, 0.01\n", "peaks_ratio.csv"),
      DataKind::peaks, {.natural_frequency_hz = 200.0});
  EXPECT_DOUBLE_EQ(peaks.column("frequency")(0), 196.0);
  EXPECT_DOUBLE_EQ(peaks.column("frequency_sigma")(0), 2.0);
  const MeasuredData hz = read_measured_data(write("frequency [Hz], amplitude [m]\n5, 1\n", "hz.csv"), DataKind::frf,
                                             {.natural_frequency_hz = 100.0});
  EXPECT_FALSE(hz.frequency_ratio);
  EXPECT_DOUBLE_EQ(hz.column("frequency")(0), 5.0);
}

TEST_F(MeasuredDataFile, AnAccelerationWithADisplacementSigmaIsRefused) {
  expect_contains(
      refusal(write("frequency [Hz], amplitude [g], amplitude_sigma [um]\n10, 1, 1\n", "mixed.csv"), DataKind::frf),
      {"mixed.csv:1", "amplitude_sigma", "'um' (length)", "acceleration"});
}

TEST_F(MeasuredDataFile, HysteresisIsReadInTimeOrder) {
  std::string text = "# one loop\nrelative_displacement [mm], tangential_force [kN], force_sigma [N]\n";
  for (int i = 0; i < 8; ++i) text += std::to_string(i % 4 - 2) + ", " + std::to_string(0.01 * (i - 4)) + ", 2\n";
  const MeasuredData d = read_measured_data(write(text, "loop.csv"), DataKind::hysteresis);
  ASSERT_EQ(d.rows(), 8);
  EXPECT_EQ(d.lines.front(), 3);
  EXPECT_EQ(d.lines.back(), 10);
  EXPECT_DOUBLE_EQ(d.column("relative_displacement")(1), -1e-3);
  EXPECT_DOUBLE_EQ(d.column("tangential_force")(0), -40.0);
  EXPECT_DOUBLE_EQ(d.column("force_sigma")(7), 2.0);
}

TEST(MeasuredDataExamples, ExampleFileOfEachKindIsReadable) {
  const fs::path dir = fs::path(BB_SOURCE_DIR) / "tests" / "data" / "measured";
  const MeasuredData frf = read_measured_data(dir / "frf_example.csv", DataKind::frf);
  EXPECT_EQ(frf.rows(), 7);
  EXPECT_DOUBLE_EQ(frf.column("amplitude")(0), 1.2e-6);
  EXPECT_DOUBLE_EQ(frf.column("phase")(6), -174.0 * pi / 180.0);
  EXPECT_EQ(read_measured_data(dir / "peaks_example.csv", DataKind::peaks).rows(), 4);
  EXPECT_EQ(read_measured_data(dir / "hysteresis_example.csv", DataKind::hysteresis).rows(), 9);
}

TEST(MeasuredDataExamples, BadInputFilesAreRefusedForTheirOneProblem) {
  const fs::path dir = fs::path(BB_SOURCE_DIR) / "tests" / "bad_input" / "data";
  expect_contains(refusal(dir / "measured_missing_column.csv", DataKind::frf),
                  {"measured_missing_column.csv:2: missing column 'amplitude [<length, compliance, velocity, "
                   "acceleration, mobility or accelerance unit>]'"});
  expect_contains(refusal(dir / "measured_nan.csv", DataKind::frf),
                  {"measured_nan.csv:5: column 'amplitude': 'nan' is not a finite number"});
  expect_contains(refusal(dir / "measured_unsorted.csv", DataKind::frf),
                  {"measured_unsorted.csv:5: frequency 110 Hz is not above the previous row's 121 Hz"});
  expect_contains(refusal(dir / "measured_duplicate_frequency.csv", DataKind::frf),
                  {"measured_duplicate_frequency.csv:5: frequency 120 Hz is not above the previous row's 120 Hz"});
  expect_contains(refusal(dir / "measured_wrong_unit.csv", DataKind::frf),
                  {"measured_wrong_unit.csv:2: column 'amplitude' has unit 'N' (force); it needs a length, compliance, "
                   "velocity, acceleration, mobility or accelerance unit"});
}

TEST_F(MeasuredDataFile, MissingFileCannotBeOpened) {
  const fs::path file = dir_ / "absent.csv";
  EXPECT_EQ(refusal(file, DataKind::frf), file.string() + ": cannot open (no such file)");
  expect_contains(refusal(dir_, DataKind::frf), {": cannot open (it is a directory)"});
  // A device never ends; a link loop never resolves; a NUL byte would cut a cell: each is refused.
  expect_contains(refusal("/dev/zero", DataKind::frf), {"/dev/zero: cannot open (not a regular file"});
  fs::create_symlink("loop_b.csv", dir_ / "loop_a.csv");
  fs::create_symlink("loop_a.csv", dir_ / "loop_b.csv");
  expect_contains(refusal(dir_ / "loop_a.csv", DataKind::frf), {"loop_a.csv: cannot open ("});
  {
    std::ofstream out(dir_ / "nul.csv", std::ios::binary);
    out << "frequency [Hz], amplitude [um]\n100.0, 1.0\n110.0, 2.";
    out.put('\0');
    out << "5\n";
  }
  expect_contains(refusal(dir_ / "nul.csv", DataKind::frf), {"nul.csv:3: a NUL byte in the file"});
}

TEST_F(MeasuredDataFile, EmptyOrCommentOnlyFileIsRefused) {
  expect_contains(refusal(write("", "empty.csv"), DataKind::frf), {"empty.csv: no header line"});
  expect_contains(refusal(write("# only\n\n# comments\n", "comments.csv"), DataKind::peaks),
                  {"comments.csv: no header line"});
}

TEST_F(MeasuredDataFile, HeaderWithoutRowsIsRefused) {
  expect_contains(refusal(write("# c\nfrequency [Hz], amplitude [m]\n\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: 0 data rows; a frf file needs at least 1"});
}

TEST_F(MeasuredDataFile, HysteresisWithFewerThanEightRowsIsRefused) {
  std::string text = "relative_displacement [um], tangential_force [N]\n";
  for (int i = 0; i < 7; ++i) text += "1, 2\n";
  expect_contains(refusal(write(text, "loop.csv"), DataKind::hysteresis),
                  {"loop.csv:1: 7 data rows; a hysteresis file needs at least 8"});
}

TEST_F(MeasuredDataFile, HeaderCellWithoutUnitOrNameIsRefused) {
  expect_contains(refusal(write("frequency [Hz], amplitude\n1, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:1: column 'amplitude' has no '[unit]'"});
  expect_contains(refusal(write("# c\nfrequency [Hz], amplitude [m,\n1, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: column 'amplitude' has no '[unit]' ('amplitude [m')"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m],\n1, 1,\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:1: header cell '' has no column name"});
}

TEST_F(MeasuredDataFile, UnknownUnitIsRefused) {
  expect_contains(refusal(write("frequency [Hz], amplitude [um/n]\n1, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:1: column 'amplitude': unknown unit 'um/n'",
                   "(known: m mm um nm, N kN mN, Hz kHz rad/s rpm, deg rad, m/N mm/N um/N nm/N",
                   "m/s mm/s um/s, m/s^2 mm/s^2 g, m/s/N mm/s/N, m/s^2/N g/N (u also as the micro sign)"});
}

TEST_F(MeasuredDataFile, UnitOfTheWrongDimensionIsRefused) {
  expect_contains(refusal(write("# c\n\nfrequency [Hz], amplitude [N]\n1, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:3: column 'amplitude' has unit 'N' (force); it needs a length, compliance, velocity, "
                   "acceleration, mobility or accelerance unit"});
  expect_contains(refusal(write("frequency [deg], amplitude [m]\n1, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:1: column 'frequency' has unit 'deg' (angle); it needs a frequency or dimensionless unit"});
  expect_contains(
      refusal(write("relative_displacement [um/N], tangential_force [N]\n1, 1\n", "loop.csv"), DataKind::hysteresis),
      {"loop.csv:1: column 'relative_displacement' has unit 'um/N' (compliance); it needs a length unit"});
}

TEST_F(MeasuredDataFile, SigmaNeedsItsColumnAndItsDimension) {
  expect_contains(
      refusal(write("frequency [Hz], amplitude [um/N], amplitude_sigma [um]\n1, 1, 1\n", "rig.csv"), DataKind::frf),
      {"rig.csv:1: column 'amplitude_sigma' has unit 'um' (length); it needs a compliance unit, like "
       "column 'amplitude'"});
  expect_contains(
      refusal(write("frequency [Hz], amplitude [m], phase_sigma [deg]\n1, 1, 1\n", "rig.csv"), DataKind::frf),
      {"rig.csv:1: column 'phase_sigma' needs the column 'phase'"});
}

TEST_F(MeasuredDataFile, UnknownColumnIsRefusedWithTheColumnsOfTheKind) {
  expect_contains(
      refusal(write("frequency [Hz], amplitud [m]\n1, 1\n", "rig.csv"), DataKind::frf),
      {"rig.csv:1: unknown column 'amplitud'; a frf file has: frequency, amplitude, phase, force, force_phase, "
       "amplitude_sigma, phase_sigma, force_sigma"});
  expect_contains(refusal(write("force [N], frequency [Hz], amplitude [m], phase [deg]\n1, 1, 1, 1\n", "peaks.csv"),
                          DataKind::peaks),
                  {"peaks.csv:1: unknown column 'phase'; a peaks file has: force, frequency, amplitude"});
}

TEST_F(MeasuredDataFile, DuplicatedColumnIsRefused) {
  expect_contains(refusal(write("frequency [Hz], amplitude [m], frequency [rpm]\n1, 1, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:1: column 'frequency' appears twice"});
}

TEST_F(MeasuredDataFile, MissingRequiredColumnIsNamedWithItsUnitAndTheFileColumns) {
  expect_contains(
      refusal(write("# loop\nrelative_displacement [um], force_sigma [N]\n1, 1\n", "loop.csv"), DataKind::hysteresis),
      {"loop.csv:2: missing column 'tangential_force [<force unit>]'; the file has: "
       "relative_displacement, force_sigma"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1, 1\n", "peaks.csv"), DataKind::peaks),
                  {"peaks.csv:1: missing column 'force [<force unit>]'"});
}

TEST_F(MeasuredDataFile, RowWithTooFewOrTooManyCellsIsRefused) {
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1, 1\n\n2\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:4: 1 cells where the header (line 1) has 2"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1, 1, 3\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: 3 cells where the header (line 1) has 2"});
}

TEST_F(MeasuredDataFile, EmptyOrNonNumericCellIsRefused) {
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1,  \n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: column 'amplitude': empty cell"});
  for (const char* text : {"1.2.3", "12abc", "0x10", "abc", "1 2", "--1", "+-1", "5e"})
    expect_contains(
        refusal(write(std::string("# c\nfrequency [Hz], amplitude [m]\n1, 1\n") + text + ", 1\n", "rig.csv"),
                DataKind::frf),
        {"rig.csv:4: column 'frequency': '"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1, 12abc\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: column 'amplitude': '12abc' is not a number"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1, 1e400\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: column 'amplitude': '1e400' is out of range"});
}

TEST_F(MeasuredDataFile, NanAndInfinityAreRefusedExplicitly) {
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-inf", "Infinity"})
    expect_contains(
        refusal(write(std::string("frequency [Hz], phase [deg], amplitude [m]\n1, ") + text + ", 1\n", "rig.csv"),
                DataKind::frf),
        {std::string("rig.csv:2: column 'phase': '") + text + "' is not a finite number"});
}

TEST_F(MeasuredDataFile, NonPositiveAmplitudeOrSigmaIsRefused) {
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n1, 1\n2, 0\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:3: column 'amplitude': '0' must be positive"});
  expect_contains(
      refusal(write("force [N], frequency [Hz], amplitude [m]\n1, 100, -1e-6\n", "peaks.csv"), DataKind::peaks),
      {"peaks.csv:2: column 'amplitude': '-1e-6' must be positive"});
  expect_contains(
      refusal(write("frequency [Hz], amplitude [m], phase [deg], phase_sigma [deg]\n1, 1, -10, -0.5\n", "rig.csv"),
              DataKind::frf),
      {"rig.csv:2: column 'phase_sigma': '-0.5' must be positive"});
}

TEST_F(MeasuredDataFile, FrfFrequenciesMustIncreaseStrictly) {
  expect_contains(
      refusal(write("# c\nfrequency [Hz], amplitude [m]\n100, 1\n120, 1\n# c\n110, 1\n", "rig.csv"), DataKind::frf),
      {"rig.csv:6: frequency 110 Hz is not above the previous row's 120 Hz (rows must follow one stepped sine, up "
       "or down, without repeated frequencies)"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m]\n120, 1\n110, 1\n115, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:4: frequency 115 Hz is not below the previous row's 110 Hz"});
  expect_contains(refusal(write("frequency [rpm], amplitude [m]\n7200, 1\n7200, 1\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:3: frequency 7200 rpm is not above the previous row's 7200 rpm"});
}

TEST_F(MeasuredDataFile, DownSweepWithTheForceOfEachPointIsReadInItsOrder) {
  // A force-controlled rig's stepped sine down in frequency: its force drifts, its force channel
  // has its own phase; the response's phase is read against the force.
  const MeasuredData d = read_measured_data(write("frequency [Hz], amplitude [m/s^2], phase [deg], force [mN], "
                                                  "force_phase [deg]\n"
                                                  "82, 10, 30, 150, 20\n81, 20, -170, 180, 10\n80, 5, 175, 210, -10\n",
                                                  "down.csv"),
                                            DataKind::frf);
  ASSERT_EQ(d.rows(), 3);
  EXPECT_DOUBLE_EQ(d.column("frequency")[0], 82.0);
  EXPECT_DOUBLE_EQ(d.column("frequency")[2], 80.0);
  EXPECT_DOUBLE_EQ(d.column("force")[1], 0.18);
  const double w = 2.0 * std::numbers::pi * 81.0;
  EXPECT_NEAR(d.column("amplitude")[1], 20.0 / (w * w), 1e-15);
  // -170 - 180 (acceleration to displacement) - 10 (the force's phase) = -360 = 0 deg.
  EXPECT_NEAR(d.column("phase")[1], 0.0, 1e-12);
  // 175 - 180 + 10 = 5 deg.
  EXPECT_NEAR(d.column("phase")[2], 5.0 * std::numbers::pi / 180.0, 1e-12);
  expect_contains(
      refusal(write("frequency [Hz], amplitude [m], force_phase [deg]\n1, 1, 0\n", "rig.csv"), DataKind::frf),
      {"rig.csv:1: column 'force_phase' needs the column 'force'"});
  expect_contains(refusal(write("frequency [Hz], amplitude [m], force [N]\n1, 1, 0\n", "rig.csv"), DataKind::frf),
                  {"rig.csv:2: column 'force': '0' must be positive"});
}

TEST_F(MeasuredDataFile, RepeatedForceLevelIsRefusedNamingBothRows) {
  expect_contains(
      refusal(write("force [N], frequency [Hz], amplitude [m]\n1, 300, 1\n2, 299, 2\n\n1, 298, 3\n", "peaks.csv"),
              DataKind::peaks),
      {"peaks.csv:5: column 'force': level 1 N repeats the level of line 2"});
}

}  // namespace
}  // namespace bb
