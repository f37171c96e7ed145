// Settings that reach into an array of tables by index (`run --set analysis.contact.0.mu=1.4`,
// issue 68): the element's key is replaced, and an index or a path that names no element's key is
// refused by name, never taken for a missing table.
#include <gtest/gtest.h>

#include <string>

#include "cases/case_settings.hpp"
#include "common/errors.hpp"

namespace bb {
namespace {

toml::table contacts() {
  return toml::parse(R"(
[analysis]
type = "hbm"
[analysis.model]
frequency_hz = [78.6, 120.0]
[[analysis.contact]]
kt = 1e5
mu = 0.5
[[analysis.contact]]
kt = 2e5
mu = 0.6
)");
}

std::string refusal(const std::vector<std::string>& settings, const std::vector<std::string>& removals = {}) {
  toml::table t = contacts();
  try {
    apply_settings(t, settings, removals);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CaseSettingsArrays, SetsAndRemovesAKeyOfAnArrayOfTablesElementByIndex) {
  toml::table t = contacts();
  apply_settings(t, {"analysis.contact.0.mu=1.4", "analysis.contact.1.beta=0.2"}, {"analysis.contact.1.kt"});
  EXPECT_EQ(t["analysis"]["contact"][0]["mu"].value<double>(), 1.4);
  EXPECT_EQ(t["analysis"]["contact"][0]["kt"].value<double>(), 1e5);  // untouched
  EXPECT_EQ(t["analysis"]["contact"][1]["mu"].value<double>(), 0.6);
  EXPECT_EQ(t["analysis"]["contact"][1]["beta"].value<double>(), 0.2);
  EXPECT_FALSE(t["analysis"]["contact"][1]["kt"]);
}

TEST(CaseSettingsArrays, RefusesAnIndexOutsideTheArrayOrAPathThatNamesNoElementKey) {
  EXPECT_NE(refusal({"analysis.contact.2.mu=1"}).find("'2' is not an index of [[analysis.contact]] (0 to 1)"),
            std::string::npos);
  EXPECT_NE(refusal({"analysis.contact.x.mu=1"}).find("'x' is not an index"), std::string::npos);
  EXPECT_NE(refusal({"analysis.contact.mu=1"}).find("name an element's key, analysis.contact.0.<key>"),
            std::string::npos);
  EXPECT_NE(refusal({"analysis.contact.0=1"}).find("array of tables: name an element's key"), std::string::npos);
  EXPECT_NE(refusal({}, {"analysis.contact.0.chi"}).find("--unset 'analysis.contact.0.chi': the case has no such key"),
            std::string::npos);
}

// An element of an array of values, the way calibration names it (analysis.model.frequency_hz.0).
TEST(CaseSettingsArrays, SetsAnElementOfAnArrayOfValuesByIndex) {
  toml::table t = contacts();
  apply_settings(t, {"analysis.model.frequency_hz.1=121.5"}, {});
  EXPECT_EQ(t["analysis"]["model"]["frequency_hz"][0].value<double>(), 78.6);
  EXPECT_EQ(t["analysis"]["model"]["frequency_hz"][1].value<double>(), 121.5);
  EXPECT_NE(refusal({"analysis.model.frequency_hz.2=1"})
                .find("'2' is not an index of analysis.model.frequency_hz (2 element(s))"),
            std::string::npos);
}

}  // namespace
}  // namespace bb
