// Builds MIP packets of one descriptor set: fills field and payload lengths, appends the
// Fletcher checksum and splits at the 255-byte payload limit on whole-field boundaries into
// continuation packets, copying the leading shared descriptors (0xD0-0xD8) into each
// continuation so a reader can group them by timestamp (digest §2.8, L3974-4024).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/bytes/byte_writer.hpp"

namespace navfuse::frontends::mip {

class PacketWriter {
 public:
  // Appends to `out` (which may already hold other packets).
  PacketWriter(std::vector<std::uint8_t>& out, std::uint8_t desc_set);
  PacketWriter(const PacketWriter&) = delete;
  PacketWriter& operator=(const PacketWriter&) = delete;

  // Starts a field with descriptor `desc`; write its data through the returned writer.
  // Field data must not exceed kMaxFieldData (253) bytes.
  bytes::BeWriter& field(std::uint8_t desc);
  // Appends a complete field from raw data bytes.
  void raw_field(std::uint8_t desc, std::span<const std::uint8_t> data);
  // Closes the last field and packet. Returns the number of packets written.
  std::size_t finish();

 private:
  void close_field();
  void open_packet();
  void close_packet();

  std::vector<std::uint8_t>& out_;
  bytes::BeWriter writer_;
  std::uint8_t set_;
  std::size_t packet_start_ = 0;
  std::size_t field_start_ = 0;
  bool field_open_ = false;
  bool prefix_done_ = false;        // a non-shared field has been written in the first packet
  std::vector<std::uint8_t> prefix_;  // leading shared fields, copied into continuations
  std::vector<std::uint8_t> moved_;   // scratch for a field moved to a continuation packet
  std::size_t packets_ = 0;
};

// Convenience: one complete single-field packet.
std::vector<std::uint8_t> make_packet(std::uint8_t desc_set, std::uint8_t desc,
                                      std::span<const std::uint8_t> field_data);

}  // namespace navfuse::frontends::mip
