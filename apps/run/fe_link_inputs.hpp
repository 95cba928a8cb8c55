// FusionEngine sensor inputs a client sends on the --fe-out link (spec §3.5: IMUInput,
// WheelSpeedInput, VehicleSpeedInput, WheelTickInput, VehicleTickInput), decoded by the
// front-end's own mapping (frontends/fusionengine/to_core.hpp) and handed to the filter as the
// same inputs from an --in FusionEngine stream would be: a device fuses what it is sent.
//
// Time, as a device takes its inputs (spec §2.6.4 L294-311): GPS time as given; P1 time is the
// link's own, which is navfuse's GPS time (frontends/fusionengine/from_core.cpp p1_time_of);
// "Invalid" or "Timestamped on Reception" takes the time of the newest epoch streamed (the
// device's clock at arrival); the Output P1 Time a sender fills in "will be ignored". Sender
// system time stays on the sender's clock, which the filter rejects as time_base.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/measurements/measurements.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/to_core.hpp"

namespace navfuse::apps {

class FeLinkInputs {
 public:
  FeLinkInputs();
  // The time of the newest epoch streamed (GPS ns): inputs without a time of their own get it.
  void set_now_ns(std::int64_t gps_ns) { now_ns_ = gps_ns; }
  // The WheelConfig a client set on the link (tick rollover and direction, spec L1111-1172).
  void set_wheel_config(const frontends::fusionengine::WheelConfig& config) { mapper_.set_wheel_config(config); }
  // Decodes `frame` when it is a sensor input, appending its measurements to `out`. Returns
  // false for any other message type. A payload too short for its layout is counted in
  // decode_errors() and yields nothing.
  bool decode(const frontends::fusionengine::Frame& frame, std::vector<Measurement>& out);
  std::uint64_t decode_errors() const { return decode_errors_; }

 private:
  frontends::fusionengine::MeasurementMapper mapper_;
  std::optional<std::int64_t> now_ns_;
  std::uint64_t decode_errors_ = 0;
};

}  // namespace navfuse::apps
