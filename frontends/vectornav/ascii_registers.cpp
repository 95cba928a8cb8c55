#include "frontends/vectornav/ascii_registers.hpp"

#include <array>

namespace navfuse::frontends::vectornav {
namespace {

using N = std::string_view;
// Measurement registers (ICD §4, digest §6.8 and §2.6).
constexpr std::array<N, 3> kYpr = {"yaw_deg", "pitch_deg", "roll_deg"};
constexpr std::array<N, 4> kQtn = {"quat_x", "quat_y", "quat_z", "quat_s"};
constexpr std::array<N, 13> kQmr = {"quat_x", "quat_y", "quat_z", "quat_s", "mag_x_gauss", "mag_y_gauss",
                                    "mag_z_gauss", "accel_x_mps2", "accel_y_mps2", "accel_z_mps2",
                                    "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 3> kMag = {"mag_x_gauss", "mag_y_gauss", "mag_z_gauss"};
constexpr std::array<N, 3> kAcc = {"accel_x_mps2", "accel_y_mps2", "accel_z_mps2"};
constexpr std::array<N, 3> kGyr = {"gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 9> kMar = {"mag_x_gauss", "mag_y_gauss", "mag_z_gauss", "accel_x_mps2", "accel_y_mps2",
                                   "accel_z_mps2", "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 12> kYmr = {"yaw_deg", "pitch_deg", "roll_deg", "mag_x_gauss", "mag_y_gauss",
                                    "mag_z_gauss", "accel_x_mps2", "accel_y_mps2", "accel_z_mps2",
                                    "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 9> kYba = {"yaw_deg", "pitch_deg", "roll_deg", "lin_accel_x_mps2", "lin_accel_y_mps2",
                                   "lin_accel_z_mps2", "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 9> kYia = {"yaw_deg", "pitch_deg", "roll_deg", "lin_accel_n_mps2", "lin_accel_e_mps2",
                                   "lin_accel_d_mps2", "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 11> kImu = {"uncomp_mag_x_gauss", "uncomp_mag_y_gauss", "uncomp_mag_z_gauss",
                                    "uncomp_accel_x_mps2", "uncomp_accel_y_mps2", "uncomp_accel_z_mps2",
                                    "uncomp_gyro_x_rps", "uncomp_gyro_y_rps", "uncomp_gyro_z_rps",
                                    "temperature_c", "pressure_kpa"};
constexpr std::array<N, 15> kGps = {"gps_tow_s", "gps_week", "fix", "num_sats", "lat_deg", "lon_deg", "height_m",
                                    "vel_n_mps", "vel_e_mps", "vel_d_mps", "pos_std_n_m", "pos_std_e_m",
                                    "pos_std_d_m", "vel_std_mps", "time_std_s"};
constexpr std::array<N, 15> kGpe = {"gps_tow_s", "gps_week", "fix", "num_sats", "ecef_x_m", "ecef_y_m",
                                    "ecef_z_m", "vel_ecef_x_mps", "vel_ecef_y_mps", "vel_ecef_z_mps",
                                    "pos_std_x_m", "pos_std_y_m", "pos_std_z_m", "vel_std_mps", "time_std_s"};
constexpr std::array<N, 15> kIns = {"gps_tow_s", "gps_week", "ins_status", "yaw_deg", "pitch_deg", "roll_deg",
                                    "lat_deg", "lon_deg", "height_m", "vel_n_mps", "vel_e_mps", "vel_d_mps",
                                    "att_std_deg", "pos_std_m", "vel_std_mps"};
constexpr std::array<N, 15> kIne = {"gps_tow_s", "gps_week", "ins_status", "yaw_deg", "pitch_deg", "roll_deg",
                                    "ecef_x_m", "ecef_y_m", "ecef_z_m", "vel_ecef_x_mps", "vel_ecef_y_mps",
                                    "vel_ecef_z_mps", "att_std_deg", "pos_std_m", "vel_std_mps"};
constexpr std::array<N, 15> kIsl = {"yaw_deg", "pitch_deg", "roll_deg", "lat_deg", "lon_deg", "height_m",
                                    "vel_n_mps", "vel_e_mps", "vel_d_mps", "accel_x_mps2", "accel_y_mps2",
                                    "accel_z_mps2", "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 15> kIse = {"yaw_deg", "pitch_deg", "roll_deg", "ecef_x_m", "ecef_y_m", "ecef_z_m",
                                    "vel_ecef_x_mps", "vel_ecef_y_mps", "vel_ecef_z_mps", "accel_x_mps2",
                                    "accel_y_mps2", "accel_z_mps2", "gyro_x_rps", "gyro_y_rps", "gyro_z_rps"};
constexpr std::array<N, 7> kDtv = {"delta_time_s", "delta_theta_x_deg", "delta_theta_y_deg", "delta_theta_z_deg",
                                   "delta_vel_x_mps", "delta_vel_y_mps", "delta_vel_z_mps"};
constexpr std::array<N, 3> kHve = {"heave_m", "heave_rate_mps", "delayed_heave_m"};
constexpr std::array<N, 2> kCompassStartup = {"percent_complete", "heading_deg"};
// Configuration registers navfuse writes (ICD §3, digest §6).
constexpr std::array<N, 2> kBaud = {"baud_rate", "serial_port"};
constexpr std::array<N, 2> kAdor = {"async_type", "serial_port"};
constexpr std::array<N, 2> kAdof = {"async_freq_hz", "serial_port"};
constexpr std::array<N, 9> kRfr = {"rfr00", "rfr01", "rfr02", "rfr10", "rfr11", "rfr12", "rfr20", "rfr21", "rfr22"};
constexpr std::array<N, 7> kComm = {"ascii_append_count", "ascii_append_status", "spi_append_count",
                                    "spi_append_status", "ascii_checksum", "spi_checksum", "error_mode"};
constexpr std::array<N, 3> kVelAid = {"vel_x_mps", "vel_y_mps", "vel_z_mps"};
constexpr std::array<N, 3> kVelAidCtl = {"vel_aid_enable", "vel_uncert_tuning", "resv"};
constexpr std::array<N, 3> kAntenna = {"offset_x_m", "offset_y_m", "offset_z_m"};
constexpr std::array<N, 4> kInsConfig = {"scenario", "ahrs_aiding", "est_baseline", "resv"};
constexpr std::array<N, 5> kDeltaCfg = {"integration_frame", "gyro_compensation", "accel_compensation",
                                        "earth_rate_compensation", "resv"};
constexpr std::array<N, 10> kImuFilt = {"mag_window", "accel_window", "gyro_window", "temp_window",
                                        "pres_window", "mag_filter_mode", "accel_filter_mode",
                                        "gyro_filter_mode", "temp_filter_mode", "pres_filter_mode"};
constexpr std::array<N, 6> kBaseline = {"baseline_x_m", "baseline_y_m", "baseline_z_m",
                                        "baseline_std_x_m", "baseline_std_y_m", "baseline_std_z_m"};

constexpr std::uint32_t kInsStatusHex = 1u << 2;  // InsStatus printed as 4 hex digits (L4900)

constexpr std::array<RegisterLayout, 35> kLayouts = {{
    {reg::kBaudRate, "", kBaud, 0},
    {reg::kAsyncType, "", kAdor, 0},
    {reg::kAsyncFreq, "", kAdof, 0},
    {reg::kYpr, "VNYPR", kYpr, 0},
    {reg::kQuaternion, "VNQTN", kQtn, 0},
    {reg::kQuatMagAccelGyro, "VNQMR", kQmr, 0},
    {reg::kMag, "VNMAG", kMag, 0},
    {reg::kAccel, "VNACC", kAcc, 0},
    {reg::kGyro, "VNGYR", kGyr, 0},
    {reg::kMagAccelGyro, "VNMAR", kMar, 0},
    {reg::kReferenceFrameRotation, "", kRfr, 0},
    {reg::kYprMagAccelGyro, "VNYMR", kYmr, 0},
    {reg::kCommProtocol, "", kComm, 0},
    {reg::kVelAidMeasurement, "", kVelAid, 0},
    {reg::kVelAidControl, "", kVelAidCtl, 0},
    {reg::kImuMeasurements, "VNIMU", kImu, 0},
    {reg::kGnssAntennaA, "", kAntenna, 0},
    {reg::kGnssLla, "VNGPS", kGps, 0},
    {reg::kGnssEcef, "VNGPE", kGpe, 0},
    {reg::kInsLla, "VNINS", kIns, kInsStatusHex},
    {reg::kInsEcef, "VNINE", kIne, kInsStatusHex},
    {reg::kInsBasicConfig, "", kInsConfig, 0},
    {reg::kInsStateLla, "VNISL", kIsl, 0},
    {reg::kInsStateEcef, "VNISE", kIse, 0},
    {reg::kDeltaThetaVel, "VNDTV", kDtv, 0},
    {reg::kDeltaConfig, "", kDeltaCfg, 0},
    {reg::kImuFilter, "", kImuFilt, 0},
    {reg::kCompassBaseline, "", kBaseline, 0},
    {reg::kCompassStartup, "", kCompassStartup, 0},
    {reg::kGnss2Lla, "VNG2S", kGps, 0},
    {reg::kGnss2Ecef, "VNG2E", kGpe, 0},
    {reg::kHeave, "VNHVE", kHve, 0},
    {reg::kExternalGnssAntenna, "", kAntenna, 0},
    {reg::kYprLinBodyGyro, "VNYBA", kYba, 0},
    {reg::kYprLinNedGyro, "VNYIA", kYia, 0},
}};

}  // namespace

const RegisterLayout* find_register(int id) {
  for (const auto& l : kLayouts)
    if (l.id == id) return &l;
  return nullptr;
}

const RegisterLayout* find_async_output(std::string_view header) {
  if (header.empty()) return nullptr;
  for (const auto& l : kLayouts)
    if (l.async_header == header) return &l;
  return nullptr;
}

}  // namespace navfuse::frontends::vectornav
