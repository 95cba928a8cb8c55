// The "vn" StreamDecoder: one VN-300 port's bytes (binary 0xFA, split 0xFB and ASCII $VN
// mixed) to FrameRecords and core measurements.
//
// Counters (frontends/common/stream_decoder.hpp): `frames` counts every checksum-valid frame
// (each 0xFB split packet is one frame); `unknown_frames` those among them that are valid but
// not VectorNav sentences (e.g. NMEA from Reg 101/102); `decode_errors` valid frames whose
// content could not be used (unparsable ASCII field, undefined enum, a split message that lost
// a packet, a reassembled message whose length disagrees with its header).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/vectornav/ascii_sentence.hpp"
#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/decoder_ascii.hpp"
#include "frontends/vectornav/decoder_options.hpp"
#include "frontends/vectornav/framer.hpp"
#include "frontends/vectornav/split_packet.hpp"
#include "frontends/vectornav/stream_clock.hpp"
#include "frontends/vectornav/to_core.hpp"

namespace navfuse::frontends::vectornav {

// Why a frame's content was not used, for reports beyond the StreamCounters totals.
enum class DecodeIssue : std::uint8_t {
  kAsciiFields,       // a known sentence whose fields do not parse
  kBinaryContent,     // undefined enum value or unusable field in a binary message
  kSplitSequence,     // a split message lost a packet
  kSplitBody,         // a reassembled split message is not a valid message body
  kCount,
};
std::string_view to_string(DecodeIssue issue);

class VnStreamDecoder final : public StreamDecoder {
 public:
  explicit VnStreamDecoder(const DecoderOptions& options = {});
  std::string_view format() const override { return "vn"; }
  void feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) override;
  void finish(DecodeSink& sink) override;
  const StreamCounters& counters() const override { return framer_.counters(); }

  // For invariant checks: bytes == framed + skipped + buffered at all times.
  std::uint64_t framed_bytes() const { return framer_.framed_bytes(); }
  std::size_t buffered_bytes() const { return framer_.buffered_bytes(); }
  std::uint64_t issues(DecodeIssue issue) const { return issues_[static_cast<std::size_t>(issue)]; }

 private:
  void on_frame(const Frame& frame, DecodeSink& sink);
  void on_binary(std::span<const std::uint8_t> body, std::uint64_t offset, std::string_view name, DecodeSink& sink);
  void on_split(const Frame& frame, DecodeSink& sink);
  void on_ascii(const Frame& frame, DecodeSink& sink);
  void count(DecodeIssue issue);

  DecoderOptions options_;
  PortFramer framer_;
  StreamClock clock_;
  BinaryMapper binary_;
  AsciiMapper ascii_;
  SplitReassembler split_;
  std::uint64_t split_offset_ = 0;
  BinaryMessage message_;
  AsciiSentence sentence_;
  FrameRecord record_;
  std::array<std::uint64_t, static_cast<std::size_t>(DecodeIssue::kCount)> issues_{};
};

}  // namespace navfuse::frontends::vectornav
