// The client side of NTRIP, the HTTP-like protocol GNSS correction casters speak (RTCM 10410.1,
// "Networked Transport of RTCM via Internet Protocol": version 1.0, and 2.0 which is HTTP/1.1
// with chunked transfer encoding), as far as `navfuse run --corrections` needs it: the request
// for one mountpoint, the caster's answer, and the de-chunking of a 2.0 data stream.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::apps {

// --corrections SOURCE: ntrip://... (port 2101, version 2 by default) or tcp://HOST:PORT (raw
// correction bytes, no protocol). Options after '?', joined by '&': version=1|2 (NTRIP), and
// gga=SECONDS, how often the rover's position goes upstream as an NMEA GGA sentence (network RTK,
// VRS; 0 or absent: never).
inline constexpr std::string_view kCorrectionsSourceForms =
    "ntrip://[USER[:PASSWORD]@]HOST[:PORT]/MOUNT[?version=1|2&gga=SECONDS] or tcp://HOST:PORT[?gga=SECONDS]";

struct CorrectionsSource {
  std::string text;  // as given, with the password masked (for messages)
  bool ntrip = false;
  int version = 2;
  std::string host;
  std::uint16_t port = 0;
  std::string mount;
  std::string user, password;
  double gga_interval_s = 0.0;  // 0: no GGA uploads
};

// Throws CommandError with a one-line reason.
CorrectionsSource parse_corrections_source(const std::string& argument);

// The request for source.mount (NTRIP 1.0: GET ... HTTP/1.0; 2.0: HTTP/1.1 with Ntrip-Version).
// With the rover's position `gga` (one NMEA sentence with its CR LF; empty: none known yet), 2.0
// carries it in the Ntrip-GGA header and 1.0 sends it right after the request's blank line.
// Later uploads are the bare sentence on the same connection, for both versions.
std::string ntrip_request(const CorrectionsSource& source, std::string_view gga = {});

// What the caster answered, once its header is complete.
struct NtripAnswer {
  bool ok = false;
  bool chunked = false;        // 2.0 data in HTTP chunks
  std::size_t header_bytes = 0;  // the data starts after these
  std::string reason;          // why not ok, one line
};
// nullopt while the header is incomplete (more bytes needed). Throws nothing: a damaged or
// oversized header is an answer that is not ok.
std::optional<NtripAnswer> parse_ntrip_answer(std::string_view head, const std::string& mount);

// HTTP/1.1 chunked transfer coding (RFC 9112 section 7.1) undone, across reads of any size.
class ChunkedDecoder {
 public:
  // Appends the data carried by `bytes` to `out`; false on a malformed stream (then stays failed).
  bool feed(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& out);
  bool ended() const { return state_ == State::kEnded; }

 private:
  enum class State { kSize, kSizeExtension, kSizeLf, kData, kDataCr, kDataLf, kEnded, kFailed };
  State state_ = State::kSize;
  std::uint64_t remaining_ = 0;
  int size_digits_ = 0;
};

}  // namespace navfuse::apps
