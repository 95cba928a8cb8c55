// The nav process's FusionEngine link answers configuration commands through the front-end's
// device-compatible handler and turns what they change into engine actions: a GNSS lever arm
// set in FLU reaches the engine in FRD, a device orientation as a mounting in radians, and
// GetConfig reports what was set. Until a client changes a rate, the link streams the messages
// replay writes to an --fe-out file for the same epochs, plus the device's 1 s CalibrationStatus
// and SystemStatus. Everything on the link, command responses included, is numbered by one
// sequence counter (spec L190); VersionInfo comes from the build; resets and configuration
// changes are announced as EventNotifications (spec L2615-2642). Sensor inputs sent on the link
// become measurements on the link's clock.
#include <gtest/gtest.h>

#include <sys/utsname.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "apps/output/fe_epoch_encoder.hpp"
#include "apps/run/fe_device_emulator.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/messages_sensor.hpp"
#include "frontends/fusionengine/payload_reader.hpp"
#include "fe_link_reply.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

TEST(FeDeviceEmulator, SetConfigLeverArmBecomesAnEngineActionAndGetConfigReportsIt) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  host.set_next_sequence(7);
  fe::SetConfigMessage set;
  set.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  set.value = fe::pack_config(fe::Point3f{{1.5f, 0.25f, 0.75f}});  // FLU: forward, left, up

  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  emulator->receive(1, host.frame(set), reply, effects);
  Reply r = parse_reply(reply);
  ASSERT_EQ(r.types.size(), 1u);
  EXPECT_EQ(r.types[0], fe::to_u16(fe::MessageType::kCommandResponse));
  fe::CommandResponseMessage resp;
  ASSERT_TRUE(fe::decode_payload(r.payloads[0], resp));
  EXPECT_EQ(resp.source_sequence, 7u);
  EXPECT_EQ(resp.response, static_cast<std::uint8_t>(fe::Response::kOk));

  ASSERT_EQ(effects.actions.size(), 1u);
  EXPECT_EQ(effects.actions[0].kind, EngineAction::Kind::kGnssLeverArm);
  EXPECT_EQ(effects.actions[0].antenna, 0);
  // FRD (DESIGN.md): left -> -y, up -> -z.
  EXPECT_TRUE(effects.actions[0].vector.isApprox(Eigen::Vector3d(1.5, -0.25, -0.75)));

  fe::GetConfigMessage get;
  get.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  reply.clear();
  effects.clear();
  emulator->receive(1, host.frame(get), reply, effects);
  r = parse_reply(reply);
  ASSERT_EQ(r.types.size(), 1u);
  EXPECT_EQ(r.types[0], fe::to_u16(fe::MessageType::kConfigResponse));
  fe::ConfigResponseMessage cfg;
  ASSERT_TRUE(fe::decode_payload(r.payloads[0], cfg));
  const auto arm = fe::parse_config<fe::Point3f>(cfg.value);
  ASSERT_TRUE(arm);
  EXPECT_EQ(arm->xyz_m, (std::array<float, 3>{1.5f, 0.25f, 0.75f}));
  EXPECT_TRUE(effects.actions.empty()) << "a GetConfig changes nothing";
}

TEST(FeDeviceEmulator, SameSetConfigTwiceGivesOneAction) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  fe::SetConfigMessage set;
  set.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  set.value = fe::pack_config(fe::Point3f{{0.8f, 0.4f, 1.3f}});
  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  emulator->receive(3, host.frame(set), reply, effects);
  emulator->receive(3, host.frame(set), reply, effects);
  EXPECT_EQ(effects.actions.size(), 1u);
  EXPECT_EQ(parse_reply(reply).types.size(), 2u) << "each request is answered";
}

