#include "frontends/vectornav/framer.hpp"

#include "core/bytes/checks.hpp"
#include "frontends/vectornav/ascii_sentence.hpp"

namespace navfuse::frontends::vectornav {

PortFramer::Attempt PortFramer::try_binary(const std::uint8_t* p, std::size_t n) {
  const std::span<const std::uint8_t> after_sync(p + 1, n - 1);
  switch (parse_header(after_sync, header_)) {
    case ParseStatus::kIncomplete: return {Verdict::kIncomplete, 0};
    case ParseStatus::kInvalid: return {Verdict::kNotFrame, 0};
    case ParseStatus::kOk: break;
  }
  const std::size_t overhead = 1 + header_.header_bytes + kCrcBytes;
  if (overhead >= kMaxBinaryPacketBytes) return {Verdict::kNotFrame, 0};
  std::size_t payload = 0;
  switch (measure_payload(header_, after_sync.subspan(header_.header_bytes), kMaxBinaryPacketBytes - overhead,
                          payload)) {
    case ParseStatus::kIncomplete: return {Verdict::kIncomplete, 0};
    case ParseStatus::kInvalid: return {Verdict::kNotFrame, 0};
    case ParseStatus::kOk: break;
  }
  const std::size_t total = overhead + payload;
  if (total > n) return {Verdict::kIncomplete, 0};
  // Running the CRC over header, payload and the big-endian CRC itself gives 0 (L699, L5250).
  // Errata A2 (digest §10): the polynomial is 0x1021 of the reference code (L624-639), not the
  // "0x07" of Reg 30's text (L2842); errata A3: big-endian trailer, sync byte not covered.
  if (bytes::crc16_xmodem({p + 1, total - 1}) != 0) return {Verdict::kBad, 0};
  return {Verdict::kFrame, total};
}

PortFramer::Attempt PortFramer::try_split(const std::uint8_t* p, std::size_t n) {
  switch (parse_split_header({p + 1, n - 1}, split_)) {
    case ParseStatus::kIncomplete: return {Verdict::kIncomplete, 0};
    case ParseStatus::kInvalid: return {Verdict::kNotFrame, 0};
    case ParseStatus::kOk: break;
  }
  const std::size_t total = 1 + kSplitHeaderBytes + split_.payload_bytes + kCrcBytes;
  if (total > n) return {Verdict::kIncomplete, 0};
  if (bytes::crc16_xmodem({p + 1, total - 1}) != 0) return {Verdict::kBad, 0};
  return {Verdict::kFrame, total};
}

PortFramer::Attempt PortFramer::try_ascii(const std::uint8_t* p, std::size_t n) {
  const std::size_t limit = std::min(n, kMaxAsciiSentenceBytes);
  std::size_t k = 1;
  for (; k < limit; ++k) {
    const std::uint8_t c = p[k];
    if (c == '\n') break;
    // Another '$' or a byte no sentence contains: this '$' was noise (or binary data).
    if (c == '$') return {Verdict::kNotFrame, 0};
    if ((c < 0x20 && c != '\r') || c > 0x7E) return {Verdict::kNotFrame, 0};
    if (c == '\r' && k + 1 < n && p[k + 1] != '\n') return {Verdict::kNotFrame, 0};
  }
  if (k == limit) return {limit == n && n < kMaxAsciiSentenceBytes ? Verdict::kIncomplete : Verdict::kNotFrame, 0};
  const std::size_t length = k + 1;
  return {check_sentence({p, length}).ok ? Verdict::kFrame : Verdict::kBad, length};
}

}  // namespace navfuse::frontends::vectornav
