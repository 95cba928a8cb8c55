// FusionEngine message structs -> core measurements (the decoding direction), with the little
// state a stream needs:
//  - the P1 -> GPS time offset, learned from any message that carries both (Pose, GNSSInfo,
//    MeasurementDetails with a GPS time source and a valid output P1 time), so that messages
//    stamped only in P1 time (IMUOutput, wheel outputs, PoseAux) get GPS times; until one is
//    seen they keep P1 time as TimeSource::kDeviceMonotonic (P1 time is "synthetic" and not
//    GPS time, spec §2.5 L233-240);
//  - the WheelConfig in force (from the front-end options or a SetConfig / ConfigResponse in the
//    stream), which gives tick rollover and direction (spec L1111-1172);
//  - the device solution of the current epoch: Pose opens it, PoseAux and GNSSInfo with the same
//    P1 time complete it (ENU velocity and its std, GPS time), and it is emitted as one
//    NavSolution (kind device_solution) when a message of another epoch arrives or at flush().
#pragma once

#include <optional>

#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/messages_ros.hpp"
#include "frontends/fusionengine/messages_sensor.hpp"
#include "frontends/fusionengine/messages_solution.hpp"

namespace navfuse::frontends::fusionengine {

// NavMode and GnssFixType of a Pose SolutionType (the inverse of solution_type_of()).
NavMode nav_mode_of(SolutionType type);
GnssFixType gnss_fix_of(SolutionType type);

// Pose 10000 alone -> NavSolution (NED/FRD, SI). Time is left to the caller.
NavSolution solution_from(const PoseMessage& pose);

class MeasurementMapper {
 public:
  using Sink = frontends::DecodeSink;

  void set_wheel_config(const WheelConfig& config) {
    wheel_config_ = config;
    wheel_config_known_ = true;
  }
  const WheelConfig& wheel_config() const { return wheel_config_; }
  // For a stream whose P1 -> GPS offset is known rather than learnt from its messages (navfuse's
  // own link, whose P1 time is its GPS time: from_core.cpp p1_time_of).
  void set_gps_minus_p1_ns(std::int64_t ns) { gps_minus_p1_ns_ = ns; }

  // One overload per message kind that carries a measurement or stream state; the decoder calls
  // whichever exists for the decoded type (shared layouts take their base struct).
  void on(const PoseMessage& m, Sink& sink);
  void on(const PoseAuxMessage& m, Sink& sink);
  void on(const GnssInfoMessage& m, Sink& sink);
  void on(const ImuOutputMessage& m, Sink& sink);
  void on(const ScaledImuLayout& m, Sink& sink);
  void on(const GnssAttitudeOutputMessage& m, Sink& sink);
  void on(const RawGnssAttitudeOutputMessage& m, Sink& sink);
  void on(const WheelTickLayout& m, Sink& sink);
  void on(const VehicleTickLayout& m, Sink& sink);
  void on(const WheelSpeedLayout& m, Sink& sink);
  void on(const VehicleSpeedLayout& m, Sink& sink);
  void on(const WheelSpeedOutputMessage& m, Sink& sink);
  void on(const VehicleSpeedOutputMessage& m, Sink& sink);
  void on(const RosGpsFixMessage& m, Sink& sink);
  void on(const SetConfigMessage& m, Sink& sink);
  void on(const ConfigResponseMessage& m, Sink& sink);

  // Emits the pending device solution, if any (end of stream).
  void flush(Sink& sink);

 private:
  MeasurementHeader header_from_p1(const Timestamp& p1) const;
  MeasurementHeader header_from_details(const MeasurementDetails& d);
  void learn_offset(const Timestamp& p1, const Timestamp& gps);
  // Emits the pending solution when `p1` belongs to another epoch.
  void close_epoch_unless(const Timestamp& p1, Sink& sink);
  void apply_config(std::uint16_t config_type, const std::vector<std::uint8_t>& value);
  void tick_rollover(WheelTicks& t, bool single_channel) const;

  std::optional<std::int64_t> gps_minus_p1_ns_;
  WheelConfig wheel_config_;
  bool wheel_config_known_ = false;
  std::optional<NavSolution> pending_;
  Timestamp pending_p1_;
};

}  // namespace navfuse::frontends::fusionengine
