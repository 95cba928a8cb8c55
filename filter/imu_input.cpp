#include "filter/imu_input.hpp"

namespace navfuse::filter {
namespace {

// Increments arriving more than this many nominal periods (ImuSample::dt_s) after the previous
// sample mean frames were lost between them: a device's sample clock jitters by far less than
// half a period.
constexpr double kLostFrameRatio = 1.5;

}  // namespace

std::optional<ImuIncrement> ImuInput::convert(const ImuSample& s) {
  const Eigen::Matrix3d c = s.frame == SensorFrame::kSensor ? c_vs_ : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d gyro = c * s.gyro;
  const Eigen::Vector3d accel = c * s.accel;
  const double since_previous_s =
      have_previous_ ? static_cast<double>(s.header.time_ns - previous_time_ns_) * 1e-9 : 0.0;
  std::optional<ImuIncrement> out;
  if (s.quantity == ImuQuantity::kIncrements) {
    double dt = s.dt_s > 0.0 ? s.dt_s : since_previous_s;
    double scale = 1.0;
    if (s.dt_s > 0.0 && since_previous_s > kLostFrameRatio * s.dt_s) {
      // Frames were lost since the previous sample (the Engine has already restarted on gaps
      // beyond max_imu_gap_s, which reset the previous sample). This sample's increments cover
      // only its own dt_s; integrating just them would drop the motion of the lost frames (1 in
      // 20 VN-300 frames lost: 12.8 m horizontal RMS against 0.81 m). Assume the rate of this
      // interval held over the whole gap and stretch the increments to it. The consequence: a
      // change of rate during the lost frames (a turn starting) is missed, an error of
      // (rate change) x (lost time) in attitude and velocity; the process noise, integrated over
      // the stretched dt, grows the covariance with the gap so the next fixes can correct it.
      scale = since_previous_s / s.dt_s;
      dt = since_previous_s;
    }
    if (dt > 0.0) out = ImuIncrement{s.header.time_ns, dt, scale * gyro, scale * accel, s.increments};
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
