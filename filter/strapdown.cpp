#include "filter/strapdown.hpp"

#include <cmath>

#include "core/geodesy/gravity.hpp"
#include "core/measurements/imu_increments.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::filter {

LocalEarth LocalEarth::at(double lat_rad, double height_m) {
  LocalEarth e;
  e.lat_rad = lat_rad;
  e.height_m = height_m;
  e.radii = geo::radii_of_curvature(lat_rad);
  e.gravity_ned_mps2 = geo::normal_gravity_ned(lat_rad, height_m);
  e.earth_rate_ned_rps = geo::earth_rate_ned(lat_rad);
  return e;
}

Eigen::Vector3d LocalEarth::transport_rate(const Eigen::Vector3d& v) const {
  const double re_h = radii.prime_vertical_m + height_m;
  const double rn_h = radii.meridian_m + height_m;
  return {v.y() / re_h, -v.x() / rn_h, -v.y() * std::tan(lat_rad) / re_h};
}

ImuIncrement compensate(const ImuIncrement& raw, const NavState& x) {
  // measured = (1 + s) * true + b * dt  =>  true ~= (measured - b * dt) / (1 + s).
  ImuIncrement c = raw;
  c.dtheta_rad = (raw.dtheta_rad - x.gyro_bias_rps * raw.dt_s).cwiseQuotient(
      Eigen::Vector3d::Ones() + x.gyro_scale);
  c.dvel_mps = (raw.dvel_mps - x.accel_bias_mps2 * raw.dt_s).cwiseQuotient(
      Eigen::Vector3d::Ones() + x.accel_scale);
  return c;
}

void strapdown_step(NavState& x, StrapdownMemory& mem, const ImuIncrement& imu,
                    const LocalEarth& earth) {
  const double dt = imu.dt_s;
  const Eigen::Vector3d& dth = imu.dtheta_rad;
  const Eigen::Vector3d& dv = imu.dvel_mps;
  const Eigen::Vector3d prev_dth = mem.has_prev ? mem.prev_dtheta_rad : dth;
  const Eigen::Vector3d prev_dv = mem.has_prev ? mem.prev_dvel_mps : dv;
  // Coning, rotation and sculling terms for raw integrals; a device's compensated increments
  // already hold them (ImuIncrements).
  const StartFrameIncrement body = imu.contents == ImuIncrements::kRawIntegrals
                                       ? start_frame_increment(dth, dv, prev_dth, prev_dv)
                                       : StartFrameIncrement{dth, dv};

  // Velocity: the start-frame increment, then the half-interval rotation of the n frame,
  // (I - [zeta x] / 2).
  const Eigen::Vector3d w_ie = earth.earth_rate_ned_rps;
  const Eigen::Vector3d w_en = earth.transport_rate(x.vel_ned_mps);
  const Eigen::Vector3d zeta = (w_ie + w_en) * dt;
  const Eigen::Matrix3d c_nb = x.q_nb.toRotationMatrix();
  const Eigen::Vector3d dv_f_n =
      (Eigen::Matrix3d::Identity() - 0.5 * rot::skew(zeta)) * (c_nb * body.dvel_mps);
  // Gravity and Coriolis (Groves 2nd ed. §5.4, local-navigation-frame velocity update).
  const Eigen::Vector3d dv_g =
      (earth.gravity_ned_mps2 - (2.0 * w_ie + w_en).cross(x.vel_ned_mps)) * dt;
  const Eigen::Vector3d v_old = x.vel_ned_mps;
  x.vel_ned_mps = v_old + dv_f_n + dv_g;

  // Position: trapezoidal integration of the curvilinear rates (Groves 2nd ed. §5.4).
  const Eigen::Vector3d v_mid = 0.5 * (v_old + x.vel_ned_mps);
  const double h_old = x.height_m;
  x.height_m = h_old - v_mid.z() * dt;
  const double h_mid = 0.5 * (h_old + x.height_m);
  const double lat_old = x.lat_rad;
  x.lat_rad = lat_old + v_mid.x() / (earth.radii.meridian_m + h_mid) * dt;
  const double lat_mid = 0.5 * (lat_old + x.lat_rad);
  x.lon_rad += v_mid.y() / ((earth.radii.prime_vertical_m + h_mid) * std::cos(lat_mid)) * dt;

  // Attitude: the body's rotation vector, and the rotation of the n frame over the interval.
  x.q_nb = (rot::quat_from_rotvec(-zeta) * x.q_nb * rot::quat_from_rotvec(body.phi_rad)).normalized();

  x.time_ns = imu.time_ns;
  mem.prev_dtheta_rad = dth;
  mem.prev_dvel_mps = dv;
  mem.has_prev = true;
}

}  // namespace navfuse::filter
