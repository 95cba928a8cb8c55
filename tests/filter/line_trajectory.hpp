// Closed-form truth for unit tests that need no simulator: a vehicle moving at constant NED
// velocity with constant attitude relative to the local NED frame (standing still when v = 0),
// optionally yawing at a constant rate. The IMU sees
//   f_b = C_bn (-g_n + (2 w_ie + w_en) x v_n)       (dv_n/dt = 0 in the NED velocity equation)
//   w_ib_b = C_bn (w_ie + w_en) + (0, 0, yaw_rate)  (the body follows the NED frame, plus yaw)
// evaluated at the interval midpoint, which is exact to O(dt^3) per interval.
#pragma once

#include <cstdint>
#include <random>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geodesy/geodesy.hpp"
#include "core/geodesy/gravity.hpp"
#include "core/measurements/measurements.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::filter::test {

struct LineTruth {
  std::int64_t time_ns = 0;
  geo::Llh llh;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();
};

class LineTrajectory {
 public:
  LineTrajectory(const geo::Llh& start, const Eigen::Vector3d& vel_ned_mps, const Eigen::Vector3d& rpy_rad,
                 double rate_hz, double yaw_rate_rps = 0.0)
      : dt_ns_(static_cast<std::int64_t>(1e9 / rate_hz + 0.5)), yaw_rate_(yaw_rate_rps) {
    truth_.time_ns = 1'000'000'000'000'000LL;
    truth_.llh = start;
    truth_.vel_ned_mps = vel_ned_mps;
    truth_.rpy_rad = rpy_rad;
  }

  const LineTruth& truth() const { return truth_; }
  double dt_s() const { return static_cast<double>(dt_ns_) * 1e-9; }

  // Constant sensor biases added to the perfect increments (vehicle = sensor frame here).
  Eigen::Vector3d gyro_bias_rps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2 = Eigen::Vector3d::Zero();

  // Advances one interval and returns the IMU increment sample that covers it.
  ImuSample next() {
    const double dt = dt_s();
    const Eigen::Vector3d v = truth_.vel_ned_mps;
    const geo::Radii r0 = geo::radii_of_curvature(truth_.llh.lat_rad);
    // Midpoint of the interval.
    geo::Llh mid = truth_.llh;
    mid.lat_rad += 0.5 * v.x() / (r0.meridian_m + mid.height_m) * dt;
    mid.lon_rad += 0.5 * v.y() / ((r0.prime_vertical_m + mid.height_m) * std::cos(mid.lat_rad)) * dt;
    mid.height_m -= 0.5 * v.z() * dt;
    Eigen::Vector3d rpy_mid = truth_.rpy_rad;
    rpy_mid.z() += 0.5 * yaw_rate_ * dt;
    const Eigen::Matrix3d c_bn = rot::dcm_from_rpy(rpy_mid).transpose();
    const Eigen::Vector3d w_ie = geo::earth_rate_ned(mid.lat_rad);
    const Eigen::Vector3d w_en = geo::transport_rate_ned(mid.lat_rad, mid.height_m, v);
    const Eigen::Vector3d g = geo::normal_gravity_ned(mid.lat_rad, mid.height_m);
    const Eigen::Vector3d f_b = c_bn * (-g + (2.0 * w_ie + w_en).cross(v));
    // Yaw about the NED down axis seen in the body frame (roll/pitch constant).
    const Eigen::Vector3d yaw_axis_b = c_bn * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d w_b = c_bn * (w_ie + w_en) + yaw_axis_b * yaw_rate_;

    // Advance the truth with midpoint rates.
    const geo::Radii rm = geo::radii_of_curvature(mid.lat_rad);
    truth_.llh.lat_rad += v.x() / (rm.meridian_m + mid.height_m) * dt;
    truth_.llh.lon_rad += v.y() / ((rm.prime_vertical_m + mid.height_m) * std::cos(mid.lat_rad)) * dt;
    truth_.llh.height_m -= v.z() * dt;
    truth_.rpy_rad.z() = rot::wrap_pi(truth_.rpy_rad.z() + yaw_rate_ * dt);
    truth_.time_ns += dt_ns_;

    ImuSample s;
    s.header.time_ns = truth_.time_ns;
    s.header.time_source = TimeSource::kGps;
    s.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
    s.quantity = ImuQuantity::kIncrements;
    s.frame = SensorFrame::kVehicle;
    s.dt_s = dt;
    s.gyro = (w_b + gyro_bias_rps) * dt;
    s.accel = (f_b + accel_bias_mps2) * dt;
    return s;
  }

 private:
  std::int64_t dt_ns_;
  double yaw_rate_;
  LineTruth truth_;
};

// A GNSS fix of the antenna at `lever_arm_m` with white noise of the given std per axis.
inline GnssPosition make_fix(const LineTruth& t, const Eigen::Vector3d& lever_arm_m, double std_m,
                             std::mt19937_64* rng) {
  Eigen::Vector3d noise = Eigen::Vector3d::Zero();
  if (rng != nullptr) {
    std::normal_distribution<double> n(0.0, std_m);
    noise = {n(*rng), n(*rng), n(*rng)};
  }
  const Eigen::Vector3d lever_n = rot::dcm_from_rpy(t.rpy_rad) * lever_arm_m;
  const geo::Llh llh = geo::llh_offset(t.llh, lever_n + noise);
  GnssPosition p;
  p.header.time_ns = t.time_ns;
  p.header.time_source = TimeSource::kGps;
  p.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
  p.lat_rad = llh.lat_rad;
  p.lon_rad = llh.lon_rad;
  p.height_m = llh.height_m;
  p.cov_ned_m2 = Eigen::Matrix3d::Identity() * std_m * std_m;
  p.fix = GnssFixType::kFix3D;
  p.num_sats = 10;
  return p;
}

inline GnssVelocity make_velocity(const LineTruth& t, double std_mps, std::mt19937_64* rng) {
  Eigen::Vector3d noise = Eigen::Vector3d::Zero();
  if (rng != nullptr) {
    std::normal_distribution<double> n(0.0, std_mps);
    noise = {n(*rng), n(*rng), n(*rng)};
  }
  GnssVelocity v;
  v.header.time_ns = t.time_ns;
  v.header.time_source = TimeSource::kGps;
  v.header.valid = GnssVelocity::kValidVelocity | GnssVelocity::kValidCovariance;
  v.vel_ned_mps = t.vel_ned_mps + noise;
  v.cov_ned_m2ps2 = Eigen::Matrix3d::Identity() * std_mps * std_mps;
  v.fix = GnssFixType::kFix3D;
  return v;
}

}  // namespace navfuse::filter::test
