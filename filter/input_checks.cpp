#include "filter/input_checks.hpp"

#include <cmath>

namespace navfuse::filter {
namespace {

using Reason = std::optional<RejectReason>;

bool finite(double v) { return std::isfinite(v); }
template <class Derived>
bool finite(const Eigen::MatrixBase<Derived>& v) { return v.allFinite(); }

// Uncertainties of the valid axes (bit i of `mask` = axis i) must be positive.
Reason check_std(const Eigen::Vector3d& std_v, std::uint32_t mask) {
  for (int i = 0; i < 3; ++i) {
    if ((mask & (1u << i)) != 0 && !(std_v(i) > 0.0)) return RejectReason::kNegativeStd;
  }
  return std::nullopt;
}

Reason check_cov(const Eigen::Matrix3d& cov, int rows) {
  for (int i = 0; i < rows; ++i) {
    if (!(cov(i, i) > 0.0)) return RejectReason::kNegativeStd;
  }
  return std::nullopt;
}

}  // namespace

Reason check_input(const ImuSample& m) {
  if (!finite(m.gyro) || !finite(m.accel) || !finite(m.dt_s)) return RejectReason::kNan;
  if (m.dt_s < 0.0) return RejectReason::kInvalid;
  const std::uint32_t both = ImuSample::kValidGyro | ImuSample::kValidAccel;
  if (m.header.valid != 0 && (m.header.valid & both) != both) return RejectReason::kInvalid;
  return std::nullopt;
}

Reason check_input(const GnssPosition& m) {
  if (!finite(m.lat_rad) || !finite(m.lon_rad) || !finite(m.height_m) || !finite(m.cov_ned_m2)) {
    return RejectReason::kNan;
  }
  if (std::abs(m.lat_rad) > 1.5707963267948966) return RejectReason::kInvalid;
  if ((m.header.valid & GnssPosition::kValidCovariance) != 0) {
    return check_cov(m.cov_ned_m2, (m.header.valid & GnssPosition::kValidHeight) != 0 ? 3 : 2);
  }
  return std::nullopt;
}

Reason check_input(const GnssVelocity& m) {
  if (!finite(m.vel_ned_mps) || !finite(m.cov_ned_m2ps2)) return RejectReason::kNan;
  if ((m.header.valid & GnssVelocity::kValidCovariance) != 0) return check_cov(m.cov_ned_m2ps2, 3);
  return std::nullopt;
}

Reason check_input(const GnssHeading& m) {
  if (!finite(m.heading_rad) || !finite(m.heading_std_rad)) return RejectReason::kNan;
  if ((m.header.valid & GnssHeading::kValidHeading) != 0 && !(m.heading_std_rad > 0.0)) {
    return RejectReason::kNegativeStd;
  }
  return std::nullopt;
}

Reason check_input(const WheelSpeeds& m) {
  for (double v : m.speed_mps) {
    if (!finite(v)) return RejectReason::kNan;
  }
  if (!finite(m.speed_std_mps)) return RejectReason::kNan;
  if (m.speed_std_mps < 0.0) return RejectReason::kNegativeStd;
  return std::nullopt;
}

Reason check_input(const VehicleSpeed& m) {
  if (!finite(m.speed_mps) || !finite(m.speed_std_mps)) return RejectReason::kNan;
  if (m.speed_std_mps < 0.0) return RejectReason::kNegativeStd;
  return std::nullopt;
}

Reason check_input(const WheelTicks& m) {
  if (!std::isfinite(m.period_s)) return RejectReason::kNan;
  // One counter (a vehicle odometer) or four wheels; counts inside the counter's range.
  if (m.channels != 1 && m.channels != 4) return RejectReason::kInvalid;
  const std::uint32_t channel_bits = m.channels == 1 ? WheelTicks::kValidFrontLeft : 0b1111u;
  if ((m.header.valid & channel_bits) == 0) return RejectReason::kInvalid;
  for (std::size_t i = 0; i < m.channels; ++i) {
    if (m.rollover != 0 && m.ticks[i] >= m.rollover) return RejectReason::kInvalid;
  }
  return std::nullopt;
}

Reason check_input(const ExternalPosition& m) {
  if (!finite(m.value) || !finite(m.std_m) || !finite(m.lever_arm_m)) return RejectReason::kNan;
  return check_std(m.std_m, m.header.valid);
}

Reason check_input(const ExternalVelocity& m) {
  if (!finite(m.value_mps) || !finite(m.std_mps) || !finite(m.lever_arm_m)) return RejectReason::kNan;
  return check_std(m.std_mps, m.header.valid);
}

Reason check_input(const ExternalHeading& m) {
  if (!finite(m.heading_rad) || !finite(m.std_rad)) return RejectReason::kNan;
  if ((m.header.valid & ExternalHeading::kValidHeading) != 0 && !(m.std_rad > 0.0)) {
    return RejectReason::kNegativeStd;
  }
  return std::nullopt;
}

Reason check_input(const Magnetometer& m) {
  if (!finite(m.field_gauss)) return RejectReason::kNan;
  return std::nullopt;
}

Reason check_input(const Pressure& m) {
  if (!finite(m.pressure_pa)) return RejectReason::kNan;
  // Above the Dead Sea's ~107 kPa no static pressure occurs; 0 or less is no pressure at all.
  if ((m.header.valid & Pressure::kValidPressure) != 0 && !(m.pressure_pa > 0.0 && m.pressure_pa < 120e3)) {
    return RejectReason::kInvalid;
  }
  return std::nullopt;
}


}  // namespace navfuse::filter
