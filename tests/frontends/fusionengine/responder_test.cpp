// The device-compatible command handler answers like a device: right response message and
// code, config and rate changes visible in core types, reset mask reported, never a crash.
#include <gtest/gtest.h>

#include <cmath>

#include "frontends/fusionengine/responder.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

struct Reply {
  std::vector<test::OwnedFrame> frames;
};

Reply send(DeviceControl& dc, const std::vector<std::uint8_t>& request) {
  std::vector<std::uint8_t> out;
  dc.feed(request, out);
  return {test::frames_of(out)};
}

template <class M>
M payload_as(const test::OwnedFrame& f) {
  M m;
  EXPECT_TRUE(decode_payload(f.view().payload, m));
  return m;
}

std::uint8_t code_of(const Reply& r, std::uint32_t expected_sequence) {
  EXPECT_EQ(r.frames.size(), 1u);
  if (r.frames.empty()) return 0xFF;
  EXPECT_EQ(r.frames[0].header.message_type, to_u16(MessageType::kCommandResponse));
  const auto resp = payload_as<CommandResponseMessage>(r.frames[0]);
  EXPECT_EQ(resp.source_sequence, expected_sequence);
  return resp.response;
}

TEST(FeDeviceControl, GnssLeverArmSetChangesConfigAndGetReportsIt) {
  DeviceControl dc(config::Config{});
  FusionEngineWriter host;
  host.set_next_sequence(41);
  SetConfigMessage set;
  set.config_type = to_u16(ConfigType::kGnssLeverArm);
  set.value = pack_config(Point3f{{1.5f, 0.25f, 0.75f}});  // FLU: forward, left, up
  EXPECT_EQ(code_of(send(dc, host.frame(set)), 41), static_cast<std::uint8_t>(Response::kOk));
  // navfuse config is FRD (DESIGN.md): left -> -y, up -> -z.
  EXPECT_EQ(dc.config().gnss.lever_arm_m, (config::Vec3{1.5, -0.25, -0.75}));

  GetConfigMessage get;
  get.config_type = to_u16(ConfigType::kGnssLeverArm);
  const Reply r = send(dc, host.frame(get));
  ASSERT_EQ(r.frames.size(), 1u);
  ASSERT_EQ(r.frames[0].header.message_type, to_u16(MessageType::kConfigResponse));
  const auto resp = payload_as<ConfigResponseMessage>(r.frames[0]);
  EXPECT_EQ(resp.response, static_cast<std::uint8_t>(Response::kOk));
  EXPECT_EQ(resp.active_differs_from_saved, 1);  // not saved yet
  const auto arm = parse_config<Point3f>(resp.value);
  ASSERT_TRUE(arm);
  EXPECT_EQ(arm->xyz_m, (std::array<float, 3>{1.5f, 0.25f, 0.75f}));
  // Saved copy still the default until SaveConfig.
  get.source = static_cast<std::uint8_t>(ConfigSource::kSaved);
  const auto saved = payload_as<ConfigResponseMessage>(send(dc, host.frame(get)).frames.at(0));
  EXPECT_EQ(parse_config<Point3f>(saved.value)->xyz_m, (std::array<float, 3>{0, 0, 0}));
}

TEST(FeDeviceControl, SpecExampleOrientationLeftUpGivesMountingYaw) {
  // Spec example E7 (L1019-1024): IMU +X pointing left, +Z up, saved at once.
  DeviceControl dc(config::Config{});
  const auto e7 = test::from_hex("2e31 0000 0ac0 a42c 0200 2c33 0000 0000 0c00 0000 0000 0000 1100 0100 0400 0000 0204 0000");
  EXPECT_EQ(code_of(send(dc, e7), 0), static_cast<std::uint8_t>(Response::kOk));
  // IMU axes in FRD: x = left = (0,-1,0), z = up = (0,0,-1), y = z cross x = (-1,0,0).
  // C = [x y z] = yaw -90 deg, roll 180 deg (hand: Rz(-90) Rx(180) has these columns).
  const auto& m = dc.config().imu.mounting_rpy_deg;
  EXPECT_NEAR(std::abs(m[0]), 180.0, 1e-9);
  EXPECT_NEAR(m[1], 0.0, 1e-9);
  EXPECT_NEAR(m[2], -90.0, 1e-9);
  GetConfigMessage get;
  get.config_type = to_u16(ConfigType::kDeviceCoarseOrientation);
  get.source = static_cast<std::uint8_t>(ConfigSource::kSaved);  // APPLY_AND_SAVE was set
  FusionEngineWriter host;
  const auto resp = payload_as<ConfigResponseMessage>(send(dc, host.frame(get)).frames.at(0));
  const auto o = parse_config<CoarseOrientation>(resp.value);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->x_direction, static_cast<std::uint8_t>(Direction::kLeft));
  EXPECT_EQ(o->z_direction, static_cast<std::uint8_t>(Direction::kUp));
}

