#include "filter/imu_input.hpp"

namespace navfuse::filter {

std::optional<ImuIncrement> ImuInput::convert(const ImuSample& s) {
  const Eigen::Matrix3d c = s.frame == SensorFrame::kSensor ? c_vs_ : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d gyro = c * s.gyro;
  const Eigen::Vector3d accel = c * s.accel;
  const double since_previous_s =
      have_previous_ ? static_cast<double>(s.header.time_ns - previous_time_ns_) * 1e-9 : 0.0;
  std::optional<ImuIncrement> out;
  if (s.quantity == ImuQuantity::kIncrements) {
    const double dt = s.dt_s > 0.0 ? s.dt_s : since_previous_s;
    if (dt > 0.0) out = ImuIncrement{s.header.time_ns, dt, gyro, accel};
  } else if (have_previous_ && since_previous_s > 0.0) {
    const double dt = since_previous_s;
    out = ImuIncrement{s.header.time_ns, dt, 0.5 * (previous_rate_ + gyro) * dt,
                       0.5 * (previous_force_ + accel) * dt};
  }
  have_previous_ = true;
  previous_time_ns_ = s.header.time_ns;
  previous_rate_ = gyro;
  previous_force_ = accel;
  return out;
}

}  // namespace navfuse::filter
