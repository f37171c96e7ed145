// What a [[check]] compares: result columns against reference columns, row by row on a shared key.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/source_location.hpp"

namespace bb {

struct CheckSpec {
  std::string name;
  std::string result;                    // result table, e.g. "nodal_displacements"
  std::filesystem::path reference;       // CSV, resolved against the case file's folder; or empty when
  std::string reference_result;          // another result table of the same run is the reference,
  std::filesystem::path reference_case;  // or of this other case's run (its analysis only, not its checks)
  // How computed compares with reference: equal within the tolerance, or one-sided (at most /
  // at least the reference, give or take the tolerance), e.g. "this mesh is stiffer than that one".
  enum class Relation { equal, at_most, at_least } relation = Relation::equal;
  // Which computed row a reference row is compared with: the row of the same key; the mode of the
  // same shape (checks/mode_matching: MAC against the reference case's modes, a pairing below
  // min_mac fails); or the k-th row with the same text labels (e.g. the 2nd "torsion" mode).
  enum class Match { key, mac, label } match = Match::key;
  double min_mac = 0.9;
  std::vector<std::string> labels;                           // match = label: the text columns that must agree
  std::string key;                                           // key column of the reference, e.g. "node"
  std::vector<std::pair<std::string, std::string>> compare;  // result column -> reference column
  std::vector<long> keys;                                    // compare only these reference rows; empty = every row
  double abs_tol = 0.0;
  double rel_tol = 0.0;
  std::string source;  // where the reference values come from (for the report)
  SourceLocation at;
};

// The case file's name of each relation (`expect = ...`) and match (`match = ...`): a new kind is
// an enumerator and its case in these switches (-Wswitch), which the parser, the checks and the
// report read.
constexpr std::string_view relation_name(CheckSpec::Relation r) {
  switch (r) {
    case CheckSpec::Relation::equal:
      return "equal";
    case CheckSpec::Relation::at_most:
      return "at_most";
    case CheckSpec::Relation::at_least:
      return "at_least";
  }
  return "";
}
constexpr std::string_view match_name(CheckSpec::Match m) {
  switch (m) {
    case CheckSpec::Match::key:
      return "key";
    case CheckSpec::Match::mac:
      return "mac";
    case CheckSpec::Match::label:
      return "label";
  }
  return "";
}
inline constexpr std::array kRelations{CheckSpec::Relation::equal, CheckSpec::Relation::at_most,
                                       CheckSpec::Relation::at_least};
inline constexpr std::array kMatches{CheckSpec::Match::key, CheckSpec::Match::mac, CheckSpec::Match::label};

}  // namespace bb
