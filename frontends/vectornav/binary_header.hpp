// The header of a VectorNav binary message: group byte(s) then the type word(s) of each active
// group (ICD §2.1.3 L692-699, Appendix B.1.1 L5353-5393; digest §4.1-§4.4, §4.8), and the
// payload length it implies through the type-size table, variable-length fields included.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "frontends/vectornav/binary_layout.hpp"

namespace navfuse::frontends::vectornav {

struct BinaryHeader {
  std::uint32_t groups = 0;                        // raw group bits, extension bits cleared
  std::array<std::uint32_t, kGroupCount> types{};  // raw type bits per group slot, extension bits cleared
  std::size_t header_bytes = 0;                    // group bytes + type words on the wire

  bool has(std::size_t slot, unsigned type_bit) const { return (types[slot] >> type_bit) & 1u; }
  void set(std::size_t slot, unsigned type_bit) {
    types[slot] |= 1u << type_bit;
    groups |= 1u << group_bit(kGroups[slot]);
  }
};

enum class ParseStatus : std::uint8_t {
  kOk,
  kIncomplete,  // more bytes are needed to decide
  kInvalid,     // not a message of this firmware (unknown group/type, no groups, too long)
};

// Parses the header from `bytes`, which start just after the sync byte.
ParseStatus parse_header(std::span<const std::uint8_t> bytes, BinaryHeader& out);

// Payload length for `header`, reading the count bytes of variable-length types from `payload`
// (the bytes available after the header). kInvalid when the payload would exceed `max_payload`.
ParseStatus measure_payload(const BinaryHeader& header, std::span<const std::uint8_t> payload,
                            std::size_t max_payload, std::size_t& payload_bytes);

// Appends the header with the minimum number of group bytes and type words (L5359: "Only the
// minimum number of group bytes are used"; extension bits set only where needed).
void append_header(const BinaryHeader& header, std::vector<std::uint8_t>& out);

}  // namespace navfuse::frontends::vectornav
