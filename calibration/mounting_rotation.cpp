// The config key's Euler angles of the mounting the calibration found (mounting_rotation.hpp).
#include "calibration/mounting_rotation.hpp"

#include "core/rotation/rotation.hpp"

namespace navfuse::calib {

Eigen::Vector3d mounting_rpy(const Eigen::Vector2d& residual, const Eigen::Matrix3d& c_vs0) {
  return rot::rpy_from_dcm(mounting_dcm(residual.data(), c_vs0));
}

Eigen::Vector3d mounting_rpy_std(const Eigen::Vector2d& residual, const Eigen::Matrix2d& cov, const Eigen::Matrix3d& c_vs0) {
  constexpr double kStep_rad = 1e-6;
  Eigen::Matrix<double, 3, 2> j;
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d h = kStep_rad * Eigen::Vector2d::Unit(i);
    const Eigen::Vector3d d = mounting_rpy(residual + h, c_vs0) - mounting_rpy(residual - h, c_vs0);
    for (int a = 0; a < 3; ++a) j(a, i) = rot::wrap_pi(d[a]) / (2.0 * kStep_rad);
  }
  // An angle the residual does not move (the Euler roll of a sensor mounted in the vehicle axes)
  // differs only by rounding: held, std 0.
  const Eigen::Vector3d std = (j * cov * j.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();
  return std.unaryExpr([](double s) { return s < 1e-9 ? 0.0 : s; });
}

}  // namespace navfuse::calib
