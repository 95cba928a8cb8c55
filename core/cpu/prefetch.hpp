// Cache prefetch hints for data one thread hands to another. A replay's threads pass each
// measurement and each output epoch across cores (apps/fusion/merger_thread, apps/output/
// pose_output_thread): the receiving side finds those lines in the other core's cache, and the
// stride between items (a 704-byte Measurement variant holding an 88-byte IMU sample, a 1.6 kB
// OutputEpoch) defeats the hardware's next-line prefetcher. Asking for an item a few ahead
// hides that transfer: on the 9-minute replay benchmark the filter thread's share in reading
// the measurements and writing the epochs' captured state fell from ~15 % to ~5 % of its time
// (perf, 2026-11-29). Hints only: they never fault, and do nothing on other compilers.
#pragma once

#include <cstddef>

namespace navfuse::cpu {

inline constexpr std::size_t kCacheLineBytes = 64;

enum class Intent { kRead = 0, kWrite = 1 };

// Every cache line of [p, p + bytes) towards this core's cache, to be read or written.
template <Intent kIntent>
inline void prefetch(const void* p, std::size_t bytes) {
#if defined(__GNUC__)
  const char* c = static_cast<const char*>(p);
  for (std::size_t b = 0; b < bytes; b += kCacheLineBytes) __builtin_prefetch(c + b, static_cast<int>(kIntent));
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace navfuse::cpu
