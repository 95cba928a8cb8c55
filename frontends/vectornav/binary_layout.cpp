#include "frontends/vectornav/binary_layout.hpp"

namespace navfuse::frontends::vectornav {
namespace {

constexpr std::uint8_t V = kVariableSize;
// Table 2.2 (L737-759), one row per group slot, index = raw type bit; 0 = undefined ("–").
// Bit 15 is the type-word extension bit and never names data.
constexpr std::array<std::array<std::uint8_t, 32>, kGroupCount> kSizes = {{
    /* Common   */ {8, 8, 8, 12, 16, 12, 24, 12, 12, 24, 20, 28, 2, 4, 8},
    /* Time     */ {8, 8, 8, 2, 8, 8, 8, 4, 4, 1},
    /* Imu      */ {2, 12, 12, 12, 4, 4, 16, 12, 12, 12, 12, 2},
    /* Gnss1    */ {8, 8, 2, 1, 1, 24, 24, 12, 12, 12, 4, 4, 2, 28, V, 0, V, 2, 8},
    /* Attitude */ {0, 12, 16, 36, 12, 12, 12, 12, 12, 0, 0, 0, 12, 4},
    /* Ins      */ {2, 24, 24, 12, 12, 12, 12, 12, 12, 4, 4},
    /* Gnss2    */ {8, 8, 2, 1, 1, 24, 24, 12, 12, 12, 4, 4, 2, 28, V, 0, V, 2, 8},
    /* Gnss3    */ {8, 8, 2, 1, 1, 24, 24, 12, 12, 12, 4, 4, 2, 28, V, 0, V, 2, 8},
}};

constexpr std::array<std::uint32_t, kGroupCount> make_masks() {
  std::array<std::uint32_t, kGroupCount> m{};
  for (std::size_t s = 0; s < kGroupCount; ++s)
    for (unsigned b = 0; b < 32; ++b)
      if (kSizes[s][b] != 0) m[s] |= 1u << b;
  return m;
}
constexpr std::array<std::uint32_t, kGroupCount> kMasks = make_masks();

constexpr std::array<std::uint32_t, kGroupCount> make_variable_masks() {
  std::array<std::uint32_t, kGroupCount> m{};
  for (std::size_t s = 0; s < kGroupCount; ++s)
    for (unsigned b = 0; b < 32; ++b)
      if (kSizes[s][b] == V) m[s] |= 1u << b;
  return m;
}
constexpr std::array<std::uint32_t, kGroupCount> kVariableMasks = make_variable_masks();

// Per slot and per byte of the type bits: the summed sizes of the fixed-size types that byte
// selects, so that a message's length is four lookups per group rather than one per type (the
// framer and the decoder measure every message).
using ByteSums = std::array<std::array<std::array<std::uint16_t, 256>, 4>, kGroupCount>;
constexpr ByteSums make_byte_sums() {
  ByteSums sums{};
  for (std::size_t s = 0; s < kGroupCount; ++s)
    for (unsigned byte = 0; byte < 4; ++byte)
      for (unsigned v = 0; v < 256; ++v) {
        unsigned total = 0;
        for (unsigned b = 0; b < 8; ++b) {
          const std::uint8_t size = kSizes[s][byte * 8 + b];
          if ((v >> b) & 1u && size != V) total += size;
        }
        sums[s][byte][v] = static_cast<std::uint16_t>(total);
      }
  return sums;
}
constexpr ByteSums kByteSums = make_byte_sums();

}  // namespace

std::uint8_t type_size(std::size_t slot, unsigned type_bit) {
  if (slot >= kGroupCount || type_bit >= 32) return 0;
  return kSizes[slot][type_bit];
}

std::uint32_t known_type_mask(std::size_t slot) { return slot < kGroupCount ? kMasks[slot] : 0; }

std::uint32_t variable_type_mask(std::size_t slot) { return slot < kGroupCount ? kVariableMasks[slot] : 0; }

std::size_t fixed_types_size(std::size_t slot, std::uint32_t types) {
  if (slot >= kGroupCount) return 0;
  const auto& sums = kByteSums[slot];
  return std::size_t{sums[0][types & 0xFFu]} + sums[1][(types >> 8) & 0xFFu] + sums[2][(types >> 16) & 0xFFu] +
         sums[3][types >> 24];
}

std::size_t slot_of_group_bit(unsigned bit) {
  for (std::size_t s = 0; s < kGroupCount; ++s)
    if (group_bit(kGroups[s]) == bit) return s;
  return kGroupCount;
}

}  // namespace navfuse::frontends::vectornav
