#include "frontends/vectornav/decoder.hpp"

#include "frontends/vectornav/binary_codec.hpp"

namespace navfuse::frontends::vectornav {
namespace {
constexpr std::string_view kProtocol = "vn";
constexpr std::string_view kBinaryName = "binary";
constexpr std::string_view kSplitName = "binary_split";
constexpr std::string_view kVectorNavPrefix = "VN";
}  // namespace

std::string_view to_string(DecodeIssue issue) {
  switch (issue) {
    case DecodeIssue::kAsciiFields: return "ascii_fields";
    case DecodeIssue::kBinaryContent: return "binary_content";
    case DecodeIssue::kSplitSequence: return "split_sequence";
    case DecodeIssue::kSplitBody: return "split_body";
    case DecodeIssue::kCount: break;
  }
  return "unknown";
}

VnStreamDecoder::VnStreamDecoder(const DecoderOptions& options)
    : options_(options), binary_(clock_, options_), ascii_(clock_, options_) {
  record_.protocol = kProtocol;
}

void VnStreamDecoder::count(DecodeIssue issue) {
  ++framer_.counters().decode_errors;
  ++issues_[static_cast<std::size_t>(issue)];
}

void VnStreamDecoder::feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) {
  framer_.feed(bytes, [&](const Frame& f) { on_frame(f, sink); });
}

void VnStreamDecoder::finish(DecodeSink& sink) {
  framer_.finish([&](const Frame& f) { on_frame(f, sink); });
  if (split_.abandon()) count(DecodeIssue::kSplitSequence);
}

void VnStreamDecoder::on_frame(const Frame& frame, DecodeSink& sink) {
  switch (frame.kind) {
    case FrameKind::kBinary:
      on_binary(frame.bytes.subspan(1, frame.bytes.size() - 1 - kCrcBytes), frame.offset, kBinaryName, sink);
      break;
    case FrameKind::kSplit: on_split(frame, sink); break;
    case FrameKind::kAscii: on_ascii(frame, sink); break;
  }
}

void VnStreamDecoder::on_binary(std::span<const std::uint8_t> body, std::uint64_t offset, std::string_view name,
                                DecodeSink& sink) {
  if (!decode_binary_body(body, message_)) {
    count(DecodeIssue::kSplitBody);  // only reassembled bodies can fail: framed ones were measured
    return;
  }
  if (binary_.map(message_, sink) > 0) count(DecodeIssue::kBinaryContent);
  if (sink.wants_frames()) {
    record_.name = std::string(name);
    record_.offset = offset;
    record_.fields.clear();
    describe_binary_message(message_, record_);
    sink.on_frame(record_);
  }
}

void VnStreamDecoder::on_split(const Frame& frame, DecodeSink& sink) {
  const SplitPacketHeader& h = *frame.split;
  const auto payload = frame.bytes.subspan(1 + kSplitHeaderBytes, h.payload_bytes);
  const SplitReassembler::Result result = split_.add(h, payload);
  if (split_.packets() == 1) split_offset_ = frame.offset;  // this packet started a message
  switch (result) {
    case SplitReassembler::Result::kPending:
    case SplitReassembler::Result::kIgnored: break;
    case SplitReassembler::Result::kAbandoned: count(DecodeIssue::kSplitSequence); break;
    case SplitReassembler::Result::kComplete: on_binary(split_.body(), split_offset_, kSplitName, sink); break;
  }
}

void VnStreamDecoder::on_ascii(const Frame& frame, DecodeSink& sink) {
  const SentenceCheck check = check_sentence(frame.bytes);
  const std::string_view body = check.body;
  const bool vectornav = body.starts_with(kVectorNavPrefix);
  if (!vectornav || !parse_sentence(body, true, sentence_)) {
    if (vectornav) {
      count(DecodeIssue::kAsciiFields);
    } else {
      ++framer_.counters().unknown_frames;
    }
    return;
  }
  FrameRecord* record = nullptr;
  if (sink.wants_frames()) {
    record_.offset = frame.offset;
    record_.fields.clear();
    record = &record_;
  }
  switch (ascii_.handle(sentence_, sink, record)) {
    case AsciiOutcome::kDecoded:
      if (record) sink.on_frame(*record);
      break;
    case AsciiOutcome::kUnknown: ++framer_.counters().unknown_frames; break;
    case AsciiOutcome::kError: count(DecodeIssue::kAsciiFields); break;
  }
}

}  // namespace navfuse::frontends::vectornav
