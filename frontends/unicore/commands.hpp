// Encoders for every UM220-INS input command (Unicore INS protocol spec R2.8 §5.1-§5.3;
// digest §3) and the command sequence that prepares a fresh module for navfuse.
//
// Conventions of every encoder here:
//   * the sentence always carries a checksum ("$NAME,...*HH\r\n", XOR of L164);
//   * an optional parameter left as std::nullopt is written as an empty field, which the
//     receiver ignores ("the options it controls will remain unchanged", L156-L158);
//   * trailing empty parameters are dropped, and a command with no parameter at all is written
//     "$NAME,*HH" as L168 requires ("If the parameters ... are empty and a checksum needs to be
//     added, it should be followed by ','"). For the CFG* commands that form is the QUERY of the
//     current setting (L160): a struct with every field empty encodes the query.
// Each function returns the complete sentence, or an empty string if it cannot be encoded
// (a value out of its documented range, or more than 128 bytes).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::frontends::unicore {

// "$NAME,p1,...,pn*HH\r\n" from raw parameter texts, with the rules above.
std::string encode_command(std::string_view name, const std::vector<std::string>& params);
// "$NAME,*HH\r\n": query of a setting or a parameterless command (PDTINFO, CFGSAVE, ...).
std::string encode_query(std::string_view name);

// RESET (L233-L248).
enum class ResetType : std::uint32_t { kSoftware = 0, kChip = 1, kBoard = 2, kStop = 3 };
inline constexpr std::uint32_t kClearHotStart = 0x00;   // presets, L246
inline constexpr std::uint32_t kClearWarmStart = 0x01;  // ephemeris
// Cold start also sets bit3, clearing the inertial device parameters (digest §3.2).
inline constexpr std::uint32_t kClearColdStart = 0xFF;
struct ResetCommand {
  std::optional<ResetType> type;
  std::optional<std::uint32_t> clear_mask;  // bit0 ephemeris, bit2 position/time, bit3 inertial, ...
};
std::string encode(const ResetCommand& c);

// CFGPRT (L286-L321). With only `port` set it is the read form "$CFGPRT,1".
// The bit table (L310) omits bit5 "RTCM2.3" that the default 1185 uses (L1468), and bit9's
// odometer protocol is documented nowhere (digest §11 item 7): neither is used here.
inline constexpr std::uint32_t kProtoUnicore = 1u << 0;
inline constexpr std::uint32_t kOutProtoNmea = 1u << 1;
inline constexpr std::uint32_t kProtoRtcm32In = 1u << 7, kProtoRtcm32Out = 1u << 2;
inline constexpr std::uint32_t kInProtoOdometer = 1u << 9;    // "only supported by ADR version"
inline constexpr std::uint32_t kInProtoMapMatching = 1u << 10;
inline constexpr std::uint32_t kOutProtoEcho = 1u << 5;       // fw >= R3.4.0.0 (L317)
struct CfgPrtCommand {
  std::optional<std::uint32_t> port;      // 1 UART1, 2 UART2; empty: the receiving port
  std::optional<std::uint32_t> baud;      // 9600, 115200, 460800 (L309)
  std::optional<std::uint32_t> in_proto;  // kProto* bits
  std::optional<std::uint32_t> out_proto;
};
std::string encode(const CfgPrtCommand& c);

// CFGMSG (L324-L373): enable (1) / disable (0) one output; without `enable` it reads the state.
// msgID is always written: what an empty (optional, L347) msgID means is undefined (digest §11
// item 9).
struct MessageId {
  std::uint32_t msg_class = 0;
  std::uint32_t msg_id = 0;
};
// Class/ID table L352-L369.
inline constexpr MessageId kMsgGga{0, 0}, kMsgGll{0, 1}, kMsgGsa{0, 2}, kMsgGsv{0, 3},
    kMsgRmc{0, 4}, kMsgVtg{0, 5}, kMsgZda{0, 6}, kMsgGst{0, 7};
inline constexpr MessageId kMsgNavpos{1, 0}, kMsgNavvel{1, 1}, kMsgNavtime{1, 2}, kMsgNavacc{1, 3};
inline constexpr MessageId kMsgGyoacc{4, 0}, kMsgSnrstat{4, 1}, kMsgNavatt{4, 2}, kMsgGyoaccV{4, 3};
struct CfgMsgCommand {
  MessageId message;
  std::optional<bool> enable;
};
std::string encode(const CfgMsgCommand& c);

// CFGTP timing pulse (L375-L400).
struct CfgTpCommand {
  std::optional<std::uint32_t> interval_us, width_us, flags;
  std::optional<std::int32_t> antenna_delay_ns, rf_delay_ns, user_delay_ns;  // -32768..32767
};
std::string encode(const CfgTpCommand& c);

