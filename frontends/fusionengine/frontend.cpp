#include "frontends/fusionengine/frontend.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/commands.hpp"
#include "frontends/fusionengine/decoder.hpp"
#include "frontends/fusionengine/encoder.hpp"
#include "frontends/fusionengine/framer.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

std::size_t probe(std::span<const std::uint8_t> head) {
  Framer framer;
  std::size_t frames = 0;
  framer.feed(head, [&](const Frame&) { ++frames; });
  return frames;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<FusionEngineDecoder>(); }
std::unique_ptr<MeasurementEncoder> make_encoder() { return std::make_unique<FusionEngineEncoder>(); }

}  // namespace

const FrontendInfo& frontend() {
  static const FrontendInfo info{
      .format = "fe",
      .description = "Point One FusionEngine binary (spec v0.24, protocol 1.25)",
      .probe = &probe,
      .make_decoder = &make_decoder,
      .make_encoder = &make_encoder,
      .default_profile = config::DeviceProfile::kFusionEngine,
      // A FusionEngine device streams poses and measurements by default: the set-up is the
      // installation geometry and the rates of the messages navfuse decodes (commands.hpp).
      .setup_steps = &fusion_setup_steps,
      .find_refusal = &find_refusal,
      // Device solution of a Point One GNSS/INS with corrections, 10 Hz: typical of the class,
      // not datasheet guarantees.
      .device_errors = {.horizontal_std_m = 0.5,
                        .vertical_std_m = 1.0,
                        .velocity_std_mps = 0.03,
                        .roll_pitch_std_rad = 0.05 * rot::kDegToRad,
                        .heading_std_rad = 0.2 * rot::kDegToRad,
                        .rate_hz = 10.0},
      // The wheel / vehicle speed input messages (spec §3.5) are how a host feeds odometry to a
      // Point One device.
      .odometry_input = true,
  };
  return info;
}

}  // namespace navfuse::frontends::fusionengine
