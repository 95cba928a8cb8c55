#include "calibration/local_frame.hpp"

#include "core/geodesy/gravity.hpp"
#include "core/geodesy/wgs84.hpp"

namespace navfuse::calib {

LocalFrame::LocalFrame(const geo::Llh& origin)
    : origin_ecef_(geo::ecef_from_llh(origin)),
      c_te_(geo::rot_ecef_from_ned(origin.lat_rad, origin.lon_rad).transpose()),
      earth_rate_(c_te_ * Eigen::Vector3d(0.0, 0.0, geo::wgs84::kEarthRate_radps)) {}

Eigen::Vector3d LocalFrame::position(const geo::Llh& llh) const {
  return position_from_ecef(geo::ecef_from_llh(llh));
}

Eigen::Vector3d LocalFrame::position_from_ecef(const Eigen::Vector3d& ecef_m) const {
  return c_te_ * (ecef_m - origin_ecef_);
}

Eigen::Matrix3d LocalFrame::rot_from_ned(const geo::Llh& llh) const {
  return c_te_ * geo::rot_ecef_from_ned(llh.lat_rad, llh.lon_rad);
}

Eigen::Vector3d LocalFrame::gravity(const geo::Llh& llh) const {
  return rot_from_ned(llh) * geo::normal_gravity_ned(llh.lat_rad, llh.height_m);
}

}  // namespace navfuse::calib
