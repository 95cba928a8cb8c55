// The time-fault fuzz target (tests/fuzz/fusion/time_fault_fuzz.cpp) in the ordinary build: its
// seed corpus and a fixed set of random streams, so that its invariant (no crash, the counts add
// up with jumps, gaps and clock changes) is checked by every `ctest`, not only under clang's
// libFuzzer in `make sanitize`.
#include <cstdint>
#include <filesystem>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "test_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace navfuse::apps {
namespace {

TEST(TimeFaultFuzz, SeedCorpus) {
  const std::filesystem::path corpus = std::filesystem::path(NAVFUSE_SOURCE_DIR) / "tests/fuzz/fusion/corpus";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    const auto bytes = testing::read_bytes(entry.path());
    EXPECT_EQ(LLVMFuzzerTestOneInput(bytes.data(), bytes.size()), 0) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 2);
}

TEST(TimeFaultFuzz, RandomStreams) {
  std::mt19937_64 rng(15);
  for (int i = 0; i < 200; ++i) {
    std::vector<std::uint8_t> bytes(rng() % 4096);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    EXPECT_EQ(LLVMFuzzerTestOneInput(bytes.data(), bytes.size()), 0) << i;
  }
}

}  // namespace
}  // namespace navfuse::apps
