// Attitude group (group bit 4; ICD Table 2.64, L1505-1654; digest §5.5).
#pragma once

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/field_io.hpp"

namespace navfuse::frontends::vectornav {

namespace attitude_names {
inline constexpr Names3 kYpr = {"yaw_deg", "pitch_deg", "roll_deg"};
inline constexpr std::array<std::string_view, 4> kQuat = {"quat_x", "quat_y", "quat_z", "quat_s"};
inline constexpr std::array<std::string_view, 9> kDcm = {"dcm00", "dcm01", "dcm02", "dcm10", "dcm11",
                                                         "dcm12", "dcm20", "dcm21", "dcm22"};
inline constexpr Names3 kMagNed = {"mag_n_gauss", "mag_e_gauss", "mag_d_gauss"};
inline constexpr Names3 kAccelNed = {"accel_n_mps2", "accel_e_mps2", "accel_d_mps2"};
inline constexpr Names3 kLinBody = {"lin_accel_x_mps2", "lin_accel_y_mps2", "lin_accel_z_mps2"};
inline constexpr Names3 kLinNed = {"lin_accel_n_mps2", "lin_accel_e_mps2", "lin_accel_d_mps2"};
inline constexpr Names3 kYprU = {"yaw_std_deg", "pitch_std_deg", "roll_std_deg"};
inline constexpr Names3 kHeave = {"heave_m", "heave_rate_mps", "delayed_heave_m"};
}  // namespace attitude_names

template <class Io>
void visit_attitude_type(unsigned bit, Io& io, AttitudeFields& f) {
  switch (bit) {
    case attitude_type::kYpr: io.fields(attitude_names::kYpr, f.ypr_deg); break;
    case attitude_type::kQuaternion: io.fields(attitude_names::kQuat, f.quaternion); break;
    case attitude_type::kDcm: io.fields(attitude_names::kDcm, f.dcm); break;
    case attitude_type::kMagNed: io.fields(attitude_names::kMagNed, f.mag_ned_gauss); break;
    case attitude_type::kAccelNed: io.fields(attitude_names::kAccelNed, f.accel_ned_mps2); break;
    case attitude_type::kLinBodyAcc: io.fields(attitude_names::kLinBody, f.lin_body_acc_mps2); break;
    case attitude_type::kLinAccelNed: io.fields(attitude_names::kLinNed, f.lin_accel_ned_mps2); break;
    case attitude_type::kYprU: io.fields(attitude_names::kYprU, f.ypr_uncertainty_deg); break;
    case attitude_type::kHeave: io.fields(attitude_names::kHeave, f.heave); break;
    case attitude_type::kAttU: io.field("att_std_deg", f.att_uncertainty_deg); break;
    default: break;
  }
}

}  // namespace navfuse::frontends::vectornav
