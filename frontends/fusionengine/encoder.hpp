// MeasurementEncoder for FusionEngine: writes core measurements as a Point One device emits
// them, so `navfuse sim --format fe` produces realistic logs and decode(encode(m)) == m to the
// protocol's resolution.
//
//   ImuSample (vehicle frame)   -> IMUOutput 11000 (f64, FLU body)
//   ImuSample (sensor frame)    -> RawIMUOutput 11002 (2^-16 m/s^2, 2^-20 rad/s)
//   NavSolution                 -> Pose 10000 + PoseAux 10003 (+ GNSSInfo 10001 with a GNSS fix)
//   GnssHeading                 -> GNSSAttitudeOutput 11005
//   WheelSpeeds / VehicleSpeed  -> RawWheelSpeedOutput 11125 / RawVehicleSpeedOutput 11126
//   WheelTicks (4 / 1 channel)  -> RawWheelTickOutput 11123 / RawVehicleTickOutput 11124
//   GnssPosition, GnssVelocity  -> ROSGPSFix 12010 (see from_core.hpp)
// With `sensor_inputs`, IMU and wheel data are written as the host->device input messages
// (IMUInput 11004, WheelTickInput 11103, VehicleTickInput 11104, WheelSpeedInput 11105,
// VehicleSpeedInput 11106) instead, to feed a real device.
#pragma once

#include "frontends/common/stream_decoder.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::frontends::fusionengine {

struct EncoderOptions {
  bool sensor_inputs = false;  // write input messages (§3.5) rather than raw outputs (§3.6)
};

class FusionEngineEncoder final : public frontends::MeasurementEncoder {
 public:
  explicit FusionEngineEncoder(const EncoderOptions& options = {}) : options_(options) {}
  bool encode(const Measurement& m, std::vector<std::uint8_t>& out) override;

 private:
  EncoderOptions options_;
  FusionEngineWriter writer_;
};

}  // namespace navfuse::frontends::fusionengine