TEST(FeDeviceEmulator, StreamsWhatTheFileEncoderWritesAtDefaultRates) {
  auto emulator = make_fe_device_emulator(config::Config{});
  FeEpochEncoder file_encoder;
  std::vector<std::uint8_t> streamed, file;
  for (int k = 0; k < 8; ++k) {
    OutputEpoch e;
    e.solution.header.time_ns = 1'000'000'000LL + k * 5'000'000LL;
    e.solution.header.valid = NavSolution::kValidAttitude;
    e.pose_due = k % 2 == 0;
    e.gnss_fused_total = k >= 3 ? 1 : 0;
    e.gnss_updated = k == 4;
    emulator->stream(e, streamed);
    file_encoder.append(e, file);
  }
  const Reply link = parse_reply(streamed);
  const Reply from_file = parse_reply(file);
  EXPECT_EQ(from_file.types.size(), 8u + 4u * 2u + 1u) << "IMUOutput x8, Pose+PoseAux x4, GNSSInfo";
  EXPECT_EQ(link.without_status().types, from_file.types);
  EXPECT_EQ(link.without_status().payloads, from_file.payloads);
  // All 8 epochs are within one second: one of each status message, at the first.
  EXPECT_EQ(link.count(fe::MessageType::kCalibrationStatus), 1u);
  EXPECT_EQ(link.count(fe::MessageType::kSystemStatus), 1u);
  // On a file output of run: byte for byte what replay writes.
  auto file_link = make_fe_device_emulator(config::Config{}, false);
  FeEpochEncoder again;
  std::vector<std::uint8_t> from_run, from_replay;
  for (int k = 0; k < 30; ++k) {
    file_link->stream(epoch_at(k), from_run);
    again.append(epoch_at(k), from_replay);
  }
  EXPECT_EQ(from_run, from_replay);
}

TEST(FeDeviceEmulator, StatusMessagesAtOneHertzUntilAClientTurnsThemOff) {
  auto emulator = make_fe_device_emulator(config::Config{});
  std::vector<std::uint8_t> streamed;
  for (int k = 0; k < 30; ++k) emulator->stream(epoch_at(k), streamed);  // 1.0 s ... 3.9 s
  Reply r = parse_reply(streamed);
  EXPECT_EQ(r.count(fe::MessageType::kCalibrationStatus), 3u);
  EXPECT_EQ(r.count(fe::MessageType::kSystemStatus), 3u);

  fe::FusionEngineWriter host;
  fe::SetMessageRateMessage off;
  off.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
  off.message_id = fe::to_u16(fe::MessageType::kSystemStatus);
  off.rate = static_cast<std::uint8_t>(fe::MessageRate::kOff);
  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  emulator->receive(1, host.frame(off), reply, effects);
  streamed.clear();
  for (int k = 30; k < 60; ++k) emulator->stream(epoch_at(k), streamed);
  r = parse_reply(streamed);
  EXPECT_EQ(r.count(fe::MessageType::kCalibrationStatus), 3u);
  EXPECT_EQ(r.count(fe::MessageType::kSystemStatus), 0u);
}