// CFGNMEA (L402-L426).
inline constexpr std::uint32_t kNmeaVersion41 = 0x51;  // "h51"
inline constexpr std::uint32_t kNmeaVersion30 = 0x30;  // "h30"
struct CfgNmeaCommand {
  std::optional<std::uint32_t> version;   // kNmeaVersion41 / kNmeaVersion30
  std::optional<std::uint32_t> ins_rate;  // 0: 1 Hz, 1: 5 Hz, 2: 10 Hz
};
std::string encode(const CfgNmeaCommand& c);

// CFGSYS (L428-L453). The receiver RESETS after it (L443).
struct CfgSysCommand {
  std::optional<std::uint32_t> system_mask;  // H01, H10, H101, H11 (printed with 'H', L441)
};
std::string encode(const CfgSysCommand& c);

std::string encode_cfgsave();  // L455-L465: keep the power on >= 1 s afterwards
std::string encode_cfgclr();   // L467-L475

struct CfgCwoutCommand { std::optional<bool> enable; };  // L477-L495
std::string encode(const CfgCwoutCommand& c);

// CFGINS (L497-L520).
struct CfgInsCommand {
  std::optional<std::uint32_t> mode;        // 0 GNSS only, 1 land vehicle (default)
  std::optional<std::uint32_t> imu_source;  // 0 off, 1 built-in
  std::optional<std::uint32_t> odo_source;  // 0 off, 1 built-in pulse counter
  std::optional<std::uint32_t> map_source;  // 0 off, 4 map matching over UART
};
std::string encode(const CfgInsCommand& c);

// CFGROTAT mounting angles (L522-L572): module rotated about z by angle_z, then the new x by
// angle_x, then the new y by angle_y (L547-L558), sent in 0.01 degree units 0..36000. A negative
// angle is sent as 360 deg - |angle| (the field is UINT; digest §3.12 inference).
struct CfgRotatCommand {
  std::optional<double> angle_x_deg, angle_y_deg, angle_z_deg;
  std::optional<std::uint32_t> mode;  // 0 general (rough angles), 2 automatic (default)
};
std::string encode(const CfgRotatCommand& c);

struct CfgGeoidCommand { std::optional<std::uint32_t> model; };      // 0 ellipsoid, 1 MSL (L574-L592)
std::string encode(const CfgGeoidCommand& c);
struct CfgOdoFwdCommand { std::optional<std::uint32_t> polarity; };  // 1 high = forward (L594-L612)
std::string encode(const CfgOdoFwdCommand& c);
struct CfgCogCommand { std::optional<std::uint32_t> mode; };         // 0 vehicle front, 1 travel (L614-L634)
std::string encode(const CfgCogCommand& c);
struct CfgAttCommand { std::optional<std::uint32_t> rate_hz; };      // 1 or 10 (L708-L726)
std::string encode(const CfgAttCommand& c);

// AIDTIME (L636-L655): UTC.
struct AidTimeCommand {
  int year = 1980, month = 1, day = 6, hour = 0, minute = 0, second = 0, millisecond = 0;
};
// From a GPS time (ns), through the core leap-second table.
AidTimeCommand aid_time_from_gps_ns(std::int64_t gps_ns);
std::string encode(const AidTimeCommand& c);

// AIDPOS (L657-L675): latitude/longitude in ddmm.mmmmmm, ellipsoid height.
struct AidPosCommand {
  double lat_deg = 0.0, lon_deg = 0.0, height_m = 0.0;
};
std::string encode(const AidPosCommand& c);

// MAPFB map-matching feedback (L823-L846), at 1 Hz within 700 ms of the second.
struct MapFbCommand {
  std::int64_t utc_time_of_day_ns = 0;  // the integer second of the position it refers to
  std::int32_t road_count = 0, road_index = 0, road_type = 0, probability_e3 = 0;
  std::int32_t lat_diff_e6deg = 0, lon_diff_e6deg = 0, up_diff_m = 0, road_width_m = 0;
  std::int32_t road_azimuth_e2deg = 0;
};
std::string encode(const MapFbCommand& c);

// Queries of information outputs.
std::string encode_pdtinfo_query();                   // L206-L231
std::string encode_aidinfo_query();                   // L677-L704
std::string encode_lsf_query(std::uint32_t system);   // L1392-L1402: 0 GPS, 1 BDS, 2 GLO, 3 GAL

// The commands that configure a fresh UM220-INS for navfuse (issue #6), in order:
//   GYOACC on (the rate is the firmware's maximum: 5 Hz before R3.4.0.0, 10 Hz after, L371),
//   NAVPOS, NAVVEL, NAVATT at 10 Hz (CFGATT), NAVACC, NAVTIME, and LSF for GPS - UTC.
// With `save` the configuration is stored in flash (CFGSAVE) at the end. The baud rate is left
// alone: changing it on the link in use would cut the link (10 Hz GYOACC wants 230400 bps, L758,
// a rate CFGPRT does not list, digest §11 item 8).
std::vector<std::string> fusion_setup_commands(bool save = false);

}  // namespace navfuse::frontends::unicore
