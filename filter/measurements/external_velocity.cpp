#include "core/geodesy/geodesy.hpp"
#include "filter/measurements/external_aiding.hpp"
#include "filter/measurements/gnss_velocity.hpp"

namespace navfuse::filter {

Observation external_velocity_observation(const StateView& s, const ExternalVelocity& m) {
  Observation obs(3);
  switch (m.frame) {
    case VelocityFrame::kNed:
      obs = antenna_velocity_observation(s, m.lever_arm_m, m.value_mps, false);
      break;
    case VelocityFrame::kEcef: {
      // Compare in NED, then rotate residual and Jacobian into ECEF axes (v_e = C_en v_n).
      const Eigen::Matrix3d c_en = geo::rot_ecef_from_ned(s.x.lat_rad, s.x.lon_rad);
      obs = antenna_velocity_observation(s, m.lever_arm_m, c_en.transpose() * m.value_mps, false);
      obs.residual = (c_en * obs.residual).eval();
      obs.h = (c_en * obs.h).eval();
      break;
    }
    case VelocityFrame::kVehicle: {
      const BodyVelocityModel v = body_velocity_at(s, m.lever_arm_m, false);
      obs.residual = v.vel_mps - m.value_mps;
      obs.h = v.jacobian;
      break;
    }
  }
  obs.r.setZero();
  obs.r.diagonal() = m.std_mps.array().square().matrix();
  obs.keep_rows(m.header.valid & 0b111u);
  return obs;
}

}  // namespace navfuse::filter
