// VectorNav ASCII sentences: `$` + header + `,`fields + `*` + checksum + newline (ICD §1.2
// L127-145, §1.4 L583-641; digest §2.1-§2.3, §2.7).
//
// The checksum covers the bytes strictly between '$' and '*' (L587). Two hex digits are the
// 8-bit XOR, four are the CRC16 (Reg 30 AsciiChecksum, L2865-2871); `XX` bypasses the check
// (L591-597) and, errata A26, `XXXX` is accepted the same way in CRC mode. Errata A27: the
// terminator is "a newline character" (L127), so "\n" and "\r\n" are both accepted; the encoder
// sends "\r\n".
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace navfuse::frontends::vectornav {

enum class AsciiChecksum : std::uint8_t {
  kXor8 = 1,   // Reg 30 value 1 (default)
  kCrc16 = 3,  // Reg 30 value 3
  kBypass = 0, // "XX" / "XXXX": the device skips the check
};

struct SentenceCheck {
  bool ok = false;
  AsciiChecksum kind = AsciiChecksum::kXor8;
  std::string_view body;  // between '$' and '*'
};
// Checks one framed sentence ('$' through '\n').
SentenceCheck check_sentence(std::span<const std::uint8_t> frame);

inline constexpr std::size_t kMaxAsciiFields = 40;

struct AsciiSentence {
  std::string_view header;  // e.g. "VNYPR", "VNRRG", "VNERR", "GPGGA"
  std::array<std::string_view, kMaxAsciiFields> fields{};
  std::size_t field_count = 0;
  // Reg 30 appends on asynchronous outputs (L2787-2813): `,T<uint32>` counter/time and
  // `,S<4 hex>` status. Errata A7: the text and the example disagree on their order, so both
  // orders are accepted, keyed on the prefix.
  bool has_append_count = false;
  std::uint32_t append_count = 0;
  bool has_append_status = false;
  std::uint16_t append_status = 0;

  std::span<const std::string_view> values() const { return {fields.data(), field_count}; }
};
// Splits a checked body into header and fields; `strip_appends` removes trailing T/S appends
// (only asynchronous outputs carry them). False when there are too many fields.
bool parse_sentence(std::string_view body, bool strip_appends, AsciiSentence& out);

// "$" + body + "*" + checksum + "\r\n" (uppercase hex, as in every ICD example).
std::string make_sentence(std::string_view body, AsciiChecksum kind = AsciiChecksum::kXor8);

}  // namespace navfuse::frontends::vectornav
