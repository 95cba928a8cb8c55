#include "apps/output/compensated_imu.hpp"

namespace navfuse::apps {

bool compensated_imu_from(const NavSolution& s, ImuSample& out) {
  if ((s.header.valid & NavSolution::kValidAttitude) == 0) return false;
  out.header.time_ns = s.header.time_ns;
  out.header.time_source = s.header.time_source;
  out.header.stream_id = s.header.stream_id;
  out.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
  out.quantity = ImuQuantity::kRates;
  out.frame = SensorFrame::kVehicle;
  out.gyro = s.angular_rate_rps;
  out.accel = s.linear_accel_mps2 - s.q_nb.conjugate() * s.gravity_ned_mps2;
  out.dt_s = 0.0;
  return true;
}

}  // namespace navfuse::apps