// The fault the issue names: configuration responses came from a second writer (sequence 0,
// 1, ... beside the stream's). Stream, responses of every kind, stream again: one counter.
TEST(FeDeviceEmulator, OneSequenceCounterForStreamAndEveryResponse) {
  auto emulator = make_fe_device_emulator(config::Config{});
  std::vector<std::uint8_t> link;  // what one client receives, in order
  for (int k = 0; k < 5; ++k) emulator->stream(epoch_at(k), link);

  fe::FusionEngineWriter host;
  fe::SetConfigMessage set;
  set.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  set.value = fe::pack_config(fe::Point3f{{0.5f, 0.0f, 1.0f}});
  fe::GetConfigMessage get;
  get.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  fe::SaveConfigMessage save;
  fe::MessageRequestMessage version;
  version.message_type = fe::to_u16(fe::MessageType::kVersionInfo);
  fe::MessageRequestMessage calibration;
  calibration.message_type = fe::to_u16(fe::MessageType::kCalibrationStatus);
  fe::GetMessageRateMessage rates;
  rates.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
  rates.message_id = fe::kAllMessages;
  CommandEffects effects;
  emulator->receive(1, host.frame(set), link, effects);
  emulator->receive(1, host.frame(get), link, effects);
  emulator->receive(1, host.frame(save), link, effects);
  emulator->receive(1, host.frame(version), link, effects);
  emulator->receive(1, host.frame(calibration), link, effects);
  emulator->receive(1, host.frame(rates), link, effects);
  for (int k = 5; k < 12; ++k) emulator->stream(epoch_at(k), link);

  const Reply r = parse_reply(link);
  ASSERT_GT(r.sequences.size(), 20u);
  for (std::size_t i = 0; i < r.sequences.size(); ++i) {
    ASSERT_EQ(r.sequences[i], i) << "frame " << i << " type " << r.types[i];
  }
  for (auto t : {fe::MessageType::kConfigResponse, fe::MessageType::kVersionInfo, fe::MessageType::kMessageRateResponse,
                 fe::MessageType::kEventNotification}) {
    EXPECT_EQ(r.count(t), 1u) << fe::to_u16(t);
  }
  EXPECT_EQ(r.count(fe::MessageType::kCommandResponse), 2u);      // SetConfig, SaveConfig
  EXPECT_EQ(r.count(fe::MessageType::kCalibrationStatus), 3u);    // 1 s, requested, 2 s
}

// VersionInfo (spec §3.7.3 L2588-2611): lengths at 8-11, strings from 16, not null-terminated,
// the payload padded to a multiple of 4. Firmware names the CMake project version.
TEST(FeDeviceEmulator, VersionInfoFromTheBuild) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  fe::MessageRequestMessage req;
  req.message_type = fe::to_u16(fe::MessageType::kVersionInfo);
  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  emulator->receive(1, host.frame(req), reply, effects);  // before any epoch: still answered
  const Reply r = parse_reply(reply);
  ASSERT_EQ(r.types.size(), 1u);
  ASSERT_EQ(r.types[0], fe::to_u16(fe::MessageType::kVersionInfo));
  const auto& p = r.payloads[0];
  const std::size_t fw = p[8], engine = p[9], os = p[10], rx = p[11];
  EXPECT_EQ(p.size(), (16 + fw + engine + os + rx + 3) / 4 * 4);
  const std::string fw_text(p.begin() + 16, p.begin() + 16 + static_cast<std::ptrdiff_t>(fw));
  EXPECT_EQ(fw_text.rfind(std::string("navfuse ") + NAVFUSE_TEST_PROJECT_VERSION + " (", 0), 0u) << fw_text;
  const std::string engine_text(p.begin() + 16 + static_cast<std::ptrdiff_t>(fw),
                                p.begin() + 16 + static_cast<std::ptrdiff_t>(fw + engine));
  EXPECT_EQ(engine_text, "1.25.0");
  utsname u{};
  ASSERT_EQ(::uname(&u), 0);
  const std::string os_text(p.begin() + 16 + static_cast<std::ptrdiff_t>(fw + engine),
                            p.begin() + 16 + static_cast<std::ptrdiff_t>(fw + engine + os));
  EXPECT_EQ(os_text, std::string(u.sysname) + " " + u.release);
  EXPECT_EQ(rx, 0u) << "navfuse has no receiver firmware of its own";
}

