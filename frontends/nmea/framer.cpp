#include "frontends/nmea/framer.hpp"

#include <algorithm>
#include <cstring>

namespace navfuse::frontends::nmea {
namespace {

constexpr std::array<std::uint8_t, 256> make_byte_classes() {
  std::array<std::uint8_t, 256> table{};
  for (std::size_t c = 0; c < table.size(); ++c) {
    // Sentences are printable ASCII (STR fields exclude '\r' and '\n', spec L180); anything else
    // inside a sentence is corruption and ends it.
    table[c] = (c < 0x20 || c > 0x7E) ? 3 : 0;
  }
  // "ends with 'r' (0x0D) or '\n' (0x0A) or any combination" (L150): 'r' is read as '\r', the
  // byte its hex code names (erratum, digest §11 item 2).
  table['\r'] = 1;
  table['\n'] = 1;
  table['$'] = 2;   // every sentence starts with '$' (L142) ...
  // ... except the command echo (L250-L260), whose checksum is unspecified (digest §11 item 5):
  // it is framed like any sentence, with the checksum optional.
  table['#'] = 2;
  return table;
}

int hex_value(std::uint8_t c) {
  if (c >= '0' && c <= '9') return c - '0';
  // "letters in checksums are not case-sensitive" (L154)
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

const std::array<std::uint8_t, 256> SentenceFramer::kByteClass = make_byte_classes();

SentenceFramer::SentenceFramer(FramerOptions options) : options_(options) {
  // The carry-over buffer bounds the longest sentence a caller may configure.
  const std::size_t max_bytes =
      std::clamp<std::size_t>(options_.max_sentence_bytes, kTerminatorBytes + 2, partial_.size());
  max_text_ = max_bytes - kTerminatorBytes;
}

const std::uint8_t* SentenceFramer::find_start(const std::uint8_t* p, const std::uint8_t* end) const {
  if (!options_.accept_hash_start) {
    const void* hit = std::memchr(p, '$', static_cast<std::size_t>(end - p));
    return hit ? static_cast<const std::uint8_t*>(hit) : end;
  }
  while (p < end && kByteClass[*p] != kStart) ++p;
  return p;
}

bool SentenceFramer::check(const std::uint8_t* text, std::size_t size, std::uint8_t xor_all,
                           std::size_t& body_size, bool& has_checksum) const {
  if (text[0] == '#' && !options_.accept_hash_start) return false;
  const std::uint8_t* body = text + 1;
  std::size_t n = size - 1;
  has_checksum = n >= kChecksumFieldBytes && body[n - kChecksumFieldBytes] == '*';
  if (has_checksum) {
    const int hi = hex_value(body[n - 2]);
    const int lo = hex_value(body[n - 1]);
    if (hi < 0 || lo < 0) return false;
    n -= kChecksumFieldBytes;
    // The XOR of the body is the running XOR with the "*HH" characters taken out again (L164:
    // XOR of all characters strictly between '$' and '*').
    const auto body_xor =
        static_cast<std::uint8_t>(xor_all ^ '*' ^ body[n + 1] ^ body[n + 2]);
    if (body_xor != static_cast<std::uint8_t>((hi << 4) | lo)) return false;
  } else if (options_.require_checksum) {
    return false;
  }
  // A '*' anywhere else is a damaged or misplaced checksum field ("*2", "*2C5", "**"): reject it
  // rather than read the sentence as one without a checksum.
  if (n == 0 || std::memchr(body, '*', n) != nullptr) return false;
  body_size = n;
  return true;
}

void SentenceFramer::finish() {
  counters_.skipped_bytes += partial_size_;
  partial_size_ = 0;
  swallow_lf_ = false;
}

}  // namespace navfuse::frontends::nmea
