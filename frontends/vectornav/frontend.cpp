#include "frontends/vectornav/frontend.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/vectornav/commands.hpp"
#include "frontends/vectornav/commands_geometry.hpp"
#include "frontends/vectornav/decoder.hpp"
#include "frontends/vectornav/encoder.hpp"
#include "frontends/vectornav/framer.hpp"

namespace navfuse::frontends::vectornav {
namespace {
constexpr std::string_view kAsciiVectorNav = "$VN";
}  // namespace

std::size_t probe_vectornav(std::span<const std::uint8_t> head) {
  PortFramer framer;
  std::size_t count = 0;
  auto on_frame = [&](const Frame& f) {
    if (f.kind != FrameKind::kAscii) {
      ++count;
      return;
    }
    const std::string_view text(reinterpret_cast<const char*>(f.bytes.data()), f.bytes.size());
    if (text.starts_with(kAsciiVectorNav)) ++count;
  };
  framer.feed(head, on_frame);
  return count;
}

const FrontendInfo& frontend() {
  static const FrontendInfo info{
      .format = "vn",
      .description = "VectorNav VN-300 binary (0xFA/0xFB) and ASCII ($VN) output",
      .probe = &probe_vectornav,
      .make_decoder = []() -> std::unique_ptr<StreamDecoder> { return std::make_unique<VnStreamDecoder>(); },
      .make_encoder = []() -> std::unique_ptr<MeasurementEncoder> { return std::make_unique<VnMeasurementEncoder>(); },
      .default_profile = config::DeviceProfile::kVn300,
      .setup_steps = &cmd::fusion_setup_steps,
      .find_refusal = &cmd::find_refusal,
      // VN-300, dual antenna, industrial MEMS, INS output with the IMU: typical of the class, not
      // datasheet guarantees.
      .device_errors = {.roll_pitch_std_rad = 0.05 * rot::kDegToRad,
                        .heading_std_rad = 0.2 * rot::kDegToRad,
                        .rate_is_imu_rate = true},
      .imu_increments = ImuIncrements::kCompensated,
  };
  return info;
}

}  // namespace navfuse::frontends::vectornav
