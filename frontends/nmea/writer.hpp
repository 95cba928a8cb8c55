// Builds one sentence, "$NAME,f1,...*HH\r\n", in a fixed buffer (no allocation), with the XOR
// checksum of the Unicore spec L164 / NMEA 0183 and the number formats of fields.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "frontends/nmea/fields.hpp"
#include "frontends/nmea/framer.hpp"

namespace navfuse::frontends::nmea {

class SentenceWriter {
 public:
  // Starts a sentence with its name (e.g. "GPGGA", "GYOACC-V"); `start` is '$' or '#'.
  void begin(std::string_view name, char start = '$');
  // Each add_* appends a comma and one field.
  void add(std::string_view text);
  void add_empty() { add(std::string_view{}); }
  void add(char c) { add(std::string_view(&c, 1)); }
  void add_fixed(double value, int decimals);
  void add(const Real& r) { add_fixed(r.value, r.decimals); }
  void add_uint(std::uint64_t value, int min_width = 1);
  void add(const Count& c) { add_uint(c.value, c.width); }
  void add_int(std::int64_t value);
  // UINT in the spec's hex form (L183): `prefix` 'h' or 'H', lower-case digits zero-padded to
  // min_width, e.g. add_hex(0x51) -> "h51", add_hex(1, 2) -> "h01" (RESET example L238).
  void add_hex(std::uint32_t value, int min_width = 1, char prefix = 'h');
  // Appends text to the current field without a separating comma.
  void append(std::string_view text);
  void append_fixed(double value, int decimals);
  void append_uint(std::uint64_t value, int min_width);

  // Appends "*HH\r\n" and copies the sentence to `out`. False (nothing appended) if the
  // sentence is longer than `max_bytes` or a field did not fit.
  bool finish(std::vector<std::uint8_t>& out, std::size_t max_bytes = kUnicoreMaxSentenceBytes);
  // The finished sentence (valid after a successful finish() until the next begin()).
  std::string_view text() const { return {buffer_.data(), size_}; }

 private:
  std::array<char, 512> buffer_{};
  std::size_t size_ = 0;
  bool overflow_ = false;
};

}  // namespace navfuse::frontends::nmea
