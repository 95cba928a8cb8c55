// The status a Point One device reports about itself, from navfuse's real state, for the
// device-emulating --fe-out link (apps/run/fe_device_emulator): CalibrationStatus 10004 (spec
// §3.3.5 L1876-1919), SystemStatus 10500 (§3.7.1 L2473-2486), VersionInfo 13003 (§3.7.3) and
// EventNotification 13004 (§3.7.4 L2615-2642). A field navfuse has no value for carries the
// spec's invalid value (0x7FFF temperatures, L2485) or, for floats, NaN (the spec's implied
// convention, digest "invalid values").
//
// CalibrationStatus, field by field:
//   stage            Mounting Angle while the filter estimates the residual mounting
//                    (imu.estimate_mounting) and its states are valid; Unknown otherwise. Never
//                    Done: navfuse keeps estimating and has no completion threshold.
//   yaw/pitch        the residual IMU-to-vehicle yaw and pitch on top of imu.mounting_rpy_deg
//                    ("mounting angle offset", L1891-1892) with their 1-sigma; roll is not
//                    estimated: NaN.
//   travel distance  horizontal distance travelled while the mounting is estimated.
//   state verified   1 once the filter navigates (mode navigation or dead reckoning).
//   percents         completion in 0.5 % units (L1900-1902), defined as 1 - sigma / sigma0 of
//                    the worst axis, sigma0 the configured initial std (imu.initial_*_std_*):
//                    0 before the states are estimated, 200 if the std reached 0.
//   min travel, max std  NaN: navfuse has no such thresholds.
#pragma once

#include <cstdint>
#include <string>

#include "core/config/config.hpp"
#include "core/measurements/measurements.hpp"
#include "frontends/fusionengine/messages_solution.hpp"
#include "frontends/fusionengine/messages_status.hpp"
#include "frontends/fusionengine/responder.hpp"

namespace navfuse::apps {

class FeDeviceStatus {
 public:
  explicit FeDeviceStatus(const config::Config& config) : imu_(config.imu) {}

  // Called with every solution the link sees, in time order (accumulates the travel distance).
  void update(const NavSolution& s);

  frontends::fusionengine::CalibrationStatusMessage calibration(const NavSolution& s) const;
  static frontends::fusionengine::SystemStatusMessage system(const NavSolution& s);
  // Release and build of this binary, the host OS; no receiver version (navfuse has no
  // measurement engine of its own).
  static frontends::fusionengine::VersionStrings versions();
  // An event at host monotonic time `system_time_ns` (the P1 "system time" base, DESIGN.md:
  // arrival times are host monotonic).
  static frontends::fusionengine::EventNotificationMessage event(frontends::fusionengine::EventType type,
                                                                  std::uint64_t flags, std::string description,
                                                                  std::int64_t system_time_ns);

 private:
  bool mounting_estimated(const NavSolution& s) const;

  config::ImuConfig imu_;
  double travel_m_ = 0.0;
  std::int64_t last_time_ns_ = 0;
  bool have_last_ = false;
};

// Completion of an estimate in the spec's 0.5 % units: 200 * clamp(1 - sigma / sigma0, 0, 1).
std::uint8_t completion_half_percent(double sigma, double sigma0);

}  // namespace navfuse::apps
