// What a rank sends another comes back bit for bit, and a cut record is refused, not misread.
#include "distributed/byte_record.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace bb::distributed {
namespace {

TEST(ByteRecord, NumbersStringsAndVectorsComeBackBitForBit) {
  const double awkward = std::nextafter(0.1, 1.0);
  ByteWriter w;
  w.put(awkward).put(std::numeric_limits<double>::quiet_NaN()).put(-0.0).put(42).put(std::string("start 2\n"));
  w.put(std::vector<double>{1e-300, -3.5}).put(std::vector<int>{});
  ByteReader r(w.bytes());
  double a = 0, nan = 0, zero = 1;
  int i = 0;
  std::string text;
  std::vector<double> v;
  std::vector<int> empty{7};
  r.get(a);
  r.get(nan);
  r.get(zero);
  r.get(i);
  r.get(text);
  r.get(v);
  r.get(empty);
  EXPECT_EQ(std::memcmp(&a, &awkward, sizeof a), 0);
  EXPECT_TRUE(std::isnan(nan));
  EXPECT_TRUE(std::signbit(zero));
  EXPECT_EQ(i, 42);
  EXPECT_EQ(text, "start 2\n");
  EXPECT_EQ(v, (std::vector<double>{1e-300, -3.5}));
  EXPECT_TRUE(empty.empty());
  EXPECT_TRUE(r.done());
}

TEST(ByteRecord, ARecordCutShortIsRefused) {
  ByteWriter w;
  w.put(std::string("a longer text"));
  const std::string cut = w.bytes().substr(0, w.bytes().size() - 3);
  ByteReader r(cut);
  std::string text;
  EXPECT_THROW(r.get(text), std::runtime_error);
}

}  // namespace
}  // namespace bb::distributed
