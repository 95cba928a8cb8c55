// A validated MIP packet as the framer hands it out, and a bounds-checked walk over its fields.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

struct PacketView {
  std::uint8_t desc_set = 0;
  std::span<const std::uint8_t> payload;  // the fields, without header and checksum
  std::span<const std::uint8_t> bytes;    // the whole packet, sync to checksum
  std::uint64_t offset = 0;               // stream offset of the first sync byte
};

struct FieldView {
  std::uint8_t desc = 0;
  std::span<const std::uint8_t> data;  // LEN-2 bytes after LEN and DESC
};

// Iterates the fields of a payload. The framer has already proven the walk is well formed
// (digest §2.2: LEN >= 2, no field past the payload end), but the walk re-checks so that it is
// safe on any payload (command handlers get packets from sockets, not only from the framer).
class FieldWalker {
 public:
  explicit FieldWalker(std::span<const std::uint8_t> payload) : p_(payload) {}
  bool next(FieldView& out) {
    if (pos_ >= p_.size()) return false;
    const std::size_t len = p_[pos_];
    if (len < kMinFieldLength || len > p_.size() - pos_) {
      malformed_ = true;
      pos_ = p_.size();
      return false;
    }
    out.desc = p_[pos_ + 1];
    out.data = p_.subspan(pos_ + kFieldHeaderSize, len - kFieldHeaderSize);
    pos_ += len;
    return true;
  }
  bool malformed() const { return malformed_; }

 private:
  std::span<const std::uint8_t> p_;
  std::size_t pos_ = 0;
  bool malformed_ = false;
};

// True when the payload is a whole number of well-formed fields (digest §2.2 parser rules).
inline bool fields_well_formed(std::span<const std::uint8_t> payload) {
  std::size_t pos = 0;
  while (pos < payload.size()) {
    const std::size_t len = payload[pos];
    if (len < kMinFieldLength || len > payload.size() - pos) return false;
    pos += len;
  }
  return true;
}

}  // namespace navfuse::frontends::mip
