// VN-300 commands (ICD §1.3 L178-581, §3 registers; digest §2.4, §6) as ASCII sentences with
// their checksum, the parsing of the device's replies, and the command sequence that sets up a
// fresh VN-300 for fusion.
//
// Every function returns one complete sentence ("$...*CS\r\n"). The checksum is the 8-bit XOR
// unless `checksum` says CRC16 (Reg 30 AsciiChecksum, L2865-2871).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "frontends/vectornav/ascii_sentence.hpp"
#include "frontends/vectornav/binary_header.hpp"

namespace navfuse::frontends::vectornav::cmd {

std::string read_register(int id, AsciiChecksum checksum = AsciiChecksum::kXor8);
// `values` are printed verbatim, comma separated, after the register id.
std::string write_register(int id, std::span<const std::string> values, AsciiChecksum checksum = AsciiChecksum::kXor8);
// VNWNV: saves every configuration register to flash (~0.5-1 s; send only while stationary, L227-251).
std::string write_settings(AsciiChecksum checksum = AsciiChecksum::kXor8);
// VNRFS: restores factory settings and resets (wait 2 s, L253-273).
std::string restore_factory_settings(AsciiChecksum checksum = AsciiChecksum::kXor8);
// VNRST: software reset; unsaved settings are lost (L275-295).
std::string reset(AsciiChecksum checksum = AsciiChecksum::kXor8);
// VNTAR: the tare command of earlier VectorNav firmware. FW 1.1.0.1 no longer lists it (digest
// §6.9, changelog L103), so a VN-300 on this firmware answers $VNERR 04 (invalid command).
std::string tare(AsciiChecksum checksum = AsciiChecksum::kXor8);
// VNASY: pauses (false) or resumes (true) all asynchronous output on the receiving port (L461-489).
std::string async_output(bool enable, AsciiChecksum checksum = AsciiChecksum::kXor8);

// Reg 75/76/77 (L2970-3082): AsyncMode (bit0 serial 1, bit1 serial 2), RateDivisor (rate =
// 400 Hz / divisor; errata A10: ImuRate is 400 Hz, L5221) and the same group bytes / type words
// as the binary message header (L5246).
struct BinaryOutputConfig {
  std::uint16_t async_mode = 0;
  std::uint16_t rate_divisor = 0;
  BinaryHeader header;
};
inline constexpr int kImuRateHz = 400;
// output = 1, 2 or 3. Errata A16: the group bytes are followed by one (or two) type words per
// active group; no groups means an empty message configuration ("0").
std::string write_binary_output(int output, const BinaryOutputConfig& config,
                                AsciiChecksum checksum = AsciiChecksum::kXor8);
// Reg 26: sensor-to-body rotation {X,Y,Z}_B = RFR * {X,Y,Z}_S, row-major (L3466-3501). A static
// register: takes effect after Write Settings and a reset.
std::string write_reference_frame_rotation(const Eigen::Matrix3d& rfr, AsciiChecksum checksum = AsciiChecksum::kXor8);
// Reg 57 (GNSS A antenna) or Reg 157 (external GNSS antenna): position relative to the INS
// reference point, body frame, metres (L3845-3868, L4054-4074).
enum class Antenna : std::uint8_t { kInternalA, kExternal };
std::string write_antenna_offset(Antenna antenna, const Eigen::Vector3d& offset_m,
                                 AsciiChecksum checksum = AsciiChecksum::kXor8);
// Reg 93: GNSS B antenna relative to A, body frame, and its per-axis uncertainty (set it to ~2x
// the worst-case measurement error, L4285-4287), metres.
std::string write_compass_baseline(const Eigen::Vector3d& baseline_m, const Eigen::Vector3d& uncertainty_m,
                                   AsciiChecksum checksum = AsciiChecksum::kXor8);
// Reg 67 (L4078-4123). Scenario: 0 AHRS, 3 dual GNSS without pressure, 5 with pressure
// (errata A20: the example's 2 is not a valid value).
struct InsBasicConfig {
  std::uint8_t scenario = 3;
  bool ahrs_aiding = true;
  bool estimate_baseline = true;
};
std::string write_ins_basic_config(const InsBasicConfig& config, AsciiChecksum checksum = AsciiChecksum::kXor8);
// Reg 50: body-frame velocity for the AHRS (only its length is used, as body-x speed, L3732).
std::string write_velocity_aiding(const Eigen::Vector3d& vel_body_mps, AsciiChecksum checksum = AsciiChecksum::kXor8);
// Reg 51 (L3736-3764): enable, uncertainty tuning (default 0.1); the reserved float stays at 0.01.
struct VelocityAidingControl {
  bool enable = true;
  float uncertainty_tuning = 0.1f;
};
std::string write_velocity_aiding_control(const VelocityAidingControl& control,
                                          AsciiChecksum checksum = AsciiChecksum::kXor8);

// The configuration navfuse uses for fusion. Output 1 (Reg 75): Time{TimeStartup, TimeGps,
// TimeStatus} + Imu{ImuStatus, DeltaTheta, DeltaVel, SensSat} + Attitude{Ypr, Quaternion, YprU}
// + Ins{InsStatus, PosLla, VelBody, VelNed, PosU, VelU} at `imu_rate_hz`; output 2 (Reg 76):
// GNSS1 and GNSS2 {GpsTow, GpsWeek, NumSats, GnssFix, PosLla, VelNed, PosUncertainty,
// VelUncertainty, GnssTimeInfo} at `gnss_rate_hz`. Output 1 is 159 bytes, so 200 Hz needs
// ~32 kB/s: 460800 baud or more (the device answers error 0C otherwise, L2994).
struct FusionSetup {
  std::uint16_t serial_ports = 1;  // AsyncMode bits: 1 serial 1, 2 serial 2, 3 both
  int imu_rate_hz = 200;           // must divide 400 Hz
  int gnss_rate_hz = 5;            // the receivers' rate is 5 Hz (Reg 55, L3821-3827)
  std::uint32_t baud_rate = 0;     // 0: leave Reg 5 alone
  std::optional<Eigen::Vector3d> antenna_a_offset_m;  // Reg 57, if known
  std::optional<Eigen::Vector3d> compass_baseline_m;  // Reg 93, if known
  Eigen::Vector3d compass_baseline_std_m = Eigen::Vector3d::Constant(0.0254);  // Reg 93 default
  bool save = false;               // append Write Settings (persist across power cycles)
};
BinaryOutputConfig fusion_imu_output(const FusionSetup& setup);
BinaryOutputConfig fusion_gnss_output(const FusionSetup& setup);
// Pause async output; ASCII async off (Reg 6 = 0); delta outputs in the body frame without
// compensation (Reg 82 defaults, L3503-3555); accel/gyro/temperature output filters off (Reg 85:
// the default 2-sample boxcar smooths what the EKF integrates, digest §6.3); antenna offset and
// baseline if given; binary outputs 1 and 2; optional Write Settings; resume async output.
std::vector<std::string> fusion_setup_commands(const FusionSetup& setup, AsciiChecksum checksum = AsciiChecksum::kXor8);

// A device reply: a register read/write response, an error, or a command echo.
struct Reply {
  enum class Kind : std::uint8_t { kRegister, kError, kEcho };
  Kind kind = Kind::kEcho;
  std::string header;               // "VNRRG", "VNWRG", "VNERR", "VNWNV", ...
  int register_id = -1;             // kRegister
  std::vector<std::string> values;  // kRegister: fields after the id; kEcho: all fields
  unsigned error_code = 0;          // kError (Table 1.7)
};
// Parses one reply sentence ("$...*CS" with optional line end); nullopt if its checksum fails
// or it is not a VectorNav reply.
std::optional<Reply> parse_reply(std::string_view sentence);
// Typed views of replies to the registers above (nullopt: other register or malformed).
std::optional<BinaryOutputConfig> parse_binary_output(const Reply& reply);
std::optional<Eigen::Matrix3d> parse_reference_frame_rotation(const Reply& reply);
std::optional<Eigen::Vector3d> parse_vector3(const Reply& reply, int register_id);  // Reg 50, 57, 157
std::optional<InsBasicConfig> parse_ins_basic_config(const Reply& reply);
std::optional<VelocityAidingControl> parse_velocity_aiding_control(const Reply& reply);
struct CompassBaseline {
  Eigen::Vector3d baseline_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d uncertainty_m = Eigen::Vector3d::Zero();
};
std::optional<CompassBaseline> parse_compass_baseline(const Reply& reply);

// Looks through the bytes received after a command for the device's error reply; returns the
// first "$VNERR,..." line (ICD §1.4, Table 1.7), "" when there is none.
std::string find_refusal(std::span<const std::uint8_t> reply_bytes);

}  // namespace navfuse::frontends::vectornav::cmd
