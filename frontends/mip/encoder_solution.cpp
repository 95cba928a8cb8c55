#include "frontends/mip/encoder_solution.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/mip/filter_status.hpp"
#include "frontends/mip/protocol.hpp"
#include "frontends/mip/time_fields.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

void vec3f(bytes::BeWriter& w, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(v[i]));
}
// 0x82 vectors: vector3f + u16 valid (0 invalid, 1 valid; L4191).
void vec_field(PacketWriter& pw, std::uint8_t desc, const Eigen::Vector3d& v, bool valid) {
  auto& w = pw.field(desc);
  vec3f(w, v);
  w.u16(valid ? filter::kValid : 0);
}

}  // namespace

std::size_t encode_solution(const NavSolution& s, std::vector<std::uint8_t>& out) {
  const std::uint32_t v = s.header.valid;
  const bool pos = v & NavSolution::kValidPosition;
  const bool vel = v & NavSolution::kValidVelocity;
  const bool att = v & NavSolution::kValidAttitude;
  const bool biases = v & NavSolution::kValidBiases;
  PacketWriter pw(out, set::kFilter);
  // Shared timestamp first so continuation packets repeat it (L4002-4024).
  write_time_fields(s.header, pw);
  const FilterStatusWord st = status_from_solution(s);
  {
    auto& w = pw.field(filter::kStatus);
    w.u16(st.filter_state);
    w.u16(st.dynamics_mode);
    w.u16(st.status_flags);
  }
  {
    auto& w = pw.field(filter::kLlh);
    w.f64(s.lat_rad * rot::kRadToDeg);
    w.f64(s.lon_rad * rot::kRadToDeg);
    w.f64(s.height_m);
    w.u16(pos ? filter::kValid : 0);
  }
  vec_field(pw, filter::kVelNed, s.vel_ned_mps, vel);
  {
    auto& w = pw.field(filter::kQuaternion);  // (w,x,y,z), q_nb (digest §6.1)
    w.f32(static_cast<float>(s.q_nb.w()));
    w.f32(static_cast<float>(s.q_nb.x()));
    w.f32(static_cast<float>(s.q_nb.y()));
    w.f32(static_cast<float>(s.q_nb.z()));
    w.u16(att ? filter::kValid : 0);
  }
  vec_field(pw, filter::kEuler, s.rpy_rad, att);
  vec_field(pw, filter::kGyroBias, s.gyro_bias_rps, biases);
  vec_field(pw, filter::kAccelBias, s.accel_bias_mps2, biases);
  vec_field(pw, filter::kLlhUnc, s.pos_std_ned_m, v & NavSolution::kValidPositionStd);
  vec_field(pw, filter::kVelUnc, s.vel_std_ned_mps, v & NavSolution::kValidVelocityStd);
  vec_field(pw, filter::kEulerUnc, s.att_std_rpy_rad, v & NavSolution::kValidAttitudeStd);
  vec_field(pw, filter::kGyroBiasUnc, s.gyro_bias_std_rps, biases);
  vec_field(pw, filter::kAccelBiasUnc, s.accel_bias_std_mps2, biases);
  vec_field(pw, filter::kLinearAccel, s.linear_accel_mps2, att);
  vec_field(pw, filter::kCompAngularRate, s.angular_rate_rps, att);
  // Gravity is reported in the vehicle frame (L4445): g_vehicle = q_nb^-1 g_ned.
  vec_field(pw, filter::kGravity, s.q_nb.conjugate() * s.gravity_ned_mps2, att);
  return pw.finish();
}

}  // namespace navfuse::frontends::mip