TEST(FeDeviceControl, InvalidRequestsGetTheSpecsErrorCodes) {
  DeviceControl dc(config::Config{});
  FusionEngineWriter host;
  SetConfigMessage bad_len;  // lever arm with 8 bytes instead of 12
  bad_len.config_type = to_u16(ConfigType::kGnssLeverArm);
  bad_len.value.assign(8, 0);
  EXPECT_EQ(code_of(send(dc, host.frame(bad_len)), 0), static_cast<std::uint8_t>(Response::kInconsistentPayloadLength));
  SetConfigMessage nan_arm;
  nan_arm.config_type = to_u16(ConfigType::kGnssLeverArm);
  nan_arm.value = pack_config(Point3f{{kNanF, 0, 0}});
  EXPECT_EQ(code_of(send(dc, host.frame(nan_arm)), 1), static_cast<std::uint8_t>(Response::kValueError));
  SetConfigMessage same_axes;  // X and Z both forward
  same_axes.config_type = to_u16(ConfigType::kDeviceCoarseOrientation);
  same_axes.value = pack_config(CoarseOrientation{0, 0});
  EXPECT_EQ(code_of(send(dc, host.frame(same_axes)), 2), static_cast<std::uint8_t>(Response::kValueError));
  SetConfigMessage unknown;
  unknown.config_type = 0x400;  // L-band: no such receiver
  unknown.value.assign(28, 0);
  EXPECT_EQ(code_of(send(dc, host.frame(unknown)), 3), static_cast<std::uint8_t>(Response::kUnsupportedFeature));
  MessageRequestMessage req;
  req.message_type = to_u16(MessageType::kPose);
  EXPECT_EQ(code_of(send(dc, host.frame(req)), 4), static_cast<std::uint8_t>(Response::kValueError));
  EXPECT_EQ(code_of(send(dc, host.frame(ShutdownRequestMessage{})), 5),
            static_cast<std::uint8_t>(Response::kUnsupportedFeature));
  // A truncated SaveConfig payload (2 of 4 bytes).
  std::vector<std::uint8_t> shortframe;
  const std::size_t start = begin_frame(shortframe, to_u16(MessageType::kSaveConfig), 0, 6, 0);
  shortframe.insert(shortframe.end(), 2, 0);
  end_frame(shortframe, start);
  EXPECT_EQ(code_of(send(dc, shortframe), 6), static_cast<std::uint8_t>(Response::kInconsistentPayloadLength));
  // Nothing changed.
  EXPECT_EQ(dc.config().gnss.lever_arm_m, (config::Vec3{0, 0, 0}));
}

TEST(FeDeviceControl, ResetVersionAndNoRateTableOfItsOwn) {
  DeviceControl dc(config::Config{});
  FusionEngineWriter host;
  // Spec example E11 (L1490-1497): rates belong to the stream that applies them (the --fe-out
  // link, apps/output/fe_stream_rates.hpp), not to this handler.
  const auto e11 = test::from_hex("2e31 0000 6a84 7724 0200 a433 0000 0000 0c00 0000 0000 0000 0101 0000 0100 1027 0100 0000");
  EXPECT_EQ(code_of(send(dc, e11), 0), static_cast<std::uint8_t>(Response::kUnsupportedFeature));

  // Digest §12.3 cold start (0x00000FFF): reported for the nav process to act on.
  const auto cold = test::from_hex("2e31 0000 9cff e9f8 0200 ca32 0000 0000 0400 0000 0000 0000 ff0f 0000");
  EXPECT_EQ(code_of(send(dc, cold), 0), static_cast<std::uint8_t>(Response::kOk));
  EXPECT_EQ(dc.take_reset_request(), reset::kColdStart);
  EXPECT_FALSE(dc.take_reset_request());
  // Factory reset (E2) includes RESET_CONFIG: configuration back to defaults.
  SetConfigMessage set;
  set.config_type = to_u16(ConfigType::kGnssLeverArm);
  set.value = pack_config(Point3f{{0.5f, 0.0f, 1.0f}});
  EXPECT_EQ(code_of(send(dc, host.frame(set)), 0), static_cast<std::uint8_t>(Response::kOk));
  EXPECT_EQ(dc.config().gnss.lever_arm_m, (config::Vec3{0.5, 0, -1}));
  const auto factory = test::from_hex("2e31 0000 b39e 0bf3 0200 ca32 0000 0000 0400 0000 0000 0000 ffff ffff");
  EXPECT_EQ(code_of(send(dc, factory), 0), static_cast<std::uint8_t>(Response::kOk));
  EXPECT_EQ(dc.config().gnss.lever_arm_m, (config::Vec3{0, 0, 0}));

  MessageRequestMessage req;
  req.message_type = to_u16(MessageType::kVersionInfo);
  const Reply v = send(dc, host.frame(req));
  ASSERT_EQ(v.frames.size(), 1u);
  ASSERT_EQ(v.frames[0].header.message_type, to_u16(MessageType::kVersionInfo));
  EXPECT_EQ(payload_as<VersionInfoMessage>(v.frames[0]).fw_version, "navfuse 0.1.0");
  // Responses are numbered per stream.
  EXPECT_GT(v.frames[0].header.sequence, 0u);
}

// respond() frames its answers with the caller's writer: a device link numbers its responses in
// its stream's sequence (spec L190), and only a change of the active configuration counts.
TEST(FeDeviceControl, RespondUsesTheStreamsWriterAndCountsConfigChanges) {
  DeviceControl dc(config::Config{});
  FusionEngineWriter host, stream;
  stream.set_next_sequence(41);
  SetConfigMessage set;
  set.config_type = to_u16(ConfigType::kGnssLeverArm);
  set.value = pack_config(Point3f{{0.5f, 0.0f, 1.0f}});
  std::vector<std::uint8_t> out;
  const auto request = test::frames_of(host.frame(set));
  ASSERT_EQ(request.size(), 1u);
  dc.respond(request[0].view(), stream, out);
  dc.respond(request[0].view(), stream, out);  // the same value again: no change
  const auto frames = test::frames_of(out);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].header.sequence, 41u);
  EXPECT_EQ(frames[1].header.sequence, 42u);
  EXPECT_EQ(stream.next_sequence(), 43u);
  EXPECT_EQ(dc.config_changes(), 1u);
  GetConfigMessage get;
  get.config_type = to_u16(ConfigType::kGnssLeverArm);
  dc.respond(test::frames_of(host.frame(get))[0].view(), stream, out);
  EXPECT_EQ(dc.config_changes(), 1u) << "a GetConfig changes nothing";
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine
