// The model cache (cache/model_cache, reduction/cached_craig_bampton): keys change with any input,
// a stored reduction comes back bit for bit, a damaged entry is detected and rebuilt, the folder
// stays within its size bound, quick results are not stored, and with the cache off nothing is
// written.
#include "cache/model_cache.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <optional>

#include "cache/content_key.hpp"
#include "linalg/cached_modes.hpp"
#include "reduction/cached_craig_bampton.hpp"
#include "temp_folder.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

// A fixed-free chain of n unit masses and springs of stiffness k.
Eigen::SparseMatrix<double> chain_stiffness(int n, double k = 1e4) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, i + 1 < n ? 2 * k : k);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -k);
      t.emplace_back(i + 1, i, -k);
    }
  }
  Eigen::SparseMatrix<double> m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

Eigen::SparseMatrix<double> unit_mass(int n) {
  Eigen::SparseMatrix<double> m(n, n);
  m.setIdentity();
  return m;
}

std::string key_name(const Eigen::SparseMatrix<double>& k, std::string_view text) {
  return ContentKey("test").add(k).add(text).name();
}

TEST(ContentKey, ChangesWithEveryInputAndOnlyWithThem) {
  const auto k = chain_stiffness(20);
  EXPECT_EQ(key_name(k, "a"), key_name(k, "a"));
  EXPECT_NE(key_name(k, "a"), key_name(k, "b"));
  auto changed = k;
  changed.coeffRef(7, 7) *= 1.0 + 1e-15;
  EXPECT_NE(key_name(k, "a"), key_name(changed, "a"));
  EXPECT_NE(key_name(k, "a"), key_name(chain_stiffness(21), "a"));
  // Texts are length-prefixed, so moving a boundary changes the key.
  EXPECT_NE(ContentKey("t").add("ab").add("c").name(), ContentKey("t").add("a").add("bc").name());
  EXPECT_TRUE(key_name(k, "a").starts_with("test-"));
  EXPECT_FALSE(program_fingerprint().empty());
}

class ModelCache : public test::TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    settings_ = ModelCacheSettings{.folder = dir_ / "cache", .min_build_seconds = 0.0};
  }
  ReducedModel reduce(CraigBamptonTiming& t) const {
    return cached_craig_bampton(k_, m_, {n_ - 1}, {ReducedDof{"tip", 0, 0}}, options_,
                                settings_ ? &*settings_ : nullptr, &t);
  }
  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir_ / "cache"))
      if (e.path().extension() == ".bbcache") out.push_back(e.path());
    return out;
  }
  int n_ = 30;
  Eigen::SparseMatrix<double> k_ = chain_stiffness(n_), m_ = unit_mass(n_);
  CraigBamptonOptions options_{.n_modes = 4};
  std::optional<ModelCacheSettings> settings_;  // handed to every reduction (none: no cache)
};

TEST_F(ModelCache, SecondReductionIsLoadedBitForBit) {
  CraigBamptonTiming first, second;
  const ReducedModel a = reduce(first);
  EXPECT_EQ(first.cache.outcome, CacheUse::Outcome::stored);
  EXPECT_TRUE(first.cache.note.empty()) << first.cache.note;
  ASSERT_EQ(entries().size(), 1u);
  const ReducedModel b = reduce(second);
  EXPECT_EQ(second.cache.outcome, CacheUse::Outcome::loaded);
  EXPECT_EQ(second.fixed_interface_seconds, first.fixed_interface_seconds);  // the build's own times
  EXPECT_EQ(a.stiffness, b.stiffness);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.recovery, b.recovery);
  EXPECT_EQ(a.fixed_interface_frequencies_hz, b.fixed_interface_frequencies_hz);
  EXPECT_EQ(a.dofs, b.dofs);
}

TEST_F(ModelCache, OtherOptionsMakeAnotherEntry) {
  CraigBamptonTiming t;
  reduce(t);
  options_.n_modes = 5;
  reduce(t);
  EXPECT_NE(t.cache.outcome, CacheUse::Outcome::loaded);
  EXPECT_EQ(entries().size(), 2u);
}

