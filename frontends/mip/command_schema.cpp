// Layouts of the commands and their response fields in sets 0x01, 0x0C, 0x0D, 0x0E and 0x13
// (digest §5, §6.4-§6.16, §7; response map §7.7). Lengths follow the parameter lists (errata E1);
// composite types the spec names but never defines (`Time`, `DescriptorRate`, `NmeaMessage`,
// `base_device_info`) use the MIP SDK layouts the digest records in §2.4 (errata E32).
#include "frontends/mip/field_schema.hpp"

namespace navfuse::frontends::mip {
namespace {

using W = WireType;
constexpr Param kNone[] = {{"", W::kU8}};  // never read: only a span of size 0 is taken of it below
constexpr Param kFn[] = {{"function", W::kU8}};

// ---- 0x01 base (digest §7.1, L8006-8188)
constexpr Param kCommPort[] = {{"function", W::kU8}, {"port", W::kU8}, {"baud", W::kU32}};
constexpr Param kTimeUpdate[] = {{"function", W::kU8}, {"field_id", W::kU8}, {"value", W::kU32}};
constexpr Param kDevInfo[] = {{"firmware_version", W::kU16}, {"model_name", W::kChar16}, {"model_number", W::kChar16}, {"serial_number", W::kChar16}, {"lot_number", W::kChar16}, {"device_options", W::kChar16}};
constexpr Param kDescList[] = {{"descriptor", W::kU16}};
constexpr Param kBitResult[] = {{"result", W::kU32}};
constexpr Param kCbit[] = {{"result", W::kBytes16}};
constexpr Param kCommPortResp[] = {{"port", W::kU8}, {"baud", W::kU32}};

// ---- 0x0C 3DM (digest §7.2, L6723-7717)
constexpr Param kPollNmea[] = {{"suppress_ack", W::kBool}, {"count", W::kU8}, {"message_id", W::kU8}, {"talker_id", W::kU8}, {"source_desc_set", W::kU8}, {"decimation", W::kU16}};
constexpr Param kNmeaFormat[] = {{"function", W::kU8}, {"count", W::kU8}, {"message_id", W::kU8}, {"talker_id", W::kU8}, {"source_desc_set", W::kU8}, {"decimation", W::kU16}};
constexpr Param kNmeaFormatResp[] = {{"count", W::kU8}, {"message_id", W::kU8}, {"talker_id", W::kU8}, {"source_desc_set", W::kU8}, {"decimation", W::kU16}};
constexpr Param kPollData[] = {{"desc_set", W::kU8}, {"suppress_ack", W::kBool}, {"num_descriptors", W::kU8}, {"descriptor", W::kU8}};
constexpr Param kDescSet[] = {{"desc_set", W::kU8}};
constexpr Param kBaseRateResp[] = {{"desc_set", W::kU8}, {"rate", W::kU16, "hz"}};
constexpr Param kMsgFormat[] = {{"function", W::kU8}, {"desc_set", W::kU8}, {"num_descriptors", W::kU8}, {"descriptor", W::kU8}, {"decimation", W::kU16}};
constexpr Param kMsgFormatResp[] = {{"desc_set", W::kU8}, {"num_descriptors", W::kU8}, {"descriptor", W::kU8}, {"decimation", W::kU16}};
constexpr Param kFactoryStreaming[] = {{"action", W::kU8}, {"reserved", W::kU8}};
constexpr Param kStreamCtl[] = {{"function", W::kU8}, {"desc_set", W::kU8}, {"enable", W::kBool}};
constexpr Param kStreamCtlResp[] = {{"desc_set", W::kU8}, {"enable", W::kBool}};
constexpr Param kSbas[] = {{"function", W::kU8}, {"enable", W::kU8}, {"options", W::kU16}, {"num_prns", W::kU8}, {"prn", W::kU16}};
constexpr Param kSbasResp[] = {{"enable", W::kU8}, {"options", W::kU16}, {"num_prns", W::kU8}, {"prn", W::kU16}};
constexpr Param kPps[] = {{"function", W::kU8}, {"source", W::kU8}};
constexpr Param kSource[] = {{"source", W::kU8}};
constexpr Param kQuery[] = {{"query", W::kU8}};
constexpr Param kSupportedEventsResp[] = {{"query", W::kU8}, {"max_instances", W::kU8}, {"num_entries", W::kU8}, {"type", W::kU8}, {"count", W::kU8}};
constexpr Param kEventCtl[] = {{"function", W::kU8}, {"instance", W::kU8}, {"mode", W::kU8}};
constexpr Param kEventCtlResp[] = {{"instance", W::kU8}, {"mode", W::kU8}};
constexpr Param kStatusReq[] = {{"requested_count", W::kU8}, {"instance", W::kU8}};
constexpr Param kTriggerStatusResp[] = {{"count", W::kU8}, {"type", W::kU8}, {"status", W::kU8}};
constexpr Param kActionStatusResp[] = {{"count", W::kU8}, {"action_type", W::kU8}, {"trigger_id", W::kU8}};
constexpr Param kFnInstance[] = {{"function", W::kU8}, {"instance", W::kU8}};
constexpr Param kTrigGpio[] = {{"function", W::kU8}, {"instance", W::kU8}, {"type", W::kU8}, {"pin", W::kU8}, {"mode", W::kU8}};
constexpr Param kTrigThreshold[] = {{"function", W::kU8}, {"instance", W::kU8}, {"type", W::kU8}, {"desc_set", W::kU8}, {"field_desc", W::kU8}, {"param_id", W::kU8}, {"threshold_type", W::kU8}, {"low_or_int_thres", W::kF64}, {"high_thres_or_interval", W::kF64}};
constexpr Param kTrigCombination[] = {{"function", W::kU8}, {"instance", W::kU8}, {"type", W::kU8}, {"logic_table", W::kU16}, {"input_a", W::kU8}, {"input_b", W::kU8}, {"input_c", W::kU8}, {"input_d", W::kU8}};
constexpr Param kTrigGpioResp[] = {{"instance", W::kU8}, {"type", W::kU8}, {"pin", W::kU8}, {"mode", W::kU8}};
constexpr Param kTrigThresholdResp[] = {{"instance", W::kU8}, {"type", W::kU8}, {"desc_set", W::kU8}, {"field_desc", W::kU8}, {"param_id", W::kU8}, {"threshold_type", W::kU8}, {"low_or_int_thres", W::kF64}, {"high_thres_or_interval", W::kF64}};
constexpr Param kTrigCombinationResp[] = {{"instance", W::kU8}, {"type", W::kU8}, {"logic_table", W::kU16}, {"input_a", W::kU8}, {"input_b", W::kU8}, {"input_c", W::kU8}, {"input_d", W::kU8}};
constexpr Param kActGpio[] = {{"function", W::kU8}, {"instance", W::kU8}, {"trigger_id", W::kU8}, {"type", W::kU8}, {"pin", W::kU8}, {"mode", W::kU8}};
constexpr Param kActMessage[] = {{"function", W::kU8}, {"instance", W::kU8}, {"trigger_id", W::kU8}, {"type", W::kU8}, {"desc_set", W::kU8}, {"decimation", W::kU16}, {"num_fields", W::kU8}, {"descriptor", W::kU8}};
constexpr Param kActGpioResp[] = {{"instance", W::kU8}, {"trigger_id", W::kU8}, {"type", W::kU8}, {"pin", W::kU8}, {"mode", W::kU8}};
constexpr Param kActMessageResp[] = {{"instance", W::kU8}, {"trigger_id", W::kU8}, {"type", W::kU8}, {"desc_set", W::kU8}, {"decimation", W::kU16}, {"num_fields", W::kU8}, {"descriptor", W::kU8}};
constexpr Param kEulerCmd[] = {{"function", W::kU8}, {"roll", W::kF32, "rad"}, {"pitch", W::kF32, "rad"}, {"yaw", W::kF32, "rad"}};
constexpr Param kEulerResp[] = {{"roll", W::kF32, "rad"}, {"pitch", W::kF32, "rad"}, {"yaw", W::kF32, "rad"}};
constexpr Param kQuatCmd[] = {{"function", W::kU8}, {"q", W::kQuatf}};
constexpr Param kQuatResp[] = {{"q", W::kQuatf}};
constexpr Param kDcmCmd[] = {{"function", W::kU8}, {"dcm", W::kMat3f}};
constexpr Param kDcmResp[] = {{"dcm", W::kMat3f}};
constexpr Param kAccelBiasCmd[] = {{"function", W::kU8}, {"bias", W::kVec3f, "g"}};
constexpr Param kAccelBiasResp[] = {{"bias", W::kVec3f, "g"}};
constexpr Param kGyroBiasCmd[] = {{"function", W::kU8}, {"bias", W::kVec3f, "radps"}};
constexpr Param kGyroBiasResp[] = {{"bias", W::kVec3f, "radps"}};
constexpr Param kCaptureBias[] = {{"averaging_time", W::kU16, "ms"}};
constexpr Param kHardIronCmd[] = {{"function", W::kU8}, {"offset", W::kVec3f, "gauss"}};
constexpr Param kHardIronResp[] = {{"offset", W::kVec3f, "gauss"}};
constexpr Param kBaudCmd[] = {{"function", W::kU8}, {"baud", W::kU32}};
constexpr Param kBaudResp[] = {{"baud", W::kU32}};
constexpr Param kGpioCfg[] = {{"function", W::kU8}, {"pin", W::kU8}, {"feature", W::kU8}, {"behavior", W::kU8}, {"pin_mode", W::kU8}};
constexpr Param kGpioCfgResp[] = {{"pin", W::kU8}, {"feature", W::kU8}, {"behavior", W::kU8}, {"pin_mode", W::kU8}};
constexpr Param kGpioState[] = {{"function", W::kU8}, {"pin", W::kU8}, {"state", W::kBool}};
constexpr Param kGpioStateResp[] = {{"pin", W::kU8}, {"state", W::kBool}};
constexpr Param kOdoCfg[] = {{"function", W::kU8}, {"mode", W::kU8}, {"scaling", W::kF32, "pulses_per_m"}, {"uncertainty", W::kF32, "m_per_m"}};
constexpr Param kOdoCfgResp[] = {{"mode", W::kU8}, {"scaling", W::kF32, "pulses_per_m"}, {"uncertainty", W::kF32, "m_per_m"}};
constexpr Param kLpfLegacy[] = {{"function", W::kU8}, {"target_desc", W::kU8}, {"enable", W::kBool}, {"manual", W::kBool}, {"frequency", W::kU16, "hz"}, {"reserved", W::kU8}};
constexpr Param kLpfLegacyResp[] = {{"target_desc", W::kU8}, {"enable", W::kBool}, {"manual", W::kBool}, {"frequency", W::kU16, "hz"}, {"reserved", W::kU8}};
constexpr Param kCfCfg[] = {{"function", W::kU8}, {"pitch_roll_enable", W::kBool}, {"heading_enable", W::kBool}, {"pitch_roll_time_constant", W::kF32, "s"}, {"heading_time_constant", W::kF32, "s"}};
constexpr Param kCfCfgResp[] = {{"pitch_roll_enable", W::kBool}, {"heading_enable", W::kBool}, {"pitch_roll_time_constant", W::kF32, "s"}, {"heading_time_constant", W::kF32, "s"}};
constexpr Param kSensorRange[] = {{"function", W::kU8}, {"sensor", W::kU8}, {"setting", W::kU8}};
constexpr Param kSensorRangeResp[] = {{"sensor", W::kU8}, {"setting", W::kU8}};
constexpr Param kSensor[] = {{"sensor", W::kU8}};
constexpr Param kCalRangesResp[] = {{"sensor", W::kU8}, {"num_ranges", W::kU8}, {"setting", W::kU8}, {"range", W::kF32}};
constexpr Param kLpf[] = {{"function", W::kU8}, {"desc_set", W::kU8}, {"field_desc", W::kU8}, {"enable", W::kBool}, {"manual", W::kBool}, {"frequency", W::kF32, "hz"}};
constexpr Param kLpfResp[] = {{"desc_set", W::kU8}, {"field_desc", W::kU8}, {"enable", W::kBool}, {"manual", W::kBool}, {"frequency", W::kF32, "hz"}};

// ---- 0x0D filter (digest §6.4-§6.16, §7.3, L8192-8739)
constexpr Param kHeading[] = {{"heading", W::kF32, "rad"}};
constexpr Param kVecCmdM[] = {{"function", W::kU8}, {"offset", W::kVec3f, "m"}};
constexpr Param kVecRespM[] = {{"offset", W::kVec3f, "m"}};
constexpr Param kGnssSource[] = {{"function", W::kU8}, {"source", W::kU8}};
constexpr Param kExtHeading[] = {{"heading", W::kF32, "rad"}, {"heading_std", W::kF32, "rad"}, {"type", W::kU8}};
constexpr Param kAccelNoise[] = {{"function", W::kU8}, {"noise", W::kVec3f, "mps2"}};
constexpr Param kAccelNoiseResp[] = {{"noise", W::kVec3f, "mps2"}};
constexpr Param kGyroNoise[] = {{"function", W::kU8}, {"noise", W::kVec3f, "radps"}};
constexpr Param kGyroNoiseResp[] = {{"noise", W::kVec3f, "radps"}};
constexpr Param kAccelBiasModel[] = {{"function", W::kU8}, {"beta", W::kVec3f, "per_s"}, {"noise", W::kVec3f, "mps2"}};
constexpr Param kAccelBiasModelResp[] = {{"beta", W::kVec3f, "per_s"}, {"noise", W::kVec3f, "mps2"}};
constexpr Param kGyroBiasModel[] = {{"function", W::kU8}, {"beta", W::kVec3f, "per_s"}, {"noise", W::kVec3f, "radps"}};
constexpr Param kGyroBiasModelResp[] = {{"beta", W::kVec3f, "per_s"}, {"noise", W::kVec3f, "radps"}};
constexpr Param kExtHeadingTime[] = {{"gps_tow", W::kF64, "s"}, {"gps_week", W::kU16}, {"heading", W::kF32, "rad"}, {"heading_std", W::kF32, "rad"}, {"type", W::kU8}};
constexpr Param kZaru[] = {{"function", W::kU8}, {"enable", W::kU8}, {"threshold", W::kF32, "radps"}};
constexpr Param kZaruResp[] = {{"enable", W::kU8}, {"threshold", W::kF32, "radps"}};
// Errata E12: the doc prints gravity noise in [gauss]; m/s^2 is meant.
constexpr Param kGravityNoise[] = {{"function", W::kU8}, {"noise", W::kVec3f, "mps2"}};
constexpr Param kDeclination[] = {{"function", W::kU8}, {"source", W::kU8}, {"declination", W::kF32, "rad"}};
constexpr Param kDeclinationResp[] = {{"source", W::kU8}, {"declination", W::kF32, "rad"}};
constexpr Param kAidingCtl[] = {{"function", W::kU8}, {"aiding_source", W::kU16}, {"enable", W::kBool}};
constexpr Param kAidingCtlResp[] = {{"aiding_source", W::kU16}, {"enable", W::kBool}};
// Errata E20: initial attitude is in degrees as documented (L8556-8558).
constexpr Param kInit[] = {{"function", W::kU8}, {"wait_for_run_command", W::kU8}, {"initial_cond_src", W::kU8}, {"auto_heading_alignment_selector", W::kU8}, {"initial_heading", W::kF32, "deg"}, {"initial_pitch", W::kF32, "deg"}, {"initial_roll", W::kF32, "deg"}, {"initial_position", W::kVec3f}, {"initial_velocity", W::kVec3f, "mps"}, {"reference_frame_selector", W::kU8}};
constexpr Param kInitResp[] = {{"wait_for_run_command", W::kU8}, {"initial_cond_src", W::kU8}, {"auto_heading_alignment_selector", W::kU8}, {"initial_heading", W::kF32, "deg"}, {"initial_pitch", W::kF32, "deg"}, {"initial_roll", W::kF32, "deg"}, {"initial_position", W::kVec3f}, {"initial_velocity", W::kVec3f, "mps"}, {"reference_frame_selector", W::kU8}};
constexpr Param kAdaptive[] = {{"function", W::kU8}, {"level", W::kU8}, {"time_limit", W::kU16, "ms"}};
constexpr Param kAdaptiveResp[] = {{"level", W::kU8}, {"time_limit", W::kU16, "ms"}};
constexpr Param kMultiAnt[] = {{"function", W::kU8}, {"receiver_id", W::kU8}, {"antenna_offset", W::kVec3f, "m"}};
constexpr Param kMultiAntResp[] = {{"receiver_id", W::kU8}, {"antenna_offset", W::kVec3f, "m"}};
constexpr Param kRelPos[] = {{"function", W::kU8}, {"source", W::kU8}, {"reference_frame_selector", W::kU8}, {"reference_coordinates", W::kVec3d}};
constexpr Param kRelPosResp[] = {{"source", W::kU8}, {"reference_frame_selector", W::kU8}, {"reference_coordinates", W::kVec3d}};
constexpr Param kRefLever[] = {{"function", W::kU8}, {"ref_point_sel", W::kU8}, {"lever_arm_offset", W::kVec3f, "m"}};
constexpr Param kRefLeverResp[] = {{"ref_point_sel", W::kU8}, {"lever_arm_offset", W::kVec3f, "m"}};
constexpr Param kEnable[] = {{"function", W::kU8}, {"enable", W::kU8}};
constexpr Param kEnableResp[] = {{"enable", W::kU8}};
constexpr Param kAntCal[] = {{"function", W::kU8}, {"enable", W::kU8}, {"max_offset", W::kF32, "m"}};
constexpr Param kAntCalResp[] = {{"enable", W::kU8}, {"max_offset", W::kF32, "m"}};

// ---- 0x0E GNSS (digest §7.4, L8747-8831)
constexpr Param kRecvInfoResp[] = {{"num_receivers", W::kU8}, {"receiver_id", W::kU8}, {"mip_desc_set", W::kU8}, {"description", W::kChar32}};
constexpr Param kSignalCfg[] = {{"function", W::kU8}, {"gps_enable", W::kU8}, {"glonass_enable", W::kU8}, {"galileo_enable", W::kU8}, {"beidou_enable", W::kU8}, {"reserved", W::kU32}};
constexpr Param kSignalCfgResp[] = {{"gps_enable", W::kU8}, {"glonass_enable", W::kU8}, {"galileo_enable", W::kU8}, {"beidou_enable", W::kU8}, {"reserved", W::kU32}};
constexpr Param kSpartn[] = {{"function", W::kU8}, {"enable", W::kU8}, {"type", W::kU8}, {"current_key_tow", W::kU32, "s"}, {"current_key_week", W::kU16}, {"current_key", W::kChar32}, {"next_key_tow", W::kU32, "s"}, {"next_key_week", W::kU16}, {"next_key", W::kChar32}};
constexpr Param kSpartnResp[] = {{"enable", W::kU8}, {"type", W::kU8}, {"current_key_tow", W::kU32, "s"}, {"current_key_week", W::kU16}, {"current_key", W::kChar32}, {"next_key_tow", W::kU32, "s"}, {"next_key_week", W::kU16}, {"next_key", W::kChar32}};

// ---- 0x13 aiding (digest §5, L7721-8000). `Time` = u8 timebase, u8 reserved, u64 ns (§5.1).
constexpr Param kFrameEuler[] = {{"function", W::kU8}, {"frame_id", W::kU8}, {"format", W::kU8}, {"tracking_enabled", W::kBool}, {"translation", W::kVec3f, "m"}, {"rotation_euler", W::kVec3f, "rad"}};
constexpr Param kFrameQuat[] = {{"function", W::kU8}, {"frame_id", W::kU8}, {"format", W::kU8}, {"tracking_enabled", W::kBool}, {"translation", W::kVec3f, "m"}, {"rotation_q", W::kQuatf}};
constexpr Param kFrameEulerResp[] = {{"frame_id", W::kU8}, {"format", W::kU8}, {"tracking_enabled", W::kBool}, {"translation", W::kVec3f, "m"}, {"rotation_euler", W::kVec3f, "rad"}};
constexpr Param kFrameQuatResp[] = {{"frame_id", W::kU8}, {"format", W::kU8}, {"tracking_enabled", W::kBool}, {"translation", W::kVec3f, "m"}, {"rotation_q", W::kQuatf}};
constexpr Param kEcho[] = {{"function", W::kU8}, {"mode", W::kU8}};
constexpr Param kEchoResp[] = {{"mode", W::kU8}};
#define NAVFUSE_MIP_TIME {"timebase", W::kU8}, {"time_reserved", W::kU8}, {"time", W::kU64, "ns"}, {"frame_id", W::kU8}
constexpr Param kAidEcef[] = {NAVFUSE_MIP_TIME, {"position_ecef", W::kVec3d, "m"}, {"std", W::kVec3f, "m"}, {"valid_flags", W::kU16}};
constexpr Param kAidLlh[] = {NAVFUSE_MIP_TIME, {"lat", W::kF64, "deg"}, {"lon", W::kF64, "deg"}, {"height", W::kF64, "m"}, {"std_ned", W::kVec3f, "m"}, {"valid_flags", W::kU16}};
constexpr Param kAidHeight[] = {NAVFUSE_MIP_TIME, {"height", W::kF32, "m"}, {"std", W::kF32, "m"}, {"valid_flags", W::kU16}};
constexpr Param kAidVel[] = {NAVFUSE_MIP_TIME, {"velocity", W::kVec3f, "mps"}, {"std", W::kVec3f, "mps"}, {"valid_flags", W::kU16}};
constexpr Param kAidHeading[] = {NAVFUSE_MIP_TIME, {"heading", W::kF32, "rad"}, {"std", W::kF32, "rad"}, {"valid_flags", W::kU16}};
constexpr Param kAidMag[] = {NAVFUSE_MIP_TIME, {"field", W::kVec3f, "gauss"}, {"std", W::kVec3f, "gauss"}, {"valid_flags", W::kU16}};
constexpr Param kAidPressure[] = {NAVFUSE_MIP_TIME, {"pressure", W::kF32, "mbar"}, {"std", W::kF32, "mbar"}, {"valid_flags", W::kU16}};
#undef NAVFUSE_MIP_TIME

constexpr Param kAck[] = {{"cmd_descriptor", W::kU8}, {"reply_code", W::kU8}};

constexpr std::span<const Param> kEmpty(kNone, 0);

constexpr FieldSchema kCommands[] = {
    {.set = 0x00, .desc = 0xF1, .name = "ack/nack", .params = kAck},
    // 0x01
    {.set = 0x01, .desc = 0x01, .name = "ping", .params = kEmpty},
    {.set = 0x01, .desc = 0x02, .name = "set to idle", .params = kEmpty},
    {.set = 0x01, .desc = 0x03, .name = "get device info", .params = kEmpty},
    {.set = 0x01, .desc = 0x04, .name = "get device descriptors", .params = kEmpty},
    {.set = 0x01, .desc = 0x05, .name = "built-in test", .params = kEmpty},
    {.set = 0x01, .desc = 0x06, .name = "resume", .params = kEmpty},
    {.set = 0x01, .desc = 0x07, .name = "get extended descriptors", .params = kEmpty},
    {.set = 0x01, .desc = 0x08, .name = "continuous bit", .params = kEmpty},
    {.set = 0x01, .desc = 0x09, .name = "comm port speed", .params = kCommPort, .has_function = true, .key_params = 1},
    {.set = 0x01, .desc = 0x72, .name = "gps time update", .params = kTimeUpdate, .has_function = true, .key_params = 1},
    {.set = 0x01, .desc = 0x7E, .name = "reset device", .params = kEmpty},
    {.set = 0x01, .desc = 0x81, .name = "device info", .params = kDevInfo},
    {.set = 0x01, .desc = 0x82, .name = "device descriptors", .params = kDescList, .repeat_from = 0},
    {.set = 0x01, .desc = 0x83, .name = "built-in test result", .params = kBitResult},
    {.set = 0x01, .desc = 0x86, .name = "extended descriptors", .params = kDescList, .repeat_from = 0},
    {.set = 0x01, .desc = 0x88, .name = "continuous bit result", .params = kCbit},
    {.set = 0x01, .desc = 0x89, .name = "comm port speed", .params = kCommPortResp},
    // 0x0C
    {.set = 0x0C, .desc = 0x04, .name = "poll nmea data", .params = kPollNmea, .repeat_from = 2},
    {.set = 0x0C, .desc = 0x0C, .name = "nmea message format", .params = kNmeaFormat, .repeat_from = 2, .has_function = true},
    {.set = 0x0C, .desc = 0x0D, .name = "poll data", .params = kPollData, .repeat_from = 3},
    {.set = 0x0C, .desc = 0x0E, .name = "get data base rate", .params = kDescSet},
    {.set = 0x0C, .desc = 0x0F, .name = "message format", .params = kMsgFormat, .repeat_from = 3, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x10, .name = "factory streaming", .params = kFactoryStreaming},
    {.set = 0x0C, .desc = 0x11, .name = "data stream control", .params = kStreamCtl, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x22, .name = "gnss sbas settings", .params = kSbas, .repeat_from = 4, .has_function = true},
    {.set = 0x0C, .desc = 0x28, .name = "pps source", .params = kPps, .has_function = true},
    {.set = 0x0C, .desc = 0x2A, .name = "get supported events", .params = kQuery},
    {.set = 0x0C, .desc = 0x2B, .name = "event control", .params = kEventCtl, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2C, .name = "get event trigger status", .params = kStatusReq, .repeat_from = 1},
    {.set = 0x0C, .desc = 0x2D, .name = "get event action status", .params = kStatusReq, .repeat_from = 1},
    {.set = 0x0C, .desc = 0x2E, .name = "event trigger gpio", .params = kTrigGpio, .variant_offset = 2, .variant_value = 1, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2E, .name = "event trigger threshold", .params = kTrigThreshold, .variant_offset = 2, .variant_value = 2, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2E, .name = "event trigger combination", .params = kTrigCombination, .variant_offset = 2, .variant_value = 3, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2E, .name = "event trigger", .params = kFnInstance, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2F, .name = "event action gpio", .params = kActGpio, .variant_offset = 3, .variant_value = 1, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2F, .name = "event action message", .params = kActMessage, .repeat_from = 7, .variant_offset = 3, .variant_value = 2, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x2F, .name = "event action", .params = kFnInstance, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x30, .name = "device startup settings", .params = kFn, .has_function = true},
    {.set = 0x0C, .desc = 0x31, .name = "sensor to vehicle euler", .params = kEulerCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x32, .name = "sensor to vehicle quaternion", .params = kQuatCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x33, .name = "sensor to vehicle dcm", .params = kDcmCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x37, .name = "accel bias", .params = kAccelBiasCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x38, .name = "gyro bias", .params = kGyroBiasCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x39, .name = "capture gyro bias", .params = kCaptureBias},
    {.set = 0x0C, .desc = 0x3A, .name = "mag hard iron offset", .params = kHardIronCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x3B, .name = "mag soft iron matrix", .params = kDcmCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x40, .name = "uart baudrate", .params = kBaudCmd, .has_function = true},
    {.set = 0x0C, .desc = 0x41, .name = "gpio config", .params = kGpioCfg, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x42, .name = "gpio state", .params = kGpioState, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x43, .name = "odometer config", .params = kOdoCfg, .has_function = true},
    {.set = 0x0C, .desc = 0x50, .name = "low-pass filter (legacy)", .params = kLpfLegacy, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x51, .name = "complementary filter config", .params = kCfCfg, .has_function = true},
    {.set = 0x0C, .desc = 0x52, .name = "sensor range", .params = kSensorRange, .has_function = true, .key_params = 1},
    {.set = 0x0C, .desc = 0x53, .name = "get calibrated sensor ranges", .params = kSensor},
    {.set = 0x0C, .desc = 0x54, .name = "low-pass anti-aliasing filter", .params = kLpf, .has_function = true, .key_params = 2},
    {.set = 0x0C, .desc = 0x8C, .name = "nmea message format", .params = kNmeaFormatResp, .repeat_from = 1},
    {.set = 0x0C, .desc = 0x8E, .name = "data base rate", .params = kBaseRateResp},
    {.set = 0x0C, .desc = 0x8F, .name = "message format", .params = kMsgFormatResp, .repeat_from = 2},
    {.set = 0x0C, .desc = 0x85, .name = "data stream control", .params = kStreamCtlResp},
    {.set = 0x0C, .desc = 0xA1, .name = "gnss sbas settings", .params = kSbasResp, .repeat_from = 3},
    {.set = 0x0C, .desc = 0xA8, .name = "pps source", .params = kSource},
    {.set = 0x0C, .desc = 0xB4, .name = "supported events", .params = kSupportedEventsResp, .repeat_from = 3},
    {.set = 0x0C, .desc = 0xB5, .name = "event control", .params = kEventCtlResp},
    {.set = 0x0C, .desc = 0xB6, .name = "event trigger status", .params = kTriggerStatusResp, .repeat_from = 1},
    {.set = 0x0C, .desc = 0xB7, .name = "event action status", .params = kActionStatusResp, .repeat_from = 1},
    {.set = 0x0C, .desc = 0xB8, .name = "event trigger gpio", .params = kTrigGpioResp, .variant_offset = 1, .variant_value = 1},
    {.set = 0x0C, .desc = 0xB8, .name = "event trigger threshold", .params = kTrigThresholdResp, .variant_offset = 1, .variant_value = 2},
    {.set = 0x0C, .desc = 0xB8, .name = "event trigger combination", .params = kTrigCombinationResp, .variant_offset = 1, .variant_value = 3},
    {.set = 0x0C, .desc = 0xB9, .name = "event action gpio", .params = kActGpioResp, .variant_offset = 2, .variant_value = 1},
    {.set = 0x0C, .desc = 0xB9, .name = "event action message", .params = kActMessageResp, .repeat_from = 6, .variant_offset = 2, .variant_value = 2},
    {.set = 0x0C, .desc = 0xB1, .name = "sensor to vehicle euler", .params = kEulerResp},
    {.set = 0x0C, .desc = 0xB2, .name = "sensor to vehicle quaternion", .params = kQuatResp},
    {.set = 0x0C, .desc = 0xB3, .name = "sensor to vehicle dcm", .params = kDcmResp},
    {.set = 0x0C, .desc = 0x9A, .name = "accel bias", .params = kAccelBiasResp},
    {.set = 0x0C, .desc = 0x9B, .name = "gyro bias", .params = kGyroBiasResp},
    {.set = 0x0C, .desc = 0x9C, .name = "mag hard iron offset", .params = kHardIronResp},
    {.set = 0x0C, .desc = 0x9D, .name = "mag soft iron matrix", .params = kDcmResp},
    {.set = 0x0C, .desc = 0x87, .name = "uart baudrate", .params = kBaudResp},
    {.set = 0x0C, .desc = 0xC1, .name = "gpio config", .params = kGpioCfgResp},
    {.set = 0x0C, .desc = 0xC2, .name = "gpio state", .params = kGpioStateResp},
    {.set = 0x0C, .desc = 0xC3, .name = "odometer config", .params = kOdoCfgResp},
    {.set = 0x0C, .desc = 0x8B, .name = "low-pass filter (legacy)", .params = kLpfLegacyResp},
    {.set = 0x0C, .desc = 0x97, .name = "complementary filter config", .params = kCfCfgResp},
    {.set = 0x0C, .desc = 0xD2, .name = "sensor range", .params = kSensorRangeResp},
    {.set = 0x0C, .desc = 0xD3, .name = "calibrated sensor ranges", .params = kCalRangesResp, .repeat_from = 2},
    {.set = 0x0C, .desc = 0xD4, .name = "low-pass anti-aliasing filter", .params = kLpfResp},
    // 0x0D
    {.set = 0x0D, .desc = 0x01, .name = "reset navigation filter", .params = kEmpty},
    {.set = 0x0D, .desc = 0x03, .name = "set initial heading", .params = kHeading},
    {.set = 0x0D, .desc = 0x05, .name = "run navigation filter", .params = kEmpty},
    {.set = 0x0D, .desc = 0x13, .name = "gnss antenna offset", .params = kVecCmdM, .has_function = true},
    {.set = 0x0D, .desc = 0x15, .name = "gnss aiding source", .params = kGnssSource, .has_function = true},
    {.set = 0x0D, .desc = 0x17, .name = "external heading update", .params = kExtHeading},
    {.set = 0x0D, .desc = 0x1A, .name = "accel noise std", .params = kAccelNoise, .has_function = true},
    {.set = 0x0D, .desc = 0x1B, .name = "gyro noise std", .params = kGyroNoise, .has_function = true},
    {.set = 0x0D, .desc = 0x1C, .name = "accel bias model", .params = kAccelBiasModel, .has_function = true},
    {.set = 0x0D, .desc = 0x1D, .name = "gyro bias model", .params = kGyroBiasModel, .has_function = true},
    {.set = 0x0D, .desc = 0x1F, .name = "external heading update with time", .params = kExtHeadingTime},
    {.set = 0x0D, .desc = 0x20, .name = "zero angular rate update", .params = kZaru, .has_function = true},
    {.set = 0x0D, .desc = 0x28, .name = "gravity noise std", .params = kGravityNoise, .has_function = true},
    {.set = 0x0D, .desc = 0x43, .name = "declination source", .params = kDeclination, .has_function = true},
    {.set = 0x0D, .desc = 0x50, .name = "aiding measurement control", .params = kAidingCtl, .has_function = true, .key_params = 1},
    {.set = 0x0D, .desc = 0x52, .name = "navigation filter initialization", .params = kInit, .has_function = true},
    {.set = 0x0D, .desc = 0x53, .name = "adaptive filter", .params = kAdaptive, .has_function = true},
    {.set = 0x0D, .desc = 0x54, .name = "gnss multi-antenna offset", .params = kMultiAnt, .has_function = true, .key_params = 1},
    {.set = 0x0D, .desc = 0x55, .name = "relative position config", .params = kRelPos, .has_function = true},
    {.set = 0x0D, .desc = 0x56, .name = "reference point lever arm", .params = kRefLever, .has_function = true},
    {.set = 0x0D, .desc = 0x61, .name = "speed measurement lever arm", .params = kRefLever, .has_function = true, .key_params = 1},
    {.set = 0x0D, .desc = 0x63, .name = "wheeled vehicle constraint", .params = kEnable, .has_function = true},
    {.set = 0x0D, .desc = 0x64, .name = "gnss antenna offset calibration", .params = kAntCal, .has_function = true},
    {.set = 0x0D, .desc = 0x83, .name = "gnss antenna offset", .params = kVecRespM},
    {.set = 0x0D, .desc = 0x86, .name = "gnss aiding source", .params = kSource},
    {.set = 0x0D, .desc = 0x89, .name = "accel noise std", .params = kAccelNoiseResp},
    {.set = 0x0D, .desc = 0x8A, .name = "gyro noise std", .params = kGyroNoiseResp},
    {.set = 0x0D, .desc = 0x8B, .name = "accel bias model", .params = kAccelBiasModelResp},
    {.set = 0x0D, .desc = 0x8C, .name = "gyro bias model", .params = kGyroBiasModelResp},
    {.set = 0x0D, .desc = 0x8E, .name = "zero angular rate update", .params = kZaruResp},
    {.set = 0x0D, .desc = 0x93, .name = "gravity noise std", .params = kAccelNoiseResp},
    {.set = 0x0D, .desc = 0xB2, .name = "declination source", .params = kDeclinationResp},
    {.set = 0x0D, .desc = 0xD0, .name = "aiding measurement control", .params = kAidingCtlResp},
    {.set = 0x0D, .desc = 0xD2, .name = "navigation filter initialization", .params = kInitResp},
    {.set = 0x0D, .desc = 0xD3, .name = "adaptive filter", .params = kAdaptiveResp},
    {.set = 0x0D, .desc = 0xD4, .name = "gnss multi-antenna offset", .params = kMultiAntResp},
    {.set = 0x0D, .desc = 0xD5, .name = "relative position config", .params = kRelPosResp},
    {.set = 0x0D, .desc = 0xD6, .name = "reference point lever arm", .params = kRefLeverResp},
    {.set = 0x0D, .desc = 0xE1, .name = "speed measurement lever arm", .params = kRefLeverResp},
    {.set = 0x0D, .desc = 0xE3, .name = "wheeled vehicle constraint", .params = kEnableResp},
    {.set = 0x0D, .desc = 0xE4, .name = "gnss antenna offset calibration", .params = kAntCalResp},
    // 0x0E
    {.set = 0x0E, .desc = 0x01, .name = "receiver info", .params = kEmpty},
    {.set = 0x0E, .desc = 0x02, .name = "signal configuration", .params = kSignalCfg, .has_function = true},
    {.set = 0x0E, .desc = 0x20, .name = "spartn configuration", .params = kSpartn, .has_function = true},
    {.set = 0x0E, .desc = 0x81, .name = "receiver info", .params = kRecvInfoResp, .repeat_from = 1},
    {.set = 0x0E, .desc = 0x82, .name = "signal configuration", .params = kSignalCfgResp},
    {.set = 0x0E, .desc = 0xA0, .name = "spartn configuration", .params = kSpartnResp},
    // 0x13. Errata E9: an EULER frame rotation is 3 floats (SDK), a QUATERNION 4.
    {.set = 0x13, .desc = 0x01, .name = "aiding frame config euler", .params = kFrameEuler, .variant_offset = 2, .variant_value = 1, .has_function = true, .key_params = 2},
    {.set = 0x13, .desc = 0x01, .name = "aiding frame config quaternion", .params = kFrameQuat, .variant_offset = 2, .variant_value = 2, .has_function = true, .key_params = 2},
    {.set = 0x13, .desc = 0x01, .name = "aiding frame config", .params = kFnInstance, .has_function = true, .key_params = 1},
    {.set = 0x13, .desc = 0x81, .name = "aiding frame config euler", .params = kFrameEulerResp, .variant_offset = 1, .variant_value = 1},
    {.set = 0x13, .desc = 0x81, .name = "aiding frame config quaternion", .params = kFrameQuatResp, .variant_offset = 1, .variant_value = 2},
    {.set = 0x13, .desc = 0x1F, .name = "aiding echo control", .params = kEcho, .has_function = true},
    {.set = 0x13, .desc = 0x9F, .name = "aiding echo control", .params = kEchoResp},
    {.set = 0x13, .desc = 0x21, .name = "ecef position aiding", .params = kAidEcef},
    {.set = 0x13, .desc = 0x22, .name = "llh position aiding", .params = kAidLlh},
    {.set = 0x13, .desc = 0x23, .name = "height above ellipsoid aiding", .params = kAidHeight},
    {.set = 0x13, .desc = 0x28, .name = "ecef velocity aiding", .params = kAidVel},
    {.set = 0x13, .desc = 0x29, .name = "ned velocity aiding", .params = kAidVel},
    {.set = 0x13, .desc = 0x2A, .name = "body frame velocity aiding", .params = kAidVel},
    // Errata E10: true heading is 0x31 (L7950), not the overview page's 0x3A (L807).
    {.set = 0x13, .desc = 0x31, .name = "true heading aiding", .params = kAidHeading},
    {.set = 0x13, .desc = 0x32, .name = "magnetic field aiding", .params = kAidMag},
    {.set = 0x13, .desc = 0x33, .name = "pressure aiding", .params = kAidPressure},
};

}  // namespace

std::span<const FieldSchema> command_schemas() { return kCommands; }

}  // namespace navfuse::frontends::mip
