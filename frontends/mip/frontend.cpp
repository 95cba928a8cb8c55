#include "frontends/mip/frontend.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/commands_geometry.hpp"
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/encoder.hpp"
#include "frontends/mip/framer.hpp"

namespace navfuse::frontends::mip {
namespace {

std::size_t probe(std::span<const std::uint8_t> head) {
  Framer framer;
  framer.feed(head, [](const PacketView&) {});
  return framer.counters().frames;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<MipDecoder>(); }
std::unique_ptr<MeasurementEncoder> make_encoder() { return std::make_unique<MipEncoder>(); }

}  // namespace

const FrontendInfo& frontend() {
  static const FrontendInfo info{
      .format = "mip",
      .description = "MicroStrain MIP (3DM-CV7): sensor, filter, GNSS data and 0x13 aiding",
      .probe = &probe,
      .make_decoder = &make_decoder,
      .make_encoder = &make_encoder,
      .default_profile = config::DeviceProfile::kCv7,
      .setup_steps = &cv7_setup_steps,
      .find_refusal = &find_refusal,
      // 3DM-CV7-INS, single antenna, INS output with the IMU: typical of the class, not datasheet
      // guarantees.
      .device_errors = {.roll_pitch_std_rad = 0.1 * rot::kDegToRad,
                        .heading_std_rad = 0.5 * rot::kDegToRad,
                        .rate_is_imu_rate = true},
  };
  return info;
}

}  // namespace navfuse::frontends::mip
