#include "frontends/mip/writer.hpp"

#include "core/bytes/checks.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

PacketWriter::PacketWriter(std::vector<std::uint8_t>& out, std::uint8_t desc_set)
    : out_(out), writer_(out), set_(desc_set) {
  open_packet();
}

void PacketWriter::open_packet() {
  packet_start_ = out_.size();
  out_.push_back(kSync1);
  out_.push_back(kSync2);
  out_.push_back(set_);
  out_.push_back(0);  // payload length, patched in close_packet()
  ++packets_;
}

void PacketWriter::close_packet() {
  const std::size_t payload = out_.size() - packet_start_ - kHeaderSize;
  out_[packet_start_ + kLengthOffset] = static_cast<std::uint8_t>(payload);
  const std::uint16_t ck = bytes::mip_fletcher(
      std::span<const std::uint8_t>(out_.data() + packet_start_, payload + kHeaderSize));
  out_.push_back(static_cast<std::uint8_t>(ck >> 8));  // MSB first (L3821)
  out_.push_back(static_cast<std::uint8_t>(ck & 0xFF));
}

void PacketWriter::close_field() {
  if (!field_open_) return;
  field_open_ = false;
  const std::size_t len = out_.size() - field_start_;
  out_[field_start_] = static_cast<std::uint8_t>(len);
  const std::uint8_t desc = out_[field_start_ + 1];
  const std::size_t payload = out_.size() - packet_start_ - kHeaderSize;
  if (payload > kMaxPayload) {
    // L3974: end the packet after the last whole field; the field opens a continuation packet
    // of the same set, behind copies of the leading shared descriptors (L4002-4018).
    moved_.assign(out_.begin() + static_cast<std::ptrdiff_t>(field_start_), out_.end());
    out_.resize(field_start_);
    close_packet();
    open_packet();
    out_.insert(out_.end(), prefix_.begin(), prefix_.end());
    out_.insert(out_.end(), moved_.begin(), moved_.end());
    return;
  }
  if (!prefix_done_ && packets_ == 1) {
    if (shared::is_shared(desc)) {
      prefix_.insert(prefix_.end(), out_.begin() + static_cast<std::ptrdiff_t>(field_start_), out_.end());
    } else {
      prefix_done_ = true;
    }
  }
}

bytes::BeWriter& PacketWriter::field(std::uint8_t desc) {
  close_field();
  field_start_ = out_.size();
  out_.push_back(0);  // LEN, patched in close_field()
  out_.push_back(desc);
  field_open_ = true;
  return writer_;
}

void PacketWriter::raw_field(std::uint8_t desc, std::span<const std::uint8_t> data) {
  field(desc).bytes(data);
}

std::size_t PacketWriter::finish() {
  close_field();
  close_packet();
  return packets_;
}

std::vector<std::uint8_t> make_packet(std::uint8_t desc_set, std::uint8_t desc,
                                      std::span<const std::uint8_t> field_data) {
  std::vector<std::uint8_t> out;
  PacketWriter w(out, desc_set);
  w.raw_field(desc, field_data);
  w.finish();
  return out;
}

}  // namespace navfuse::frontends::mip
