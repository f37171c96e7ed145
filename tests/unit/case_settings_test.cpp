// Settings from the command line (cases/case_settings): a key replaced or added in its table with
// its TOML type, the value without a source line, keys and tables removed, and every malformed
// setting refused by name.
#include "cases/case_settings.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"

namespace bb {
namespace {

toml::table case_table() {
  return toml::parse(R"(
[analysis]
type = "hbm"
harmonics = 1
time_samples = 256
[analysis.damper]
kt = 1e8
)");
}

TEST(CaseSettings, ReplacesAndAddsKeysWithTheirTomlTypes) {
  toml::table t = case_table();
  apply_settings(t, {"analysis.harmonics=13", "analysis.damper.kt=8.09e7", "analysis.aft=\"samples\"",
                     "analysis.levels=[5.0, 6.0]"});
  EXPECT_EQ(t["analysis"]["harmonics"].value<int64_t>(), 13);
  EXPECT_EQ(t["analysis"]["damper"]["kt"].value<double>(), 8.09e7);
  EXPECT_EQ(t["analysis"]["aft"].value<std::string>(), "samples");
  ASSERT_TRUE(t["analysis"]["levels"].is_array());
  EXPECT_EQ(t["analysis"]["levels"][1].value<double>(), 6.0);
  EXPECT_EQ(t["analysis"]["time_samples"].value<int64_t>(), 256);         // untouched
  EXPECT_EQ(t["analysis"]["harmonics"].node()->source().begin.line, 0u);  // no line of the case file
}

TEST(CaseSettings, RefusesMalformedSettingsByName) {
  for (const std::string bad : {"analysis.harmonics", "=3", "analysis..harmonics=3", "analysis.aft=samples",
                                "model.modes=10", "analysis.type.kind=1"}) {
    toml::table t = case_table();
    try {
      apply_settings(t, {bad});
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--set '" + bad + "'"), std::string::npos) << e.what();
    }
  }
}

// A value followed by more TOML (keys, a table) was parsed as a document and the rest dropped.
TEST(CaseSettings, RefusesAValueThatIsMoreThanOneTomlValue) {
  for (const std::string bad : {"analysis.harmonics=13\nother = 2", "analysis.harmonics=13\n[model]\nmodes = 1",
                                "analysis.levels=[5.0]\r\nx.y = 1"}) {
    toml::table t = case_table();
    try {
      apply_settings(t, {bad});
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("more than one TOML value"), std::string::npos) << e.what();
    }
  }
  toml::table t = case_table();
  apply_settings(t, {"analysis.harmonics=13 # a comment\n"});  // one value, then nothing
  EXPECT_EQ(t["analysis"]["harmonics"].value<int64_t>(), 13);
}

TEST(CaseSettings, RemovesKeysAndTablesThatExist) {
  toml::table t = case_table();
  apply_settings(t, {}, {"analysis.damper", "analysis.time_samples"});
  EXPECT_FALSE(t["analysis"]["damper"]);
  EXPECT_FALSE(t["analysis"]["time_samples"]);
  EXPECT_EQ(t["analysis"]["harmonics"].value<int64_t>(), 1);
  for (const std::string bad : {"analysis.nonlinear_modes", "model.damper", "analysis..harmonics"}) {
    toml::table u = case_table();
    try {
      apply_settings(u, {}, {bad});
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--unset '" + bad + "'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace bb
