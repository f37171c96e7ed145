// libFuzzer entry: the target is chosen at compile time (BB_FUZZ_TARGET, one program per target).
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  bb::fuzz::BB_FUZZ_TARGET(data, size);
  return 0;
}
