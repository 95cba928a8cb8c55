// The nav process's FusionEngine link answers configuration commands through the front-end's
// device-compatible handler and turns what they change into engine actions: a GNSS lever arm
// set in FLU reaches the engine in FRD, a device orientation as a mounting in radians, and
// GetConfig reports what was set. Until a client changes a rate, the link streams exactly the
// bytes replay writes to an --fe-out file for the same epochs.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "apps/output/fe_epoch_encoder.hpp"
#include "apps/run/fe_device_emulator.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/payload_reader.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

struct Reply {
  std::vector<std::uint16_t> types;
  std::vector<std::vector<std::uint8_t>> payloads;
};

Reply parse_reply(const std::vector<std::uint8_t>& bytes) {
  Reply r;
  fe::Framer framer;
  framer.feed(bytes, [&](const fe::Frame& f) {
    r.types.push_back(f.header.message_type);
    r.payloads.emplace_back(f.payload.begin(), f.payload.end());
  });
  return r;
}

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
  EXPECT_EQ(parse_reply(streamed).types.size(), 8u + 4u * 2u + 1u) << "IMUOutput x8, Pose+PoseAux x4, GNSSInfo";
  EXPECT_EQ(streamed, file);
}

}  // namespace
}  // namespace navfuse::apps
