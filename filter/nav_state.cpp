#include "filter/nav_state.hpp"

#include <cmath>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

void inject_error(NavState& x, const StateVector& dx) {
  const geo::Radii r = geo::radii_of_curvature(x.lat_rad);
  x.lat_rad -= dx(sx::kPos + 0) / (r.meridian_m + x.height_m);
  x.lon_rad -= dx(sx::kPos + 1) / ((r.prime_vertical_m + x.height_m) * std::cos(x.lat_rad));
  x.height_m += dx(sx::kPos + 2);  // down error: estimate too deep means height too low
  x.vel_ned_mps -= dx.segment<3>(sx::kVel);
  // C_true = (I + [phi x]) C_hat: rotate the estimate by +phi in NED.
  x.q_nb = (rot::quat_from_rotvec(dx.segment<3>(sx::kAtt)) * x.q_nb).normalized();
  x.gyro_bias_rps -= dx.segment<3>(sx::kGyroBias);
  x.accel_bias_mps2 -= dx.segment<3>(sx::kAccelBias);
  x.wheel_scale -= dx(sx::kWheelScale);
  x.mount_pitch_rad -= dx(sx::kMountPitch);
  x.mount_yaw_rad -= dx(sx::kMountYaw);
  x.gnss_lever_arm_m -= dx.segment<3>(sx::kLeverArm);
  x.gnss_time_offset_s -= dx(sx::kGnssTimeOffset);
  x.gyro_scale -= dx.segment<3>(sx::kGyroScale);
  x.accel_scale -= dx.segment<3>(sx::kAccelScale);
}

StateVector state_difference(const NavState& a, const NavState& b) {
  // inject_error, solved for dx term by term (it moves latitude first, then longitude at the new
  // latitude, both with the radii and height of `a`).
  const geo::Radii r = geo::radii_of_curvature(a.lat_rad);
  StateVector dx;
  dx(sx::kPos + 0) = (a.lat_rad - b.lat_rad) * (r.meridian_m + a.height_m);
  dx(sx::kPos + 1) = (a.lon_rad - b.lon_rad) * ((r.prime_vertical_m + a.height_m) * std::cos(b.lat_rad));
  dx(sx::kPos + 2) = b.height_m - a.height_m;
  dx.segment<3>(sx::kVel) = a.vel_ned_mps - b.vel_ned_mps;
  dx.segment<3>(sx::kAtt) = rot::rotvec_from_quat(b.q_nb * a.q_nb.conjugate());
  dx.segment<3>(sx::kGyroBias) = a.gyro_bias_rps - b.gyro_bias_rps;
  dx.segment<3>(sx::kAccelBias) = a.accel_bias_mps2 - b.accel_bias_mps2;
  dx(sx::kWheelScale) = a.wheel_scale - b.wheel_scale;
  dx(sx::kMountPitch) = a.mount_pitch_rad - b.mount_pitch_rad;
  dx(sx::kMountYaw) = a.mount_yaw_rad - b.mount_yaw_rad;
  dx.segment<3>(sx::kLeverArm) = a.gnss_lever_arm_m - b.gnss_lever_arm_m;
  dx(sx::kGnssTimeOffset) = a.gnss_time_offset_s - b.gnss_time_offset_s;
  dx.segment<3>(sx::kGyroScale) = a.gyro_scale - b.gyro_scale;
  dx.segment<3>(sx::kAccelScale) = a.accel_scale - b.accel_scale;
  return dx;
}

}  // namespace navfuse::filter
