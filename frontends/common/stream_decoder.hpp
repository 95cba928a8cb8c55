// The interface every protocol front-end implements so that the apps (navfuse decode, replay,
// run) can drive it without knowing the protocol: bytes in, in chunks of any size; decoded
// frames and normalised core measurements out, through a sink.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "core/measurements/measurements.hpp"

namespace navfuse::frontends {

// Byte-level accounting every framer keeps. `bytes` = framed + skipped + still buffered.
struct StreamCounters {
  std::uint64_t bytes = 0;          // bytes fed
  std::uint64_t frames = 0;         // frames that passed every check
  std::uint64_t bad_frames = 0;     // frames rejected: checksum, malformed header/fields, bad length
  std::uint64_t skipped_bytes = 0;  // bytes discarded while hunting for sync (incl. bad frames')
  std::uint64_t unknown_frames = 0; // valid frames of a type the decoder does not know (framed, skipped)
  std::uint64_t decode_errors = 0;  // valid frames whose payload failed to decode (too short, bad enum...)
};

// A generic, protocol-independent view of one decoded frame, for `navfuse decode` output.
using FieldValue = std::variant<std::int64_t, std::uint64_t, double, std::string>;
struct FrameRecord {
  std::string_view protocol;  // "fe", "mip", "vn", "unicore"
  std::string name;           // e.g. "Pose", "0x80 sensor", "VNINS", "GNGGA"
  std::uint64_t offset = 0;   // byte offset of the frame's first byte in the stream
  std::vector<std::pair<std::string, FieldValue>> fields;  // in wire order, units in the names
};

class DecodeSink {
 public:
  virtual ~DecodeSink() = default;
  virtual void on_measurement(const Measurement& m) = 0;
  // Called only when wants_frames() is true (building FrameRecords costs time).
  virtual void on_frame(const FrameRecord&) {}
  virtual bool wants_frames() const { return false; }
};

class StreamDecoder {
 public:
  virtual ~StreamDecoder() = default;
  // Short protocol name: "fe", "mip", "vn", "unicore", "imutxt", "rtklib" (the INPUT prefix of
  // DESIGN.md).
  virtual std::string_view format() const = 0;
  // Feeds the next chunk of the stream. Chunks may split frames anywhere.
  virtual void feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) = 0;
  // End of stream: bytes of an incomplete trailing frame are counted as skipped.
  virtual void finish(DecodeSink& sink) = 0;
  virtual const StreamCounters& counters() const = 0;
};

// Encodes core measurements the way the device itself emits them: used by `navfuse sim` to
// write device logs from simulated truth, and by round-trip tests (decode(encode(m)) == m to the
// protocol's resolution). Stateful (sequence numbers, message counters).
class MeasurementEncoder {
 public:
  virtual ~MeasurementEncoder() = default;
  // Appends the bytes for `m` to `out`. Returns false (and appends nothing) for a measurement
  // kind this protocol cannot carry.
  virtual bool encode(const Measurement& m, std::vector<std::uint8_t>& out) = 0;
};

}  // namespace navfuse::frontends
