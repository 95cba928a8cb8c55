#include "frontends/vectornav/binary_header.hpp"

#include <bit>

namespace navfuse::frontends::vectornav {
namespace {

constexpr unsigned kBitsPerGroupByte = 8;
constexpr unsigned kBitsPerTypeWord = 16;
constexpr std::uint32_t kTypeWordDataMask = 0x7FFFu;

std::uint16_t load_u16le(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

}  // namespace

ParseStatus parse_header(std::span<const std::uint8_t> bytes, BinaryHeader& out) {
  std::size_t i = 0;
  std::uint32_t groups = 0;
  for (std::size_t n = 0;; ++n) {
    if (n == kMaxGroupBytes) return ParseStatus::kInvalid;  // fifth group byte: not this protocol
    if (i >= bytes.size()) return ParseStatus::kIncomplete;
    const std::uint8_t g = bytes[i++];
    groups |= static_cast<std::uint32_t>(g & ~kGroupExtensionBit) << (kBitsPerGroupByte * n);
    if ((g & kGroupExtensionBit) == 0) break;
  }
  if (groups == 0 || (groups & ~kKnownGroupMask) != 0) return ParseStatus::kInvalid;
  out.groups = groups;
  for (std::size_t slot = 0; slot < kGroupCount; ++slot) {
    out.types[slot] = 0;
    if (((groups >> group_bit(kGroups[slot])) & 1u) == 0) continue;
    if (i + 2 > bytes.size()) return ParseStatus::kIncomplete;
    const std::uint16_t w0 = load_u16le(bytes.data() + i);
    i += 2;
    std::uint32_t t = w0 & kTypeWordDataMask;
    if (w0 & kTypeExtensionBit) {
      if (i + 2 > bytes.size()) return ParseStatus::kIncomplete;
      const std::uint16_t w1 = load_u16le(bytes.data() + i);
      i += 2;
      // A third word would be needed: more than the 2 words per group the ICD allows (L5365).
      if (w1 & kTypeExtensionBit) return ParseStatus::kInvalid;
      t |= static_cast<std::uint32_t>(w1) << kBitsPerTypeWord;
    }
    // A type unknown to this firmware has an unknown size, so the message cannot be framed
    // (digest §11.2); an empty group carries nothing and no device sends one (errata A16).
    if (t == 0 || (t & ~known_type_mask(slot)) != 0) return ParseStatus::kInvalid;
    out.types[slot] = t;
  }
  out.header_bytes = i;
  return ParseStatus::kOk;
}

ParseStatus measure_payload(const BinaryHeader& header, std::span<const std::uint8_t> payload,
                            std::size_t max_payload, std::size_t& payload_bytes) {
  std::size_t len = 0;
  for (std::size_t slot = 0; slot < kGroupCount; ++slot) {
    std::uint32_t t = header.types[slot];
    if (t == 0) continue;
    if ((t & variable_type_mask(slot)) == 0) {  // the common case: every size from the table
      len += fixed_types_size(slot, t);
      if (len > max_payload) return ParseStatus::kInvalid;
      continue;
    }
    while (t != 0) {
      const unsigned bit = static_cast<unsigned>(std::countr_zero(t));
      t &= t - 1;
      const std::uint8_t size = type_size(slot, bit);
      if (size != kVariableSize) {
        len += size;
      } else {
        // SatInfo: Count is the first byte; RawMeas: NumSats is byte 10 (L1321-1342, L1387-1413).
        const bool sat_info = bit == gnss_type::kSatInfo;
        const std::size_t count_at = len + (sat_info ? 0 : kRawMeasCountOffset);
        if (count_at >= max_payload) return ParseStatus::kInvalid;
        if (count_at >= payload.size()) return ParseStatus::kIncomplete;
        const std::size_t count = payload[count_at];
        len += sat_info ? kSatInfoHeaderBytes + kSatInfoEntryBytes * count
                        : kRawMeasHeaderBytes + kRawMeasEntryBytes * count;
      }
      if (len > max_payload) return ParseStatus::kInvalid;
    }
  }
  payload_bytes = len;
  return ParseStatus::kOk;
}

void append_header(const BinaryHeader& header, std::vector<std::uint8_t>& out) {
  const unsigned top = header.groups == 0 ? 0u : 31u - static_cast<unsigned>(std::countl_zero(header.groups));
  const unsigned group_bytes = top / kBitsPerGroupByte + 1;
  for (unsigned n = 0; n < group_bytes; ++n) {
    std::uint8_t g = static_cast<std::uint8_t>((header.groups >> (kBitsPerGroupByte * n)) & ~kGroupExtensionBit & 0xFFu);
    if (n + 1 < group_bytes) g |= kGroupExtensionBit;
    out.push_back(g);
  }
  for (std::size_t slot = 0; slot < kGroupCount; ++slot) {
    if (((header.groups >> group_bit(kGroups[slot])) & 1u) == 0) continue;
    const std::uint32_t t = header.types[slot];
    const std::uint32_t high = (t >> kBitsPerTypeWord) & kTypeWordDataMask;
    std::uint16_t w0 = static_cast<std::uint16_t>(t & kTypeWordDataMask);
    if (high != 0) w0 |= kTypeExtensionBit;
    out.push_back(static_cast<std::uint8_t>(w0 & 0xFFu));
    out.push_back(static_cast<std::uint8_t>(w0 >> 8));
    if (high != 0) {
      out.push_back(static_cast<std::uint8_t>(high & 0xFFu));
      out.push_back(static_cast<std::uint8_t>(high >> 8));
    }
  }
}

}  // namespace navfuse::frontends::vectornav
