// Turns checked ASCII sentences into FrameRecords and core measurements: asynchronous outputs
// (digest §2.6), register read/write replies (same layouts, §2.8), $VNERR errors (§2.5) and
// command echoes (§2.4).
#pragma once

#include <string_view>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/ascii_sentence.hpp"
#include "frontends/vectornav/decoder_options.hpp"
#include "frontends/vectornav/stream_clock.hpp"

namespace navfuse::frontends::vectornav {

enum class AsciiOutcome : std::uint8_t {
  kDecoded,  // a VectorNav sentence this decoder understands
  kUnknown,  // valid, but not a VectorNav sentence it knows (e.g. NMEA from Reg 101/102)
  kError,    // a known sentence whose fields do not parse (wrong count, not a number)
};

// System error codes (Table 1.7, L645-666) by name; "unknown" for other codes.
std::string_view vn_error_name(unsigned code);

class AsciiMapper {
 public:
  AsciiMapper(StreamClock& clock, const DecoderOptions& options) : clock_(clock), options_(options) {}
  // `record` (may be null) receives the sentence's fields.
  AsciiOutcome handle(const AsciiSentence& s, DecodeSink& sink, FrameRecord* record);

 private:
  AsciiOutcome handle_register(int id, std::span<const std::string_view> values, DecodeSink& sink,
                               FrameRecord* record);
  bool map_register(int id, std::span<const double> v, DecodeSink& sink);

  StreamClock& clock_;
  DecoderOptions options_;
};

}  // namespace navfuse::frontends::vectornav
