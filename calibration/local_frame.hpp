// The calibration's navigation frame: an earth-fixed tangent frame, NED at the first smoothed
// state (Groves 2nd ed. §2.1.4 "local tangent-plane frame"). Being earth-fixed it has no
// transport rate; gravity and the earth rate are known terms in it (rotated from the local NED at
// the point, so the plane's tilt away from the local vertical over a long drive is carried by
// gravity's direction, not lost).
#pragma once

#include <Eigen/Core>

#include "core/geodesy/geodesy.hpp"

namespace navfuse::calib {

class LocalFrame {
 public:
  explicit LocalFrame(const geo::Llh& origin);

  Eigen::Vector3d position(const geo::Llh& llh) const;  // tangent-frame metres
  Eigen::Vector3d position_from_ecef(const Eigen::Vector3d& ecef_m) const;
  // Rotation taking ECEF vectors into the tangent frame.
  const Eigen::Matrix3d& rot_from_ecef() const { return c_te_; }
  // Rotation taking NED vectors at `llh` into the tangent frame.
  Eigen::Matrix3d rot_from_ned(const geo::Llh& llh) const;
  // Normal gravity (gravitation plus centrifugal) at `llh`, tangent frame.
  Eigen::Vector3d gravity(const geo::Llh& llh) const;
  // Earth rotation rate, tangent frame (constant: the frame turns with the earth).
  const Eigen::Vector3d& earth_rate() const { return earth_rate_; }

 private:
  Eigen::Vector3d origin_ecef_;
  Eigen::Matrix3d c_te_;  // ECEF -> tangent
  Eigen::Vector3d earth_rate_;
};

}  // namespace navfuse::calib
