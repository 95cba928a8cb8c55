// Simulated IMU output from the truth (see imu_model.hpp for the increment conventions).
#include "apps/sim/imu_model.hpp"

#include <cmath>
#include <stdexcept>

#include "core/geodesy/wgs84.hpp"
#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::sim {
namespace {

// Body attitude relative to the earth frame, C_eb = C_en C_nb. Relative to inertial space it is
// C_ib(t) = C_ie(t) C_eb(t), where only differences of C_ie matter (see c_body_change).
Eigen::Matrix3d c_eb(const TruthSample& s) {
  return geo::rot_ecef_from_ned(s.llh.lat_rad, s.llh.lon_rad) * s.q_nb.toRotationMatrix();
}

// C_b(a) b(t): the body attitude at `b` relative to the body frame at `a`, through inertial space.
Eigen::Matrix3d c_body_change(const Eigen::Matrix3d& c_be_a, const TruthSample& a,
                              const TruthSample& b) {
  // The earth frame turns by omega_ie dt about its z axis relative to inertial space, so
  // C_ie(t_b) = C_ie(t_a) R_z(omega_ie dt) with R_z the active rotation.
  const double angle = geo::wgs84::kEarthRate_radps * time::seconds(b.time_ns - a.time_ns);
  Eigen::Matrix3d rz;
  rz << std::cos(angle), -std::sin(angle), 0.0, std::sin(angle), std::cos(angle), 0.0, 0.0, 0.0,
      1.0;
  return c_be_a * rz * c_eb(b);
}

}  // namespace

Eigen::Vector3d inertial_delta_theta(const TruthSample& a, const TruthSample& b) {
  const Eigen::Matrix3d c = c_body_change(c_eb(a).transpose(), a, b);
  return rot::rotvec_from_quat(Eigen::Quaterniond(c).normalized());
}

ImuModel::ImuModel(const ImuSpec& spec, std::uint64_t seed)
    : spec_(spec), errors_(spec.errors, seed), vibration_(spec.vibration, seed) {
  if (!(spec_.rate_hz > 0.0) || !std::isfinite(spec_.rate_hz)) {
    throw std::invalid_argument("imu.rate_hz must be positive");
  }
  const double period_ns = 1e9 / spec_.rate_hz;
  period_ns_ = static_cast<std::int64_t>(std::llround(period_ns));
  if (std::abs(period_ns - static_cast<double>(period_ns_)) > 1e-3) {
    throw std::invalid_argument("imu.rate_hz: the period must be a whole number of nanoseconds");
  }
  if (spec_.substeps < 2 || spec_.substeps % 2 != 0) {
    throw std::invalid_argument("imu.substeps must be even and at least 2 (Simpson's rule)");
  }
  c_vs_ = rot::dcm_from_rpy(spec_.mounting_rpy_deg * rot::kDegToRad);
  if (!std::isfinite(spec_.time_offset_s) || std::abs(spec_.time_offset_s) > 1.0) {
    throw std::invalid_argument("imu.time_offset_s must be within +-1 s");
  }
  time_offset_ns_ = time::nanoseconds(spec_.time_offset_s);
}

void ImuModel::make_sample(const TruthSample* nodes, ImuSample& out) {
  const int n = spec_.substeps;
  const TruthSample& end = nodes[n];
  const double dt = time::seconds(period_ns_);
  const bool increments = spec_.quantity == ImuQuantity::kIncrements;

  Eigen::Vector3d gyro_b, accel_b;
  if (!increments) {
    gyro_b = end.omega_ib_b_rps;
    accel_b = end.f_ib_b_mps2;
  } else {
    // Composite Simpson weights 1, 4, 2, 4, ..., 4, 1 times h / 3.
    const double h = dt / n;
    const bool compensated = spec_.convention == ImuIncrements::kCompensated;
    const Eigen::Matrix3d c_be0 = c_eb(nodes[0]).transpose();
    gyro_b.setZero();
    accel_b.setZero();
    for (int j = 0; j <= n; ++j) {
      const double w = (j == 0 || j == n) ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0);
      if (compensated) {
        const Eigen::Matrix3d c_b0bj =
            j == 0 ? Eigen::Matrix3d::Identity() : c_body_change(c_be0, nodes[0], nodes[j]);
        accel_b += w * (c_b0bj * nodes[j].f_ib_b_mps2);
      } else {
        gyro_b += w * nodes[j].omega_ib_b_rps;
        accel_b += w * nodes[j].f_ib_b_mps2;
      }
    }
    accel_b *= h / 3.0;
    gyro_b = compensated ? inertial_delta_theta(nodes[0], end) : Eigen::Vector3d(gyro_b * (h / 3.0));
  }

  // Into the sensor frame (x_s = C_sv x_v), where the errors live.
  Eigen::Vector3d gyro = c_vs_.transpose() * gyro_b;
  Eigen::Vector3d accel = c_vs_.transpose() * accel_b;
  // Vibration is motion the sensor really feels: scale factors and saturation apply to it.
  vibration_.apply(increments, dt, end.speed_mps, gyro, accel);
  out.saturation = errors_.apply(increments, dt, gyro, accel);
  if (spec_.frame == SensorFrame::kVehicle) {
    gyro = c_vs_ * gyro;
    accel = c_vs_ * accel;
  }

  out.header.time_ns = stamp_ns(end.time_ns);
  out.header.time_source = TimeSource::kGps;
  out.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
  out.quantity = spec_.quantity;
  out.frame = spec_.frame;
  out.gyro = gyro;
  out.accel = accel;
  out.dt_s = dt;
  out.increments = spec_.convention;
  out.low_rate = false;
}

}  // namespace navfuse::sim
