// Size of the framers' corrupted-stream benchmarks (issue 15.11): a corrupted header may claim a
// payload of megabytes, and a stream shorter than such claims hides what waiting for (and
// CRC-ing) them costs. Each benchmark builds its device stream, repeats it to this size, then
// corrupts it, all in memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace navfuse::bench {

inline constexpr std::size_t kCorruptedStreamBytes = std::size_t{200} << 20;

// Appends whole copies of `bytes` to itself until it holds at least `size` bytes.
inline void repeat_to(std::vector<std::uint8_t>& bytes, std::size_t size) {
  const std::size_t one = bytes.size();
  if (one == 0) return;
  bytes.reserve(((size + one - 1) / one) * one);
  while (bytes.size() < size) bytes.insert(bytes.end(), bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(one));
}

}  // namespace navfuse::bench