// EventNotification (spec §3.7.4; string at 24 as upstream, digest A5): a reset that the engine
// performs gives RESET with the requested mask as flags (L2639); a SetConfig that changes the
// configuration gives one CONFIG_CHANGE, the same value again none.
TEST(FeDeviceEmulator, ResetAndConfigChangeAreAnnounced) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  std::vector<std::uint8_t> reply, streamed;
  CommandEffects effects;
  fe::ResetRequestMessage reset;
  reset.reset_mask = fe::reset::kResetPositionData | fe::reset::kResetCalibrationData;
  emulator->receive(1, host.frame(reset), reply, effects);
  fe::SetConfigMessage set;
  set.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  set.value = fe::pack_config(fe::Point3f{{1.0f, 0.0f, 0.5f}});
  emulator->receive(1, host.frame(set), reply, effects);
  emulator->receive(1, host.frame(set), reply, effects);
  EXPECT_EQ(parse_reply(reply).count(fe::MessageType::kEventNotification), 0u) << "events go with the stream";
  emulator->stream(epoch_at(0), streamed);
  const Reply r = parse_reply(streamed);
  std::vector<std::vector<std::uint8_t>> events;
  for (std::size_t i = 0; i < r.types.size(); ++i) {
    if (r.types[i] == fe::to_u16(fe::MessageType::kEventNotification)) events.push_back(r.payloads[i]);
  }
  ASSERT_EQ(events.size(), 2u);
  const auto flags_of = [](const std::vector<std::uint8_t>& p) {
    std::uint64_t v = 0;
    std::memcpy(&v, p.data() + 12, 8);
    return v;
  };
  const auto text_of = [](const std::vector<std::uint8_t>& p) {
    const std::size_t n = static_cast<std::size_t>(p[20] | (p[21] << 8));
    EXPECT_EQ(p.size(), 24 + n);
    return std::string(p.begin() + 24, p.begin() + 24 + static_cast<std::ptrdiff_t>(n));
  };
  EXPECT_EQ(events[0][0], 0x01);  // RESET
  EXPECT_EQ(flags_of(events[0]), std::uint64_t{fe::reset::kResetPositionData | fe::reset::kResetCalibrationData});
  EXPECT_FALSE(text_of(events[0]).empty());
  EXPECT_EQ(events[1][0], 0x02);  // CONFIG_CHANGE
  EXPECT_EQ(flags_of(events[1]), 0u);
  EXPECT_FALSE(text_of(events[1]).empty());
  streamed.clear();
  emulator->stream(epoch_at(1), streamed);
  EXPECT_EQ(parse_reply(streamed).count(fe::MessageType::kEventNotification), 0u) << "sent once";
}


// A VehicleSpeedInput cut to 4 bytes of its 28 (a client with a wrong layout).
struct TruncatedSpeedInput {
  static constexpr fe::MessageType kType = fe::MessageType::kVehicleSpeedInput;
  static constexpr std::uint8_t kVersion = 0;
  std::uint32_t head = 0;
  template <class V>
  void visit(V& v) {
    v.field("head", head);
  }
};

