// GNSS, GNSS2 and GNSS3 groups (group bits 3, 6, 12; ICD Tables 2.35/2.90/2.119, L1131-2579;
// digest §5.4, §5.8): one layout for the three receivers.
#pragma once

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/field_io.hpp"
#include "frontends/vectornav/group_time.hpp"

namespace navfuse::frontends::vectornav {

namespace gnss_names {
inline constexpr Names3 kPosLla = {"lat_deg", "lon_deg", "height_m"};
inline constexpr Names3 kPosEcef = {"ecef_x_m", "ecef_y_m", "ecef_z_m"};
inline constexpr Names3 kVelNed = {"vel_n_mps", "vel_e_mps", "vel_d_mps"};
inline constexpr Names3 kVelEcef = {"vel_ecef_x_mps", "vel_ecef_y_mps", "vel_ecef_z_mps"};
inline constexpr Names3 kPosU = {"pos_std_n_m", "pos_std_e_m", "pos_std_d_m"};
inline constexpr std::array<std::string_view, 7> kDop = {"gdop", "pdop", "tdop", "vdop", "hdop", "ndop", "edop"};
}  // namespace gnss_names

// GnssStatus (Table 2.61, L1471-1494). Errata A12: DataSource starts at bit 8 with no stated
// width; bits 8-10 are read and only 0-3 are defined. Errata A15: "GnssStatusFlagFilterTime"
// is Reg 144's UsedForNavTime.
inline constexpr unsigned kGnssStatusDataSourceShift = 8;
inline constexpr std::uint16_t kGnssStatusDataSourceMask = 0x7;

template <class Io>
void visit_sat_info(Io& io, GnssFields& f) {
  auto count = static_cast<std::uint8_t>(f.sat_info.size());
  io.field("sat_count", count);
  io.field("sat_resv", f.sat_info_resv);
  io.resize(f.sat_info, count);
  for (std::size_t k = 0; k < f.sat_info.size(); ++k) {
    SatInfoEntry& s = f.sat_info[k];
    io.begin_element("sat", k);
    io.field("sys", s.sys);
    io.field("sv_id", s.sv_id);
    io.field("flags", s.flags);
    io.field("cno_dbhz", s.cno_dbhz);
    io.field("qi", s.qi);
    io.field("elevation_deg", s.elevation_deg);
    io.field("azimuth_deg", s.azimuth_deg);
    io.end_element();
  }
}

template <class Io>
void visit_raw_meas(Io& io, GnssFields& f) {
  io.field("raw_tow_s", f.raw_tow_s);
  io.field("raw_week", f.raw_week);
  auto count = static_cast<std::uint8_t>(f.raw_meas.size());
  io.field("raw_num_sats", count);
  io.field("raw_resv", f.raw_resv);
  io.resize(f.raw_meas, count);
  for (std::size_t k = 0; k < f.raw_meas.size(); ++k) {
    RawMeasEntry& m = f.raw_meas[k];
    io.begin_element("raw", k);
    io.field("sys", m.sys);
    io.field("sv_id", m.sv_id);
    io.field("freq", m.freq);
    io.field("chan", m.chan);
    io.field("slot", m.slot);
    io.field("cno_dbhz", m.cno_dbhz);
    io.field("flags", m.flags);
    io.field("pseudorange", m.pseudorange);  // errata A11: "cycles" per the ICD, metres in practice
    io.field("carrier_phase_cycles", m.carrier_phase_cycles);
    io.field("doppler_hz", m.doppler_hz);
    io.end_element();
  }
}

template <class Io>
void visit_gnss_type(unsigned bit, Io& io, GnssFields& f) {
  switch (bit) {
    case gnss_type::kTimeUtc: visit_utc(io, f.utc, FracSecFormat::kSigned16); break;
    case gnss_type::kGpsTow: io.field("gps_tow_ns", f.gps_tow_ns); break;
    case gnss_type::kGpsWeek: io.field("gps_week", f.gps_week); break;
    case gnss_type::kNumSats: io.field("num_sats", f.num_sats); break;
    case gnss_type::kGnssFix: io.field("fix", f.fix); break;
    case gnss_type::kPosLla: io.fields(gnss_names::kPosLla, f.pos_lla); break;
    case gnss_type::kPosEcef: io.fields(gnss_names::kPosEcef, f.pos_ecef_m); break;
    case gnss_type::kVelNed: io.fields(gnss_names::kVelNed, f.vel_ned_mps); break;
    case gnss_type::kVelEcef: io.fields(gnss_names::kVelEcef, f.vel_ecef_mps); break;
    case gnss_type::kPosUncertainty: io.fields(gnss_names::kPosU, f.pos_uncertainty_ned_m); break;
    case gnss_type::kVelUncertainty: io.field("vel_std_mps", f.vel_uncertainty_mps); break;
    case gnss_type::kTimeUncertainty: io.field("time_std_s", f.time_uncertainty_s); break;
    case gnss_type::kTimeInfo:
      io.field("time_status", f.time_status);
      io.field("leap_seconds_s", f.leap_seconds);
      break;
    case gnss_type::kDop: io.fields(gnss_names::kDop, f.dop); break;
    case gnss_type::kSatInfo: visit_sat_info(io, f); break;
    case gnss_type::kRawMeas: visit_raw_meas(io, f); break;
    case gnss_type::kStatus:
      io.field("gnss_status", f.gnss_status);
      if constexpr (std::is_same_v<Io, FieldDescriber>) {  // listing only: not a wire field
        const auto source = static_cast<std::uint8_t>((f.gnss_status >> kGnssStatusDataSourceShift) &
                                                      kGnssStatusDataSourceMask);
        io.field("gnss_status_data_source", source);
      }
      break;
    case gnss_type::kAltMsl: io.field("alt_msl_m", f.alt_msl_m); break;
    default: break;
  }
}

// GnssFix enum (Table 2.41, L1210-1221). 5 and 6 are undefined.
namespace vn_fix {
inline constexpr std::uint8_t kNoFix = 0, kTimeOnly = 1, kFix2D = 2, kFix3D = 3, kSbas = 4;
inline constexpr std::uint8_t kRtkFloat = 7, kRtkFix = 8;
}  // namespace vn_fix

}  // namespace navfuse::frontends::vectornav
