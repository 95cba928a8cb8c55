// Deterministic random numbers for the simulator.
//
// The standard library's distributions are implementation-defined (libstdc++ and libc++ give
// different normal deviates for the same engine state), so a seed would not reproduce the same
// log across compilers. This file fixes both the engine and the transforms:
//  - xoshiro256** 1.0 (D. Blackman, S. Vigna, "Scrambled linear pseudorandom number generators",
//    ACM TOMS 47(4), 2021), seeded through splitmix64 as its authors recommend;
//  - normal deviates by the Marsaglia polar method (Marsaglia & Bray, SIAM Review 6(3), 1964).
// Each sensor model draws from its own stream (seed, stream id), so that switching one sensor on
// or off does not change the noise of the others: Monte-Carlo runs stay comparable.
#pragma once

#include <cmath>
#include <cstdint>

namespace navfuse::sim {

// Stream ids: one per consumer of randomness.
enum class RandomStream : std::uint64_t {
  kImu = 1,
  kGnss = 2,
  kWheel = 3,
  kHeading = 4,
  kVibration = 5,  // apps/sim/vibration_model.hpp
  kMultipath = 6,  // apps/sim/gnss_multipath.hpp
};

class Rng {
 public:
  Rng(std::uint64_t seed, RandomStream stream) {
    std::uint64_t x = seed ^ (0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(stream));
    for (auto& s : s_) s = splitmix64(x);
  }

  std::uint64_t next_u64() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  // Uniform in [0, 1): the top 53 bits as a double mantissa.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

  // Standard normal deviate (mean 0, variance 1).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0.0, v = 0.0, s = 0.0;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double k = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * k;
    has_spare_ = true;
    return u * k;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::uint64_t s_[4]{};
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace navfuse::sim
