#include "apps/lcm/lcm_messages.hpp"

#include <cmath>

#include "apps/output/compensated_imu.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

void put(float out[3], const Eigen::Vector3d& v, double scale = 1.0) {
  for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(v[i] * scale);
}

// 1-sigma per axis from a covariance; a negative diagonal (never from a sane source) reads NaN
// rather than a plausible-looking number.
Eigen::Vector3d stds(const Eigen::Matrix3d& cov) {
  return {std::sqrt(cov(0, 0)), std::sqrt(cov(1, 1)), std::sqrt(cov(2, 2))};
}

}  // namespace

void fill_pose(const NavSolution& s, navfuse::pose_t& out) {
  out.time_gps_ns = s.header.time_ns;
  out.mode = static_cast<std::int8_t>(s.mode);
  out.gnss_fix = static_cast<std::int8_t>(s.gnss_fix);
  out.status_flags = static_cast<std::int32_t>(s.status_flags);
  out.valid = static_cast<std::int32_t>(s.header.valid);
  out.lat_deg = s.lat_rad * rot::kRadToDeg;
  out.lon_deg = s.lon_rad * rot::kRadToDeg;
  out.height_m = s.height_m;
  out.undulation_m = s.undulation_m;
  put(out.vel_ned_mps, s.vel_ned_mps);
  put(out.vel_body_mps, s.vel_body_mps);
  out.q_nb_wxyz[0] = s.q_nb.w();
  out.q_nb_wxyz[1] = s.q_nb.x();
  out.q_nb_wxyz[2] = s.q_nb.y();
  out.q_nb_wxyz[3] = s.q_nb.z();
  put(out.rpy_deg, s.rpy_rad, rot::kRadToDeg);
  put(out.pos_std_ned_m, s.pos_std_ned_m);
  put(out.vel_std_ned_mps, s.vel_std_ned_mps);
  put(out.att_std_rpy_deg, s.att_std_rpy_rad, rot::kRadToDeg);
  put(out.gyro_bias_dps, s.gyro_bias_rps, rot::kRadToDeg);
  put(out.accel_bias_mps2, s.accel_bias_mps2);
}

bool fill_imu(const NavSolution& s, navfuse::imu_t& out) {
  ImuSample imu;
  if (!compensated_imu_from(s, imu)) return false;
  out.time_gps_ns = imu.header.time_ns;
  put(out.gyro_radps, imu.gyro);
  put(out.accel_mps2, imu.accel);
  out.dt_s = 0.0f;  // rates, not increments
  return true;
}

void fill_gnss(const GnssPosition& p, const GnssVelocity* v, navfuse::gnss_t& out) {
  out.time_gps_ns = p.header.time_ns;
  out.fix = static_cast<std::int8_t>(p.fix);
  out.num_sats = static_cast<std::int8_t>(p.num_sats);
  out.receiver_id = static_cast<std::int8_t>(p.receiver_id);
  out.lat_deg = p.lat_rad * rot::kRadToDeg;
  out.lon_deg = p.lon_rad * rot::kRadToDeg;
  out.height_m = p.height_m;
  put(out.pos_std_ned_m, stds(p.cov_ned_m2));
  out.has_velocity = v != nullptr && (v->header.valid & GnssVelocity::kValidVelocity) != 0;
  if (out.has_velocity) {
    put(out.vel_ned_mps, v->vel_ned_mps);
    put(out.vel_std_ned_mps, stds(v->cov_ned_m2ps2));
  } else {
    put(out.vel_ned_mps, Eigen::Vector3d::Zero());
    put(out.vel_std_ned_mps, Eigen::Vector3d::Zero());
  }
}

}  // namespace navfuse::apps
