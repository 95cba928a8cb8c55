// Layouts of every data field the digest gives in sets 0x80, 0x82, 0x91/0x92/0x94, 0x93, 0xA0
// and the shared 0xFF descriptors (digest §4.1-§4.6). Lengths follow the parameter lists, not
// the doc's printed "Field Length" (errata E1, digest §4.7: e.g. accel is LEN 14 as the doc's own
// packet at L3957 shows, although L6395 prints 2).
#include "frontends/mip/field_schema.hpp"

namespace navfuse::frontends::mip {
namespace {

using W = WireType;

// 0xFF shared (digest §4.5, L6583-6670).
constexpr Param kEventSource[] = {{"trigger_id", W::kU8}};
constexpr Param kGpsTs[] = {{"tow", W::kF64, "s"}, {"week_number", W::kU16}, {"valid_flags", W::kU16}};
constexpr Param kDeltaTime[] = {{"dt", W::kF64, "s"}};
constexpr Param kRefTs[] = {{"reference_time", W::kU64, "ns"}};
constexpr Param kRefDelta[] = {{"dt", W::kU64, "ns"}};
constexpr Param kExtTs[] = {{"external_time", W::kU64, "ns"}, {"valid_flags", W::kU16}};
constexpr Param kExtDelta[] = {{"dt", W::kU64, "ns"}, {"valid_flags", W::kU16}};

// 0x80 sensor (digest §4.1, L6390-6559).
constexpr Param kAccel[] = {{"accel", W::kVec3f, "g"}};
constexpr Param kGyro[] = {{"gyro", W::kVec3f, "radps"}};
constexpr Param kMag[] = {{"mag", W::kVec3f, "gauss"}};
constexpr Param kDTheta[] = {{"delta_theta", W::kVec3f, "rad"}};
constexpr Param kDVel[] = {{"delta_velocity", W::kVec3f, "g_s"}};  // g*s (L6437, errata E35)
constexpr Param kCfMatrix[] = {{"dcm", W::kMat3f}};
constexpr Param kCfQuat[] = {{"q", W::kQuatf}};
constexpr Param kCfEuler[] = {{"roll", W::kF32, "rad"}, {"pitch", W::kF32, "rad"}, {"yaw", W::kF32, "rad"}};
constexpr Param kTemp[] = {{"min_temp", W::kF32, "degc"}, {"max_temp", W::kF32, "degc"}, {"mean_temp", W::kF32, "degc"}};
constexpr Param kPressure[] = {{"pressure", W::kF32, "mbar"}};
constexpr Param kOverrange[] = {{"status", W::kU16}};
constexpr Param kOdometer[] = {{"speed", W::kF32, "mps"}, {"uncertainty", W::kF32, "mps"}, {"valid_flags", W::kU16}};

// 0x82 filter (digest §4.2, L4181-4727).
constexpr Param kFLlh[] = {{"lat", W::kF64, "deg"}, {"lon", W::kF64, "deg"}, {"ellipsoid_height", W::kF64, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFVel[] = {{"vel_north", W::kF32, "mps"}, {"vel_east", W::kF32, "mps"}, {"vel_down", W::kF32, "mps"}, {"valid_flags", W::kU16}};
constexpr Param kFQuat[] = {{"q", W::kQuatf}, {"valid_flags", W::kU16}};
constexpr Param kFDcm[] = {{"dcm", W::kMat3f}, {"valid_flags", W::kU16}};
constexpr Param kFEuler[] = {{"roll", W::kF32, "rad"}, {"pitch", W::kF32, "rad"}, {"yaw", W::kF32, "rad"}, {"valid_flags", W::kU16}};
constexpr Param kFGyroBias[] = {{"gyro_bias", W::kVec3f, "radps"}, {"valid_flags", W::kU16}};
constexpr Param kFAccelBias[] = {{"accel_bias", W::kVec3f, "mps2"}, {"valid_flags", W::kU16}};
constexpr Param kFPosUnc[] = {{"north_std", W::kF32, "m"}, {"east_std", W::kF32, "m"}, {"down_std", W::kF32, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFVelUnc[] = {{"north_std", W::kF32, "mps"}, {"east_std", W::kF32, "mps"}, {"down_std", W::kF32, "mps"}, {"valid_flags", W::kU16}};
constexpr Param kFEulerUnc[] = {{"roll_std", W::kF32, "rad"}, {"pitch_std", W::kF32, "rad"}, {"yaw_std", W::kF32, "rad"}, {"valid_flags", W::kU16}};
constexpr Param kFGyroBiasUnc[] = {{"gyro_bias_std", W::kVec3f, "radps"}, {"valid_flags", W::kU16}};
constexpr Param kFAccelBiasUnc[] = {{"accel_bias_std", W::kVec3f, "mps2"}, {"valid_flags", W::kU16}};
constexpr Param kFLinAccel[] = {{"linear_accel", W::kVec3f, "mps2"}, {"valid_flags", W::kU16}};
constexpr Param kFAngRate[] = {{"angular_rate", W::kVec3f, "radps"}, {"valid_flags", W::kU16}};
constexpr Param kFStatus[] = {{"filter_state", W::kU16}, {"dynamics_mode", W::kU16}, {"status_flags", W::kU16}};
constexpr Param kFTimestamp[] = {{"tow", W::kF64, "s"}, {"week_number", W::kU16}, {"valid_flags", W::kU16}};
constexpr Param kFQuatUnc[] = {{"q_std", W::kQuatf}, {"valid_flags", W::kU16}};
constexpr Param kFGravity[] = {{"gravity", W::kVec3f, "mps2"}, {"valid_flags", W::kU16}};
constexpr Param kFMagModel[] = {{"intensity_north", W::kF32, "gauss"}, {"intensity_east", W::kF32, "gauss"}, {"intensity_down", W::kF32, "gauss"}, {"inclination", W::kF32, "rad"}, {"declination", W::kF32, "rad"}, {"valid_flags", W::kU16}};
constexpr Param kFCompAccel[] = {{"comp_accel", W::kVec3f, "mps2"}, {"valid_flags", W::kU16}};
constexpr Param kFPressAlt[] = {{"pressure_altitude", W::kF32, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFAntOffset[] = {{"receiver_id", W::kU8}, {"offset", W::kVec3f, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFAntOffsetUnc[] = {{"receiver_id", W::kU8}, {"offset_std", W::kVec3f, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFEcefPosUnc[] = {{"pos_std", W::kVec3f, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFEcefVelUnc[] = {{"vel_std", W::kVec3f, "mps"}, {"valid_flags", W::kU16}};
constexpr Param kFEcefPos[] = {{"pos_ecef", W::kVec3d, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFEcefVel[] = {{"vel_ecef", W::kVec3f, "mps"}, {"valid_flags", W::kU16}};
constexpr Param kFRelPos[] = {{"rel_pos_ned", W::kVec3d, "m"}, {"valid_flags", W::kU16}};
constexpr Param kFGnssAid[] = {{"receiver_id", W::kU8}, {"time_of_week", W::kF32, "s"}, {"status", W::kU16}, {"reserved", W::kU64}};
constexpr Param kFAidSummary[] = {{"time_of_week", W::kF32, "s"}, {"source", W::kU8}, {"type", W::kU8}, {"indicator", W::kU8}};
constexpr Param kFOdoSf[] = {{"scale_factor_error", W::kF32}, {"valid_flags", W::kU16}};
constexpr Param kFOdoSfUnc[] = {{"scale_factor_error_std", W::kF32}, {"valid_flags", W::kU16}};
constexpr Param kFDualAnt[] = {{"time_of_week", W::kF32, "s"}, {"heading", W::kF32, "rad"}, {"heading_std", W::kF32, "rad"}, {"fix_type", W::kU8}, {"status_flags", W::kU16}, {"valid_flags", W::kU16}};
constexpr Param kFFrameErr[] = {{"frame_id", W::kU8}, {"translation_error", W::kVec3f, "m"}, {"attitude_error_q", W::kQuatf}};
constexpr Param kFFrameErrUnc[] = {{"frame_id", W::kU8}, {"translation_std", W::kVec3f, "m"}, {"attitude_std", W::kVec3f, "rad"}};

// 0x91/0x92 (and 0x94 for 03, 05, 08, 0B, 20) GNSS (digest §4.3, L4985-5540).
constexpr Param kGLlh[] = {{"lat", W::kF64, "deg"}, {"lon", W::kF64, "deg"}, {"ellipsoid_height", W::kF64, "m"}, {"msl_height", W::kF64, "m"}, {"horizontal_accuracy", W::kF32, "m"}, {"vertical_accuracy", W::kF32, "m"}, {"valid_flags", W::kU16}};
constexpr Param kGEcefPos[] = {{"pos_ecef", W::kVec3d, "m"}, {"pos_accuracy", W::kF32, "m"}, {"valid_flags", W::kU16}};
constexpr Param kGVelNed[] = {{"vel_ned", W::kVec3f, "mps"}, {"speed", W::kF32, "mps"}, {"ground_speed", W::kF32, "mps"}, {"heading", W::kF32, "deg"}, {"speed_accuracy", W::kF32, "mps"}, {"heading_accuracy", W::kF32, "deg"}, {"valid_flags", W::kU16}};
constexpr Param kGEcefVel[] = {{"vel_ecef", W::kVec3f, "mps"}, {"vel_accuracy", W::kF32, "mps"}, {"valid_flags", W::kU16}};
constexpr Param kGDop[] = {{"gdop", W::kF32}, {"pdop", W::kF32}, {"hdop", W::kF32}, {"vdop", W::kF32}, {"tdop", W::kF32}, {"ndop", W::kF32}, {"edop", W::kF32}, {"valid_flags", W::kU16}};
constexpr Param kGUtc[] = {{"year", W::kU16}, {"month", W::kU8}, {"day", W::kU8}, {"hour", W::kU8}, {"minute", W::kU8}, {"second", W::kU8}, {"msec", W::kU32, "ms"}, {"valid_flags", W::kU16}};
constexpr Param kGGpsTime[] = {{"tow", W::kF64, "s"}, {"week_number", W::kU16}, {"valid_flags", W::kU16}};
constexpr Param kGFix[] = {{"fix_type", W::kU8}, {"num_sv", W::kU8}, {"fix_flags", W::kU16}, {"valid_flags", W::kU16}};
constexpr Param kGHw[] = {{"receiver_state", W::kU8}, {"antenna_state", W::kU8}, {"antenna_power", W::kU8}, {"valid_flags", W::kU16}};
constexpr Param kGClock[] = {{"bias", W::kF64}, {"drift", W::kF64}, {"bias_accuracy", W::kF64}, {"drift_accuracy", W::kF64}, {"valid_flags", W::kU16}};
constexpr Param kGLeap[] = {{"leap_seconds", W::kU8, "s"}, {"valid_flags", W::kU16}};
constexpr Param kGSbas[] = {{"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"sbas_system", W::kU8}, {"sbas_id", W::kU8}, {"count", W::kU8}, {"sbas_status", W::kU8}, {"valid_flags", W::kU16}};
constexpr Param kGSat[] = {{"index", W::kU8}, {"count", W::kU8}, {"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"gnss_id", W::kU8}, {"satellite_id", W::kU8}, {"elevation", W::kF32, "deg"}, {"azimuth", W::kF32, "deg"}, {"health", W::kBool}, {"valid_flags", W::kU16}};
constexpr Param kGRaw[] = {{"index", W::kU8}, {"count", W::kU8}, {"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"receiver_id", W::kU16}, {"tracking_channel", W::kU8}, {"gnss_id", W::kU8}, {"satellite_id", W::kU8}, {"signal_id", W::kU8}, {"signal_strength", W::kF32, "dbhz"}, {"quality", W::kU8}, {"pseudorange", W::kF64, "m"}, {"carrier_phase", W::kF64, "cycles"}, {"doppler", W::kF32, "hz"}, {"range_std", W::kF32, "m"}, {"phase_std", W::kF32, "cycles"}, {"doppler_std", W::kF32, "hz"}, {"lock_time", W::kF32, "s"}, {"valid_flags", W::kU16}};
constexpr Param kGEph[] = {{"index", W::kU8}, {"count", W::kU8}, {"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"satellite_id", W::kU8}, {"health", W::kU8}, {"iodc", W::kU8}, {"iode", W::kU8}, {"t_oc", W::kF64, "s"}, {"af0", W::kF64, "s"}, {"af1", W::kF64, "sps"}, {"af2", W::kF64, "sps2"}, {"t_gd", W::kF64, "s"}, {"isc_l1ca", W::kF64, "s"}, {"isc_l2c", W::kF64, "s"}, {"t_oe", W::kF64, "s"}, {"a", W::kF64, "m"}, {"a_dot", W::kF64, "mps"}, {"mean_anomaly", W::kF64, "rad"}, {"delta_mean_motion", W::kF64, "rad"}, {"delta_mean_motion_dot", W::kF64, "radps"}, {"eccentricity", W::kF64}, {"argument_of_perigee", W::kF64, "rad"}, {"omega", W::kF64, "rad"}, {"omega_dot", W::kF64, "radps"}, {"inclination", W::kF64, "rad"}, {"inclination_dot", W::kF64, "radps"}, {"c_ic", W::kF64, "rad"}, {"c_is", W::kF64, "rad"}, {"c_uc", W::kF64, "rad"}, {"c_us", W::kF64, "rad"}, {"c_rc", W::kF64, "m"}, {"c_rs", W::kF64, "m"}, {"valid_flags", W::kU16}};
constexpr Param kGGloEph[] = {{"index", W::kU8}, {"count", W::kU8}, {"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"satellite_id", W::kU8}, {"freq_number", W::kS8}, {"tk", W::kU32, "s"}, {"tb", W::kU32, "s"}, {"sat_type", W::kU8}, {"gamma", W::kF64}, {"tau_n", W::kF64, "s"}, {"x", W::kVec3d, "m"}, {"v", W::kVec3f, "mps"}, {"a", W::kVec3f, "mps2"}, {"health", W::kU8}, {"p", W::kU8}, {"nt", W::kU8}, {"delta_tau_n", W::kF32}, {"ft", W::kU8}, {"en", W::kU8, "days"}, {"p1", W::kU8, "min"}, {"p2", W::kU8}, {"p3", W::kU8}, {"p4", W::kU8}, {"valid_flags", W::kU16}};

// 0x93 corrections (digest §4.4, L4741-4800).
constexpr Param kCBase[] = {{"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"ecef_pos", W::kVec3d, "m"}, {"height", W::kF32, "m"}, {"station_id", W::kU16}, {"indicators", W::kU16}, {"valid_flags", W::kU16}};
constexpr Param kCRtk[] = {{"time_of_week", W::kF64, "s"}, {"week_number", W::kU16}, {"epoch_status", W::kU16}, {"dongle_status", W::kU32}, {"gps_correction_latency", W::kF32, "s"}, {"glonass_correction_latency", W::kF32, "s"}, {"galileo_correction_latency", W::kF32, "s"}, {"beidou_correction_latency", W::kF32, "s"}, {"reserved0", W::kU32}, {"reserved1", W::kU32}, {"reserved2", W::kU32}, {"reserved3", W::kU32}, {"valid_flags", W::kU16}};

// 0xA0 system (digest §4.6, L6689-6712).
constexpr Param kSBit[] = {{"result", W::kBytes16}};
constexpr Param kSTimeSync[] = {{"time_sync", W::kBool}, {"last_pps_rcvd", W::kU8, "s"}};
constexpr Param kSGpio[] = {{"states", W::kU8}};

constexpr FieldSchema kData[] = {
    {.set = 0xFF, .desc = 0xD0, .name = "event source", .params = kEventSource},
    {.set = 0xFF, .desc = 0xD3, .name = "gps timestamp", .params = kGpsTs},
    {.set = 0xFF, .desc = 0xD4, .name = "delta time", .params = kDeltaTime},
    {.set = 0xFF, .desc = 0xD5, .name = "reference timestamp", .params = kRefTs},
    {.set = 0xFF, .desc = 0xD6, .name = "reference time delta", .params = kRefDelta},
    {.set = 0xFF, .desc = 0xD7, .name = "external timestamp", .params = kExtTs},
    {.set = 0xFF, .desc = 0xD8, .name = "external time delta", .params = kExtDelta},
    {.set = 0x80, .desc = 0x04, .name = "scaled accel", .params = kAccel},
    {.set = 0x80, .desc = 0x05, .name = "scaled gyro", .params = kGyro},
    {.set = 0x80, .desc = 0x06, .name = "scaled mag", .params = kMag},
    {.set = 0x80, .desc = 0x07, .name = "delta theta", .params = kDTheta},
    {.set = 0x80, .desc = 0x08, .name = "delta velocity", .params = kDVel},
    {.set = 0x80, .desc = 0x09, .name = "cf orientation matrix", .params = kCfMatrix},
    {.set = 0x80, .desc = 0x0A, .name = "cf quaternion", .params = kCfQuat},
    {.set = 0x80, .desc = 0x0C, .name = "cf euler angles", .params = kCfEuler},
    {.set = 0x80, .desc = 0x12, .name = "gps timestamp (legacy)", .params = kGpsTs},
    {.set = 0x80, .desc = 0x14, .name = "temperature statistics", .params = kTemp},
    {.set = 0x80, .desc = 0x17, .name = "scaled pressure", .params = kPressure},
    {.set = 0x80, .desc = 0x18, .name = "overrange status", .params = kOverrange},
    {.set = 0x80, .desc = 0x40, .name = "odometer", .params = kOdometer},
    {.set = 0x82, .desc = 0x01, .name = "llh position", .params = kFLlh},
    {.set = 0x82, .desc = 0x02, .name = "velocity ned", .params = kFVel},
    {.set = 0x82, .desc = 0x03, .name = "attitude quaternion", .params = kFQuat},
    {.set = 0x82, .desc = 0x04, .name = "attitude dcm", .params = kFDcm},
    {.set = 0x82, .desc = 0x05, .name = "euler angles", .params = kFEuler},
    {.set = 0x82, .desc = 0x06, .name = "gyro bias", .params = kFGyroBias},
    {.set = 0x82, .desc = 0x07, .name = "accel bias", .params = kFAccelBias},
    {.set = 0x82, .desc = 0x08, .name = "llh position uncertainty", .params = kFPosUnc},
    {.set = 0x82, .desc = 0x09, .name = "velocity ned uncertainty", .params = kFVelUnc},
    {.set = 0x82, .desc = 0x0A, .name = "euler uncertainty", .params = kFEulerUnc},
    {.set = 0x82, .desc = 0x0B, .name = "gyro bias uncertainty", .params = kFGyroBiasUnc},
    {.set = 0x82, .desc = 0x0C, .name = "accel bias uncertainty", .params = kFAccelBiasUnc},
    {.set = 0x82, .desc = 0x0D, .name = "linear accel", .params = kFLinAccel},
    {.set = 0x82, .desc = 0x0E, .name = "compensated angular rate", .params = kFAngRate},
    {.set = 0x82, .desc = 0x10, .name = "filter status", .params = kFStatus},
    {.set = 0x82, .desc = 0x11, .name = "filter timestamp", .params = kFTimestamp},
    {.set = 0x82, .desc = 0x12, .name = "quaternion uncertainty", .params = kFQuatUnc},
    {.set = 0x82, .desc = 0x13, .name = "gravity vector", .params = kFGravity},
    {.set = 0x82, .desc = 0x15, .name = "magnetic model", .params = kFMagModel},
    {.set = 0x82, .desc = 0x1C, .name = "compensated accel", .params = kFCompAccel},
    {.set = 0x82, .desc = 0x21, .name = "pressure altitude", .params = kFPressAlt},
    {.set = 0x82, .desc = 0x34, .name = "multi antenna offset correction", .params = kFAntOffset},
    {.set = 0x82, .desc = 0x35, .name = "multi antenna offset correction uncertainty", .params = kFAntOffsetUnc},
    {.set = 0x82, .desc = 0x36, .name = "ecef position uncertainty", .params = kFEcefPosUnc},
    {.set = 0x82, .desc = 0x37, .name = "ecef velocity uncertainty", .params = kFEcefVelUnc},
    {.set = 0x82, .desc = 0x40, .name = "ecef position", .params = kFEcefPos},
    {.set = 0x82, .desc = 0x41, .name = "ecef velocity", .params = kFEcefVel},
    {.set = 0x82, .desc = 0x42, .name = "ned relative position", .params = kFRelPos},
    {.set = 0x82, .desc = 0x43, .name = "gnss position aiding status", .params = kFGnssAid},
    {.set = 0x82, .desc = 0x46, .name = "aiding measurement summary", .params = kFAidSummary},
    {.set = 0x82, .desc = 0x47, .name = "odometer scale factor error", .params = kFOdoSf},
    {.set = 0x82, .desc = 0x48, .name = "odometer scale factor error uncertainty", .params = kFOdoSfUnc},
    {.set = 0x82, .desc = 0x49, .name = "gnss dual antenna status", .params = kFDualAnt},
    {.set = 0x82, .desc = 0x50, .name = "aiding frame config error", .params = kFFrameErr},
    {.set = 0x82, .desc = 0x51, .name = "aiding frame config error uncertainty", .params = kFFrameErrUnc},
    {.set = 0x91, .desc = 0x03, .name = "gnss llh position", .params = kGLlh},
    {.set = 0x91, .desc = 0x04, .name = "gnss ecef position", .params = kGEcefPos},
    {.set = 0x91, .desc = 0x05, .name = "gnss ned velocity", .params = kGVelNed},
    {.set = 0x91, .desc = 0x06, .name = "gnss ecef velocity", .params = kGEcefVel},
    {.set = 0x91, .desc = 0x07, .name = "gnss dop", .params = kGDop},
    {.set = 0x91, .desc = 0x08, .name = "gnss utc time", .params = kGUtc},
    {.set = 0x91, .desc = 0x09, .name = "gnss gps time", .params = kGGpsTime},
    {.set = 0x91, .desc = 0x0B, .name = "gnss fix info", .params = kGFix},
    {.set = 0x91, .desc = 0x0D, .name = "gnss hardware status", .params = kGHw},
    {.set = 0x91, .desc = 0x10, .name = "gnss clock info", .params = kGClock},
    {.set = 0x91, .desc = 0x11, .name = "gnss leap seconds", .params = kGLeap},
    {.set = 0x91, .desc = 0x12, .name = "gnss sbas info", .params = kGSbas},
    {.set = 0x91, .desc = 0x20, .name = "gnss satellite status", .params = kGSat},
    {.set = 0x91, .desc = 0x22, .name = "gnss raw observation", .params = kGRaw},
    {.set = 0x91, .desc = 0x61, .name = "gps ephemeris", .params = kGEph},
    {.set = 0x91, .desc = 0x62, .name = "glonass ephemeris", .params = kGGloEph},
    {.set = 0x91, .desc = 0x63, .name = "galileo ephemeris", .params = kGEph},
    {.set = 0x91, .desc = 0x64, .name = "beidou ephemeris", .params = kGEph},
    {.set = 0x93, .desc = 0x30, .name = "base station info", .params = kCBase},
    {.set = 0x93, .desc = 0x31, .name = "rtk corrections status", .params = kCRtk},
    {.set = 0xA0, .desc = 0x01, .name = "built in test", .params = kSBit},
    {.set = 0xA0, .desc = 0x02, .name = "time sync status", .params = kSTimeSync},
    {.set = 0xA0, .desc = 0x03, .name = "gpio state", .params = kSGpio},
};

}  // namespace

std::span<const FieldSchema> data_schemas() { return kData; }

}  // namespace navfuse::frontends::mip