TEST(FeDeviceEmulator, SensorInputsOnTheLinkBecomeMeasurementsOnTheStreamsClock) {
  auto emulator = make_fe_device_emulator(config::Config{});
  std::vector<std::uint8_t> out;
  emulator->stream(epoch_at(10), out);  // the link's newest epoch: 2.0 s
  fe::FusionEngineWriter host;

  // P1 time is the link's own (navfuse's GPS time); the Output P1 Time a sender fills in is
  // ignored (spec L302).
  fe::VehicleSpeedInputMessage p1;
  p1.details.time_source = static_cast<std::uint8_t>(fe::SystemTimeSource::kP1Time);
  p1.details.measurement_time = fe::Timestamp{1, 500'000'000};
  p1.details.p1_time = fe::Timestamp{99, 0};
  p1.speed = 2560;  // 2.5 m/s at 2^-10 m/s
  // No time: timestamped on arrival, at the newest epoch's time.
  fe::WheelSpeedInputMessage on_arrival;
  on_arrival.speed = {1024, 2048, fe::kInvalidI32, 4096};
  // The sender's own clock stays its own: the filter rejects it (time_base).
  fe::VehicleTickInputMessage sender;
  sender.details.time_source = static_cast<std::uint8_t>(fe::SystemTimeSource::kSenderSystemTime);
  sender.details.measurement_time = fe::Timestamp{7, 0};
  sender.ticks = 1234;

  std::vector<std::uint8_t> bytes;
  host.append(p1, bytes);
  host.append(on_arrival, bytes);
  host.append(sender, bytes);
  host.append(TruncatedSpeedInput{}, bytes);
  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  emulator->receive(1, bytes, reply, effects);

  EXPECT_TRUE(reply.empty());  // inputs are not commands: no CommandResponse
  EXPECT_TRUE(effects.actions.empty());
  ASSERT_EQ(effects.aiding.size(), 3u);  // the truncated one is dropped
  const auto* v = std::get_if<VehicleSpeed>(&effects.aiding[0]);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->header.time_ns, 1'500'000'000);
  EXPECT_EQ(v->header.time_source, TimeSource::kGps);
  EXPECT_DOUBLE_EQ(v->speed_mps, 2.5);
  const auto* w = std::get_if<WheelSpeeds>(&effects.aiding[1]);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->header.time_ns, 2'000'000'000);
  EXPECT_EQ(w->header.time_source, TimeSource::kGps);
  EXPECT_DOUBLE_EQ(w->speed_mps[0], 1.0);
  EXPECT_DOUBLE_EQ(w->speed_mps[1], 2.0);
  EXPECT_DOUBLE_EQ(w->speed_mps[3], 4.0);
  EXPECT_EQ(w->header.valid & WheelSpeeds::kValidRearLeft, 0u);
  const auto* t = std::get_if<WheelTicks>(&effects.aiding[2]);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->header.time_ns, 7'000'000'000);
  EXPECT_EQ(t->header.time_source, TimeSource::kDeviceMonotonic);
  EXPECT_EQ(t->ticks[0], 1234u);
}

TEST(FeDeviceEmulator, RestartsOfTheFiltersOwnAreAnnouncedOnceEach) {
  auto emulator = make_fe_device_emulator(config::Config{});
  auto file = make_fe_device_emulator(config::Config{}, false);
  std::vector<std::uint8_t> out, file_out;
  const auto stream = [&](int k, std::uint64_t time_gaps, std::uint64_t divergences) {
    OutputEpoch e = epoch_at(k);
    e.time_gap_restarts = time_gaps;
    e.divergence_restarts = divergences;
    emulator->stream(e, out);
    file->stream(e, file_out);
  };
  stream(0, 0, 0);
  stream(1, 1, 0);  // an IMU gap restarted the filter before this epoch
  stream(2, 1, 0);
  stream(3, 1, 2);  // two divergences since the last epoch: one event says it
  stream(4, 1, 2);

  std::vector<std::string> descriptions;
  const Reply reply = parse_reply(out);
  for (std::size_t i = 0; i < reply.types.size(); ++i) {
    const auto& p = reply.payloads[i];
    if (reply.types[i] != fe::to_u16(fe::MessageType::kEventNotification)) continue;
    ASSERT_GE(p.size(), 24u);
    EXPECT_EQ(p[0], 0x01);  // RESET (spec L2635)
    std::uint64_t flags = 0;
    std::memcpy(&flags, p.data() + 12, 8);
    EXPECT_EQ(flags, std::uint64_t{fe::reset::kResetNavigationEngineData});
    descriptions.emplace_back(p.begin() + 24, p.end());
  }
  ASSERT_EQ(descriptions.size(), 2u);
  EXPECT_NE(descriptions[0].find("IMU time gap"), std::string::npos) << descriptions[0];
  EXPECT_NE(descriptions[1].find("diverged"), std::string::npos) << descriptions[1];
  // A file is what replay writes: no events.
  EXPECT_EQ(parse_reply(file_out).count(fe::MessageType::kEventNotification), 0u);
}

}  // namespace
}  // namespace navfuse::apps
