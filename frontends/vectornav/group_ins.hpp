// INS group (group bit 5; ICD Table 2.75, L1656-1831; digest §5.6).
#pragma once

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/field_io.hpp"
#include "frontends/vectornav/ins_status.hpp"

namespace navfuse::frontends::vectornav {

namespace ins_names {
inline constexpr Names3 kPosLla = {"lat_deg", "lon_deg", "height_m"};
inline constexpr Names3 kPosEcef = {"ecef_x_m", "ecef_y_m", "ecef_z_m"};
inline constexpr Names3 kVelBody = {"vel_x_mps", "vel_y_mps", "vel_z_mps"};
inline constexpr Names3 kVelNed = {"vel_n_mps", "vel_e_mps", "vel_d_mps"};
inline constexpr Names3 kVelEcef = {"vel_ecef_x_mps", "vel_ecef_y_mps", "vel_ecef_z_mps"};
inline constexpr Names3 kMagEcef = {"mag_ecef_x_gauss", "mag_ecef_y_gauss", "mag_ecef_z_gauss"};
inline constexpr Names3 kAccelEcef = {"accel_ecef_x_mps2", "accel_ecef_y_mps2", "accel_ecef_z_mps2"};
inline constexpr Names3 kLinEcef = {"lin_accel_ecef_x_mps2", "lin_accel_ecef_y_mps2", "lin_accel_ecef_z_mps2"};
}  // namespace ins_names

// The decoded InsStatus bits, for listings (wire field: the raw word above).
inline void describe_ins_status(FieldDescriber& io, std::uint16_t raw) {
  const InsStatus s = decode_ins_status(raw);
  io.field("ins_mode", static_cast<std::uint8_t>(s.mode));
  io.field("ins_gnss_fix", static_cast<std::uint8_t>(s.gnss_fix));
  io.field("ins_imu_error", static_cast<std::uint8_t>(s.imu_error));
  io.field("ins_mag_pres_error", static_cast<std::uint8_t>(s.mag_pres_error));
  io.field("ins_gnss_error", static_cast<std::uint8_t>(s.gnss_error));
  io.field("ins_compass_fix", static_cast<std::uint8_t>(s.compass));
  io.field("ins_undocumented_bits", s.undocumented_bits);
}

template <class Io>
void visit_ins_type(unsigned bit, Io& io, InsFields& f) {
  switch (bit) {
    case ins_type::kInsStatus:
      io.field("ins_status", f.ins_status);
      if constexpr (std::is_same_v<Io, FieldDescriber>) describe_ins_status(io, f.ins_status);
      break;
    case ins_type::kPosLla: io.fields(ins_names::kPosLla, f.pos_lla); break;
    case ins_type::kPosEcef: io.fields(ins_names::kPosEcef, f.pos_ecef_m); break;
    case ins_type::kVelBody: io.fields(ins_names::kVelBody, f.vel_body_mps); break;
    case ins_type::kVelNed: io.fields(ins_names::kVelNed, f.vel_ned_mps); break;
    case ins_type::kVelEcef: io.fields(ins_names::kVelEcef, f.vel_ecef_mps); break;
    case ins_type::kMagEcef: io.fields(ins_names::kMagEcef, f.mag_ecef_gauss); break;
    case ins_type::kAccelEcef: io.fields(ins_names::kAccelEcef, f.accel_ecef_mps2); break;
    case ins_type::kLinAccelEcef: io.fields(ins_names::kLinEcef, f.lin_accel_ecef_mps2); break;
    case ins_type::kPosU: io.field("pos_std_m", f.pos_uncertainty_m); break;
    case ins_type::kVelU: io.field("vel_std_mps", f.vel_uncertainty_mps); break;
    default: break;
  }
}

}  // namespace navfuse::frontends::vectornav
