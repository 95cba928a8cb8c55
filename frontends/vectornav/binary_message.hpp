// A decoded VectorNav binary message: which types it carries (the header) and their values in
// the device's own units (degrees, Gauss, kPa, ns), one struct per group (ICD §2.2-2.9, digest §5).
// Conversion to SI happens only when mapping to core measurements (to_core.hpp).
//
// Common-group types are copies of other groups' types with identical layouts (ICD §2.2,
// L761-784), so they are stored in the referenced group's fields; the header says which group
// carried them on the wire.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "frontends/vectornav/binary_header.hpp"

namespace navfuse::frontends::vectornav {

using Vec3f = std::array<float, 3>;
using Vec3d = std::array<double, 3>;

// TimeUtc (L860-873, L1159-1172). Errata A8 (digest §10, ICD L873 vs L1172): FracSec is uint16
// in the Time group but int16 ("may be negative") in the GNSS groups; both fit this int32.
struct UtcFields {
  std::int8_t year_since_2000 = 0;
  std::uint8_t month = 0, day = 0, hour = 0, minute = 0, second = 0;
  std::int32_t frac_ms = 0;
};

struct TimeFields {  // Time group, Table 2.4
  std::uint64_t time_startup_ns = 0;
  std::uint64_t time_gps_ns = 0;
  std::uint64_t gps_tow_ns = 0;
  std::uint16_t gps_week = 0;
  std::uint64_t time_sync_in_ns = 0;
  std::uint64_t time_gps_pps_ns = 0;
  UtcFields utc;
  std::uint32_t sync_in_cnt = 0;
  std::uint32_t sync_out_cnt = 0;
  std::uint8_t time_status = 0;  // Table 2.15: bit0 TowValid, bit1 DateValid, bit2 UtcValid
};
inline constexpr std::uint8_t kTimeStatusTowValid = 1u << 0;
inline constexpr std::uint8_t kTimeStatusDateValid = 1u << 1;
inline constexpr std::uint8_t kTimeStatusUtcValid = 1u << 2;

struct ImuFields {  // IMU group, Table 2.16
  std::uint16_t imu_status = 0;
  Vec3f uncomp_mag_gauss{};
  Vec3f uncomp_accel_mps2{};
  Vec3f uncomp_gyro_rps{};
  float temperature_c = 0;
  float pressure_kpa = 0;
  float delta_time_s = 0;
  Vec3f delta_theta_deg{};  // degrees, not radians (L1054)
  Vec3f delta_vel_mps{};
  Vec3f mag_gauss{};
  Vec3f accel_mps2{};
  Vec3f angular_rate_rps{};
  std::uint16_t sens_sat = 0;  // Table 2.34
};

struct SatInfoEntry {  // GnssSatInfo element (L1321-1342)
  std::uint8_t sys = 0, sv_id = 0, flags = 0, cno_dbhz = 0, qi = 0;
  std::int8_t elevation_deg = 0;
  std::int16_t azimuth_deg = 0;
  bool operator==(const SatInfoEntry&) const = default;
};
struct RawMeasEntry {  // GnssRawMeas element (L1387-1413)
  std::uint8_t sys = 0, sv_id = 0, freq = 0, chan = 0;
  std::int8_t slot = 0;
  std::uint8_t cno_dbhz = 0;
  std::uint16_t flags = 0;
  double pseudorange = 0;  // errata A11: the ICD says "cycles"; validate before use
  double carrier_phase_cycles = 0;
  float doppler_hz = 0;
  bool operator==(const RawMeasEntry&) const = default;
};

struct GnssFields {  // GNSS, GNSS2, GNSS3 groups, Tables 2.35/2.90/2.119
  UtcFields utc;
  std::uint64_t gps_tow_ns = 0;
  std::uint16_t gps_week = 0;
  std::uint8_t num_sats = 0;
  std::uint8_t fix = 0;       // Table 2.41
  Vec3d pos_lla{};            // deg, deg, m above the ellipsoid
  Vec3d pos_ecef_m{};
  Vec3f vel_ned_mps{};
  Vec3f vel_ecef_mps{};
  Vec3f pos_uncertainty_ned_m{};
  float vel_uncertainty_mps = 0;
  float time_uncertainty_s = 0;
  std::uint8_t time_status = 0;  // GnssTimeInfo: same bits as TimeStatus
  std::int8_t leap_seconds = 0;
  std::array<float, 7> dop{};  // G, P, T, V, H, N, E
  std::uint8_t sat_info_resv = 0;
  std::vector<SatInfoEntry> sat_info;  // capacity kept across messages: no steady-state allocation
  double raw_tow_s = 0;
  std::uint16_t raw_week = 0;
  std::uint8_t raw_resv = 0;
  std::vector<RawMeasEntry> raw_meas;
  std::uint16_t gnss_status = 0;  // Table 2.61
  double alt_msl_m = 0;
};

struct AttitudeFields {  // Attitude group, Table 2.64
  Vec3f ypr_deg{};                       // yaw, pitch, roll (3-2-1, body w.r.t. NED)
  std::array<float, 4> quaternion{};     // x, y, z, scalar: scalar LAST (L1540-1550)
  std::array<float, 9> dcm{};            // DCM00, DCM01, ... DCM22 (errata A9)
  Vec3f mag_ned_gauss{};
  Vec3f accel_ned_mps2{};
  Vec3f lin_body_acc_mps2{};
  Vec3f lin_accel_ned_mps2{};
  Vec3f ypr_uncertainty_deg{};           // 1 sigma
  Vec3f heave{};                         // heave m, heave rate m/s, delayed heave m
  float att_uncertainty_deg = 0;
};

struct InsFields {  // INS group, Table 2.75
  std::uint16_t ins_status = 0;
  Vec3d pos_lla{};
  Vec3d pos_ecef_m{};
  Vec3f vel_body_mps{};
  Vec3f vel_ned_mps{};
  Vec3f vel_ecef_mps{};
  Vec3f mag_ecef_gauss{};
  Vec3f accel_ecef_mps2{};
  Vec3f lin_accel_ecef_mps2{};
  float pos_uncertainty_m = 0;  // 1 sigma
  float vel_uncertainty_mps = 0;
};

inline constexpr std::size_t kGnssReceivers = 3;
inline constexpr std::array<std::size_t, kGnssReceivers> kGnssSlots = {kSlotGnss1, kSlotGnss2, kSlotGnss3};

struct BinaryMessage {
  BinaryHeader header;
  TimeFields time;
  ImuFields imu;
  std::array<GnssFields, kGnssReceivers> gnss;  // GNSS1, GNSS2, GNSS3
  AttitudeFields attitude;
  InsFields ins;

  bool has(std::size_t slot, unsigned type_bit) const { return header.has(slot, type_bit); }
  // True when either the group itself or the Common copy carries the value.
  bool has_either(std::size_t slot, unsigned type_bit, unsigned common_bit) const {
    return has(slot, type_bit) || has(kSlotCommon, common_bit);
  }
};

}  // namespace navfuse::frontends::vectornav
