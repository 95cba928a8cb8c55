// Typed UM220-INS output messages (Unicore INS protocol spec R2.8 §5.3, §5.5-§5.7; digest §4),
// with decoders (split fields -> struct), encoders (struct -> "$...*HH\r\n") and FrameRecord
// builders. The NMEA sentences live in frontends/nmea/sentences.hpp.
//
// Numbers keep their printed decimals (nmea::Real) so that decode + encode reproduces the bytes.
// Decoders return nullopt for a wrong field count or a malformed field.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/nmea/fields.hpp"
#include "frontends/nmea/utc_fields.hpp"

namespace navfuse::frontends::unicore {

using nmea::Real;

inline constexpr int kImuDecimals = 6;  // "output 6 decimal places" (GYOACC L746-L752)

// GYOACC (module frame, L730-L762) and GYOACC-V (vehicle frame, right-forward-up, L764-L801):
// identical syntax, different name and frame.
struct Gyoacc {
  bool vehicle_frame = false;              // true for GYOACC-V
  std::optional<nmea::Date> date;          // "ddmmyy" (the spec's "ddmmmyy" is a typo, digest §11 item 12)
  std::optional<nmea::TimeOfDay> time;     // empty until the receiver resolved UTC
  // GYOACC-V prints the IMU fields null until the device is aligned (L771).
  std::array<std::optional<Real>, 3> gyro_rps{};
  std::uint32_t gyro_period_ms = 0;
  std::array<std::optional<Real>, 3> accel_mps2{};
  std::uint32_t accel_period_ms = 0;
  std::int32_t temperature_c = 0;          // meaningless without a sensor (L753)
  std::uint32_t pulses = 0;                // odometer pulses counted over pulse_period_ms (L754)
  std::uint32_t pulse_period_ms = 0;
  std::uint32_t reverse = 0;               // "0: forward 1: reverse" (L755)
};

// SNRSTAT: INS / odometer / installation / map-matching state (L805-L821). mapstat was added in
// R2.6 (L31): older firmware prints three fields.
struct Snrstat {
  std::int32_t ins_status = 0;     // -1 IMU failure, 0 disabled, 1 started, 2 angle known, 3 done
  std::int32_t odo_status = 0;     // -1 failure, 0 disabled, 1 scale init, 2 init done, 3 calibrated
  std::int32_t install_state = 0;  // -1 failure, 0 calibrating, 1 poor sky, 2 manoeuvre, 3 too slow
  std::optional<std::int32_t> map_status;  // -2..2 (L820)
};

// NAVPOS (L1277-L1298). `time` is read as milliseconds of week on the system time scale chosen
// by priority GPS > BDS > GAL > GLO (L1287; unit not stated, digest §11 item 23).
struct Navpos {
  std::uint32_t time_ms = 0;
  std::uint32_t system = 0;   // bit0 GPS, bit2 BDS, bit4 GLO, bit5 GAL (L1288, as printed)
  std::uint32_t quality = 0;  // 0 invalid, 1 external, 2 coarse, 3 precise (L1289)
  std::array<Real, 3> ecef_m{};
  Real lat_deg, lon_deg, height_m;  // height above the ellipsoid
};

// NAVVEL (L1300-L1318).
struct Navvel {
  std::uint32_t time_ms = 0;
  std::uint32_t system = 0;
  std::uint32_t quality = 0;
  std::array<Real, 3> vel_ecef_mps{};
  Real clock_drift_mps;  // "equivalent speed of crystal drift"
};

// NAVTIME (L1320-L1346), in the 13-field order of the table and example (the syntax line is
// garbled, digest §11 item 24).
struct Navtime {
  std::uint32_t gps_week = 0;
  Real gps_tow_s;
  std::uint32_t gps_quality = 0;
  std::uint32_t bds_week = 0;
  Real bds_tow_s;
  std::uint32_t bds_quality = 0;
  std::uint32_t gal_week = 0;
  Real gal_tow_s;
  std::uint32_t gal_quality = 0;
  std::uint32_t glo_four_year = 0;  // "GLO year": the GLONASS 4-year interval N4 (digest §4.7)
  std::uint32_t glo_day = 0;        // day in the 4-year interval
  Real glo_time_of_day_s;           // Moscow time, UTC + 3 h
  std::uint32_t glo_quality = 0;
};
inline constexpr std::uint32_t kTimeQualityCoarse = 2;  // NAVTIME xxQ / NAVPOS quality (L1334)

// NAVACC (L1348-L1364). status is a character although typed UINT (digest §11 item 25).
struct Navacc {
  std::optional<nmea::TimeOfDay> time;
  char status = 'V';
  std::uint32_t pos_acc_mm = 0;   // 2-D horizontal position error RMS, 0.001 m
  std::uint32_t vel_acc_mmps = 0; // 2-D horizontal velocity error RMS, 0.001 m/s
  std::uint32_t course_acc_mdeg = 0;
};

// NAVATT (L1366-L1388): attitude in 1e-5 degrees.
struct Navatt {
  std::optional<nmea::TimeOfDay> time;
  std::uint32_t quality = 0;  // bit0 roll, bit1 pitch, bit2 yaw valid (L1379)
  std::int32_t roll_e5deg = 0, pitch_e5deg = 0, yaw_e5deg = 0;
  std::uint32_t roll_std_e5deg = 0, pitch_std_e5deg = 0, yaw_std_e5deg = 0;
};
inline constexpr std::uint32_t kNavattRollValid = 1u << 0;
inline constexpr std::uint32_t kNavattPitchValid = 1u << 1;
inline constexpr std::uint32_t kNavattYawValid = 1u << 2;
inline constexpr double kNavattDegPerUnit = 1e-5;

// LSF output (L1392-L1438). For GLONASS (system 2) the fields carry other parameters (L1413-L1422).
struct Lsf {
  std::uint32_t system = 0;  // 0 GPS, 1 BDS, 2 GLO, 3 GAL
  std::uint32_t flag = 0;    // 1 valid
  std::uint32_t tls_s = 0, tlsf_s = 0, tot_s = 0, wn = 0, dn = 0, wnlsf = 0;
  std::int32_t a0 = 0, a1 = 0;  // scale 2^-30 s and 2^-50 s/s
};
inline constexpr std::uint32_t kLsfSystemGps = 0;

// CWOUT (L1440-L1451).
struct Cwout {
  std::uint32_t flag = 0;   // 1 none, 2 detected, 3 strong
  std::uint32_t ratio = 0;  // 0..255
};

// NOTICE (L1453-L1457): "for internal use", fields undocumented; kept as text.
inline constexpr std::size_t kMaxNoticeFields = 16;
struct Notice {
  std::array<std::string_view, kMaxNoticeFields> fields{};
  std::size_t count = 0;
};

std::optional<Gyoacc> decode_gyoacc(const nmea::Fields& f, bool vehicle_frame);
std::optional<Snrstat> decode_snrstat(const nmea::Fields& f);
std::optional<Navpos> decode_navpos(const nmea::Fields& f);
std::optional<Navvel> decode_navvel(const nmea::Fields& f);
std::optional<Navtime> decode_navtime(const nmea::Fields& f);
std::optional<Navacc> decode_navacc(const nmea::Fields& f);
std::optional<Navatt> decode_navatt(const nmea::Fields& f);
std::optional<Lsf> decode_lsf(const nmea::Fields& f);
std::optional<Cwout> decode_cwout(const nmea::Fields& f);
std::optional<Notice> decode_notice(const nmea::Fields& f);

bool encode(const Gyoacc& m, std::vector<std::uint8_t>& out);
bool encode(const Snrstat& m, std::vector<std::uint8_t>& out);
bool encode(const Navpos& m, std::vector<std::uint8_t>& out);
bool encode(const Navvel& m, std::vector<std::uint8_t>& out);
bool encode(const Navtime& m, std::vector<std::uint8_t>& out);
bool encode(const Navacc& m, std::vector<std::uint8_t>& out);
bool encode(const Navatt& m, std::vector<std::uint8_t>& out);
bool encode(const Lsf& m, std::vector<std::uint8_t>& out);
bool encode(const Cwout& m, std::vector<std::uint8_t>& out);
bool encode(const Notice& m, std::vector<std::uint8_t>& out);

void append_fields(const Gyoacc& m, frontends::FrameRecord& r);
void append_fields(const Snrstat& m, frontends::FrameRecord& r);
void append_fields(const Navpos& m, frontends::FrameRecord& r);
void append_fields(const Navvel& m, frontends::FrameRecord& r);
void append_fields(const Navtime& m, frontends::FrameRecord& r);
void append_fields(const Navacc& m, frontends::FrameRecord& r);
void append_fields(const Navatt& m, frontends::FrameRecord& r);
void append_fields(const Lsf& m, frontends::FrameRecord& r);
void append_fields(const Cwout& m, frontends::FrameRecord& r);
void append_fields(const Notice& m, frontends::FrameRecord& r);

// Required-field readers shared by the message files: false if empty or malformed.
bool read(std::string_view field, Real& v);
bool read(std::string_view field, std::uint32_t& v);
bool read(std::string_view field, std::int32_t& v);

}  // namespace navfuse::frontends::unicore
