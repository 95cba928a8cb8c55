#include "apps/run/fe_device_status.hpp"

#include <algorithm>
#include <cmath>

#include "apps/run/build_info.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/from_core.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

constexpr double kRadPerSecondToDegPerHour = rot::kRadToDeg * 3600.0;

}  // namespace

std::uint8_t completion_half_percent(double sigma, double sigma0) {
  if (!(sigma0 > 0.0) || !std::isfinite(sigma)) return 0;
  const double done = std::clamp(1.0 - sigma / sigma0, 0.0, 1.0);
  return static_cast<std::uint8_t>(std::lround(200.0 * done));
}

bool FeDeviceStatus::mounting_estimated(const NavSolution& s) const {
  return imu_.estimate_mounting && (s.header.valid & NavSolution::kValidBiases) != 0 &&
         s.calibration.mount_pitch_yaw_rad.estimated;
}

void FeDeviceStatus::update(const NavSolution& s) {
  const std::int64_t t = s.header.time_ns;
  if (have_last_ && t > last_time_ns_ && mounting_estimated(s) && (s.header.valid & NavSolution::kValidVelocity) != 0) {
    travel_m_ += s.vel_ned_mps.head<2>().norm() * static_cast<double>(t - last_time_ns_) * 1e-9;
  }
  last_time_ns_ = t;
  have_last_ = true;
}

fe::CalibrationStatusMessage FeDeviceStatus::calibration(const NavSolution& s) const {
  fe::CalibrationStatusMessage m;
  m.p1_time = fe::p1_time_of(s.header);
  m.ypr_deg = {fe::kNanF, fe::kNanF, fe::kNanF};
  m.ypr_std_deg = {fe::kNanF, fe::kNanF, fe::kNanF};
  m.min_travel_distance_m = fe::kNanF;
  m.max_ypr_std_deg = {fe::kNanF, fe::kNanF, fe::kNanF};
  m.travel_distance_m = static_cast<float>(travel_m_);
  m.state_verified = s.mode == NavMode::kNavigation || s.mode == NavMode::kDeadReckoning ? 1 : 0;
  if ((s.header.valid & NavSolution::kValidBiases) != 0) {
    m.gyro_bias_half_percent =
        completion_half_percent(s.gyro_bias_std_rps.maxCoeff() * kRadPerSecondToDegPerHour, imu_.initial_gyro_bias_std_deg_hr);
    m.accel_bias_half_percent = completion_half_percent(s.accel_bias_std_mps2.maxCoeff(), imu_.initial_accel_bias_std_mps2);
  }
  if (mounting_estimated(s)) {
    const auto& mount = s.calibration.mount_pitch_yaw_rad;  // pitch, yaw
    m.calibration_stage = static_cast<std::uint8_t>(fe::CalibrationStage::kMountingAngle);
    m.ypr_deg[0] = static_cast<float>(mount.value[1] * rot::kRadToDeg);
    m.ypr_deg[1] = static_cast<float>(mount.value[0] * rot::kRadToDeg);
    m.ypr_std_deg[0] = static_cast<float>(mount.std[1] * rot::kRadToDeg);
    m.ypr_std_deg[1] = static_cast<float>(mount.std[0] * rot::kRadToDeg);
    m.mounting_half_percent = completion_half_percent(mount.std.maxCoeff() * rot::kRadToDeg, imu_.initial_mounting_std_deg);
  } else {
    m.calibration_stage = static_cast<std::uint8_t>(fe::CalibrationStage::kUnknown);
  }
  return m;
}

fe::SystemStatusMessage FeDeviceStatus::system(const NavSolution& s) {
  fe::SystemStatusMessage m;  // temperatures: navfuse measures none, 0x7FFF (L2485)
  m.p1_time = fe::p1_time_of(s.header);
  return m;
}

fe::VersionStrings FeDeviceStatus::versions() {
  fe::VersionStrings v;
  v.firmware = build_description();
  v.os = host_os_description();
  return v;
}

fe::EventNotificationMessage FeDeviceStatus::event(fe::EventType type, std::uint64_t flags, std::string description,
                                                   std::int64_t system_time_ns) {
  fe::EventNotificationMessage m;
  m.event_type = static_cast<std::uint8_t>(type);
  m.system_time_ns = system_time_ns;
  m.event_flags = flags;
  m.description = std::move(description);
  return m;
}

}  // namespace navfuse::apps
