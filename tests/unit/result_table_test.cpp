// Result tables with text labels (results/table, report/writers, checks): the labels follow the
// numeric columns in the CSV, quoted where needed; checks compare numbers only and may be
// restricted to some reference rows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "checks/checks.hpp"
#include "common/errors.hpp"
#include "report/writers.hpp"
#include "results/table.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

ResultTable labelled_frequencies() {
  ResultTable t;
  t.name = "frequencies";
  t.columns = {"mode", "frequency_hz"};
  t.values.resize(3, 2);
  t.values << 1, 100.5, 2, 101.0, 3, 250.25;
  t.add_text_column("pair", {"IP", "OOP", "-"});
  t.add_text_column("type", {"flexure-x", "flexure-x", "torsion, \"twist\""});
  return t;
}

class LabelledTable : public test::TempFolderTest {};

TEST_F(LabelledTable, CsvWritesTextColumnsAfterTheNumericOnesAndQuotesWhereNeeded) {
  write_table_csv(labelled_frequencies(), dir_ / "frequencies.csv");
  std::ifstream in(dir_ / "frequencies.csv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "mode,frequency_hz,pair,type\n"
            "1,100.5,IP,flexure-x\n"
            "2,101,OOP,flexure-x\n"
            "3,250.25,-,\"torsion, \"\"twist\"\"\"\n");
}

TEST(LabelledTableColumns, TextColumnNeedsOneValuePerRow) {
  ResultTable t = labelled_frequencies();
  EXPECT_THROW(t.add_text_column("extra", {"a"}), std::invalid_argument);
}

TEST_F(LabelledTable, ChecksCompareOnlyTheListedKeysAndRejectTextColumns) {
  const fs::path reference = dir_ / "reference.csv";
  std::ofstream(reference) << "# test reference\nmode,frequency_hz,pair\n1,100.0,1\n2,100.0,1\n3,250.0,2\n";
  ResultTables tables;
  tables.emplace("frequencies", labelled_frequencies());
  CheckSpec check;
  check.name = "first pair";
  check.result = "frequencies";
  check.reference = reference;
  check.key = "mode";
  check.compare = {{"frequency_hz", "frequency_hz"}};
  check.rel_tol = 0.006;
  check.keys = {1, 2};
  const auto entries = evaluate_check(check, tables);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].key, 1);
  EXPECT_EQ(entries[1].key, 2);
  EXPECT_EQ(entries[1].column, "frequency_hz");
  EXPECT_TRUE(entries[0].pass);   // 0.5 %
  EXPECT_FALSE(entries[1].pass);  // 1 %

  check.keys = {4};
  EXPECT_THROW(evaluate_check(check, tables), InputError);  // not a row of the reference
  check.keys = {};
  check.compare = {{"pair", "pair"}};
  try {
    evaluate_check(check, tables);
    FAIL() << "a text column was compared";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("text labels"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb
