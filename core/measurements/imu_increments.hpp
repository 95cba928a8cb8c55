// From raw IMU increments (ImuIncrements::kRawIntegrals: time integrals of the rate and the
// specific force in the moving sensor frame) to what a device's compensated increments already
// are: the rotation vector of the attitude change, and the velocity change in the body frame at
// the interval's start. The strapdown (filter/strapdown.cpp) and the calibration's
// preintegration (calibration/calibration_epochs.cpp) both take the latter.
#pragma once

#include <Eigen/Core>

namespace navfuse {

struct StartFrameIncrement {
  Eigen::Vector3d phi_rad;   // attitude change, rotation vector
  Eigen::Vector3d dvel_mps;  // velocity change, body frame at the interval's start
};

// Two-sample coning (Savage 1998 part 1), rotation and two-sample sculling (part 2) with the
// previous interval's raw increments, as in Shin 2005 §2.2. Pass this interval's own increments
// as the previous ones when there is none.
inline StartFrameIncrement start_frame_increment(const Eigen::Vector3d& dtheta_rad, const Eigen::Vector3d& dvel_mps,
                                                 const Eigen::Vector3d& prev_dtheta_rad,
                                                 const Eigen::Vector3d& prev_dvel_mps) {
  const Eigen::Vector3d rotation = 0.5 * dtheta_rad.cross(dvel_mps);
  const Eigen::Vector3d sculling = (prev_dtheta_rad.cross(dvel_mps) + prev_dvel_mps.cross(dtheta_rad)) / 12.0;
  return {dtheta_rad + prev_dtheta_rad.cross(dtheta_rad) / 12.0, dvel_mps + rotation + sculling};
}

}  // namespace navfuse
