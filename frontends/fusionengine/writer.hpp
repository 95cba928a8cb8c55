// FusionEngine writer: frames any catalogue message (header, sequence number, CRC) and offers
// one-call helpers for everything navfuse outputs (Pose, PoseAux, GNSSInfo, IMUOutput,
// GNSSAttitudeOutput, VehicleSpeedOutput, ...), for the apps' --fe-out and the nav process.
//
// Sequence numbers: "incremented with each message" (spec L190), one counter per writer, so
// use one writer per output stream.
// Source identifier: "0 for measurement input messages, or 0xFFFFFFFF (invalid) for
// non-measurement messages" (spec L193). The five input messages (spec §3.5) get 0, every
// other message 0xFFFFFFFF. The spec's own command examples use 0 (digest §13 A14); pass
// FrameOptions::source_id to reproduce them.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/measurements/measurements.hpp"
#include "frontends/fusionengine/from_core.hpp"
#include "frontends/fusionengine/message_catalog.hpp"
#include "frontends/fusionengine/payload_writer.hpp"

namespace navfuse::frontends::fusionengine {

// Per-frame overrides of the header fields the writer normally fills in.
struct FrameOptions {
  std::optional<std::uint32_t> source_id;        // default: by message kind, see above
  std::optional<std::uint8_t> message_version;   // default: the struct's kVersion
  std::optional<std::uint32_t> sequence;         // default: the writer's next number (not consumed)

  static FrameOptions with_source_id(std::uint32_t id) {
    FrameOptions o;
    o.source_id = id;
    return o;
  }
};

// Default header source identifier of a message type (spec L193).
std::uint32_t default_source_id(std::uint16_t message_type);

// Frame assembly: begin_frame() appends the 24-byte header (sync, reserved 0, protocol version
// 2, the given fields; size and CRC zero) and `payload_bytes` zero bytes for a payload written in
// place, and returns the header's offset; after the payload has been written or appended,
// end_frame() fills in the payload size and the CRC over [8, end) (spec §2.4 L197-229).
std::size_t begin_frame(std::vector<std::uint8_t>& out, std::uint16_t message_type, std::uint8_t message_version,
                        std::uint32_t sequence, std::uint32_t source_id, std::size_t payload_bytes = 0);
void end_frame(std::vector<std::uint8_t>& out, std::size_t start);

class FusionEngineWriter {
 public:
  // Appends one framed message to `out`.
  template <class M>
  void append(M msg, std::vector<std::uint8_t>& out, const FrameOptions& options = {}) {
    if constexpr (requires { msg.sync_lengths(); }) msg.sync_lengths();
    std::uint32_t sequence = next_sequence_;
    if (options.sequence) {
      sequence = *options.sequence;
    } else {
      ++next_sequence_;
    }
    const std::uint16_t type = to_u16(M::kType);
    const std::uint8_t version = options.message_version.value_or(M::kVersion);
    const std::uint32_t source_id = options.source_id.value_or(default_source_id(type));
    // The payload is measured first (the same visit, counting), the frame grows once, and the
    // fields are written in place: a pose output per IMU sample writes ~100 fields per epoch,
    // and one vector insert each was a tenth of the output thread's work.
    BasicPayloadWriter<bytes::ByteCounter> counter{bytes::ByteCounter{}};
    msg.visit(counter);
    std::size_t payload_bytes = counter.sink().written();
    if constexpr (requires { msg.padding(); }) payload_bytes += msg.padding();  // zeros, as grown
    const std::size_t start = begin_frame(out, type, version, sequence, source_id, payload_bytes);
    PayloadSpanWriter w(bytes::LeSpanWriter({out.data() + start + kHeaderSize, payload_bytes}));
    msg.visit(w);
    end_frame(out, start);
  }
  // One framed message in the writer's own buffer (valid until the next call).
  template <class M>
  const std::vector<std::uint8_t>& frame(M msg, const FrameOptions& options = {}) {
    buffer_.clear();
    append(std::move(msg), buffer_, options);
    return buffer_;
  }

  // navfuse outputs (DESIGN.md --fe-out). Each returns the writer's buffer with one frame.
  const std::vector<std::uint8_t>& pose(const NavSolution& s) { return frame(pose_from(s)); }
  const std::vector<std::uint8_t>& pose_aux(const NavSolution& s) { return frame(pose_aux_from(s)); }
  const std::vector<std::uint8_t>& gnss_info(const NavSolution& s, std::uint8_t num_svs = 0,
                                             float hdop = kNanF, float vdop = kNanF) {
    return frame(gnss_info_from(s, num_svs, hdop, vdop));
  }
  // Empty when the sample cannot be expressed (sensor frame, or increments without dt).
  const std::vector<std::uint8_t>& imu_output(const ImuSample& imu);
  const std::vector<std::uint8_t>& gnss_attitude(const GnssHeading& h) { return frame(gnss_attitude_from(h)); }
  const std::vector<std::uint8_t>& vehicle_speed_output(const VehicleSpeed& v) {
    return frame(vehicle_speed_output_from(v));
  }
  const std::vector<std::uint8_t>& command_response(std::uint32_t command_sequence, Response code) {
    return frame(CommandResponseMessage{command_sequence, static_cast<std::uint8_t>(code)});
  }

  std::uint32_t next_sequence() const { return next_sequence_; }
  void set_next_sequence(std::uint32_t sequence) { next_sequence_ = sequence; }

 private:
  std::uint32_t next_sequence_ = 0;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace navfuse::frontends::fusionengine
