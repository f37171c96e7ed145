// Every input a fuzz target ever failed on (tests/fuzz/regressions/<target>/*), replayed through
// the same target: it must now be read or refused with InputError, nothing else (fuzz_targets.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../fuzz/fuzz_targets.hpp"

namespace bb::fuzz {
namespace {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryCommittedInputIsReadOrRefusedAsBadInput) {
  const fs::path root = fs::path(BB_SOURCE_DIR) / "tests" / "fuzz" / "regressions";
  int replayed = 0;
  for (const Target& t : targets()) {
    const fs::path dir = root / t.name;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      SCOPED_TRACE(entry.path().string());
      EXPECT_NO_THROW(t.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
      ++replayed;
    }
  }
  std::printf("  %d regression inputs replayed\n", replayed);
}

}  // namespace
}  // namespace bb::fuzz
