// MeasurementEncoder for MIP: writes core measurements the way a CV7 emits them, so that
// `navfuse sim` writes realistic CV7 logs and decode(encode(m)) reproduces m to MIP resolution
// (float32 vectors, float64 positions and times).
//   ImuSample      -> 0x80: D3 (+D6 period) + 0x04/0x05 (rates, m/s^2 -> g) or 0x07/0x08
//                     (increments, m/s -> g*s), + 0x18 over-range from the saturation bits
//   Magnetometer   -> 0x80: D3 + 0x06;  Pressure -> 0x80: D3 + 0x17 (Pa -> mbar)
//   VehicleSpeed   -> 0x80: D3 + 0x40 odometer (signed speed, 1-sigma, configured flag)
//   GnssPosition   -> 0x91 / 0x92 / 0x94 by receiver_id 0 / 1 / 2: D3 + 0x03 LLH + 0x0B fix
//   GnssVelocity   -> same sets: D3 + 0x05 NED velocity + 0x0B fix
//   GnssHeading    -> 0x82: D3 + 0x49 dual-antenna status
//   NavSolution    -> 0x82 filter packets (encoder_solution.hpp)
//   ExternalPosition / ExternalVelocity / ExternalHeading -> 0x13 aiding commands (timebase 2,
//                     GPS ns), preceded by a frame configuration when a lever arm is set
// WheelSpeeds and WheelTicks have no MIP carrier: encode() returns false for them.
#pragma once

#include <memory>
#include <vector>

#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::mip {

class MipEncoder final : public MeasurementEncoder {
 public:
  bool encode(const Measurement& m, std::vector<std::uint8_t>& out) override;
};

}  // namespace navfuse::frontends::mip