TEST_F(ModelCache, DamagedEntryIsDetectedAndRebuilt) {
  CraigBamptonTiming t;
  const ReducedModel a = reduce(t);
  const fs::path entry = entries().at(0);
  {
    std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(fs::file_size(entry) / 2));
    f.put('\x5a');
  }
  const ReducedModel b = reduce(t);
  EXPECT_NE(t.cache.outcome, CacheUse::Outcome::loaded);
  EXPECT_NE(t.cache.note.find("damaged"), std::string::npos) << t.cache.note;
  EXPECT_EQ(a.stiffness, b.stiffness);
  reduce(t);  // the rebuilt entry is sound
  EXPECT_EQ(t.cache.outcome, CacheUse::Outcome::loaded);
}

TEST_F(ModelCache, TruncatedEntryIsDetectedAndRebuilt) {
  CraigBamptonTiming t;
  reduce(t);
  const fs::path entry = entries().at(0);
  fs::resize_file(entry, fs::file_size(entry) - 9);
  reduce(t);
  EXPECT_NE(t.cache.outcome, CacheUse::Outcome::loaded);
  EXPECT_NE(t.cache.note.find("damaged"), std::string::npos) << t.cache.note;
}

TEST_F(ModelCache, FolderIsPrunedToItsBound) {
  settings_ = ModelCacheSettings{.folder = dir_ / "cache", .max_bytes = 1, .min_build_seconds = 0.0};
  CraigBamptonTiming t;
  reduce(t);
  EXPECT_TRUE(entries().empty());
  reduce(t);
  EXPECT_NE(t.cache.outcome, CacheUse::Outcome::loaded);
}

TEST_F(ModelCache, QuickResultsAreNotStored) {
  settings_ = ModelCacheSettings{.folder = dir_ / "cache", .min_build_seconds = 1e9};
  CraigBamptonTiming t;
  reduce(t);
  EXPECT_EQ(t.cache.outcome, CacheUse::Outcome::not_stored);
  EXPECT_TRUE(entries().empty());
}

TEST_F(ModelCache, ModesComeBackBitForBitWithTheirCompletenessCount) {
  ModalOptions options;
  options.n_modes = 5;
  CacheUse first, second;
  const ModalSolution a = cached_lowest_modes(k_, m_, options, &*settings_, &first);
  const ModalSolution b = cached_lowest_modes(k_, m_, options, &*settings_, &second);
  EXPECT_EQ(first.outcome, CacheUse::Outcome::stored);
  EXPECT_EQ(second.outcome, CacheUse::Outcome::loaded);
  EXPECT_EQ(second.build_seconds, first.build_seconds);
  EXPECT_EQ(a.eigenvalues, b.eigenvalues);
  EXPECT_EQ(a.shapes, b.shapes);
  EXPECT_EQ(a.sturm_count, b.sturm_count);
  EXPECT_GE(b.sturm_count, 5);
  options.n_modes = 6;
  CacheUse third;
  const ModalSolution six = cached_lowest_modes(k_, m_, options, &*settings_, &third);
  EXPECT_EQ(third.outcome, CacheUse::Outcome::stored);  // five stored modes cannot serve six
  // Fewer modes than stored: the leading ones of the larger solution, said so in the note.
  options.n_modes = 4;
  CacheUse fourth;
  const ModalSolution four = cached_lowest_modes(k_, m_, options, &*settings_, &fourth);
  EXPECT_EQ(fourth.outcome, CacheUse::Outcome::loaded);
  EXPECT_EQ(fourth.note, "the lowest 4 of 6 stored modes");
  ASSERT_EQ(four.eigenvalues.size(), 4);
  EXPECT_EQ(four.eigenvalues, six.eigenvalues.head(4));
  EXPECT_EQ(four.shapes, six.shapes.leftCols(4));
  EXPECT_EQ(four.sturm_count, six.sturm_count);
}

TEST_F(ModelCache, OffWritesNothing) {
  settings_.reset();
  CraigBamptonTiming t;
  reduce(t);
  EXPECT_NE(t.cache.outcome, CacheUse::Outcome::loaded);
  EXPECT_FALSE(fs::exists(dir_ / "cache"));
}

}  // namespace
}  // namespace bb
