// The link's message rates (apps/output/fe_stream_rates.hpp) as a client sets, saves, reverts
// and reads them: spec §3.1.8 SaveConfig, §3.1.11-12 Set/GetMessageRate, §3.2.4
// MessageRateResponse; and ResetRequest RESET_CONFIG, which restores the configuration too.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "apps/run/fe_device_emulator.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/payload_reader.hpp"
#include "fe_link_reply.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

// The link's one rate table (apps/output/fe_stream_rates.hpp): spec example E11 (L1490-1497)
// sets Pose on change and GetMessageRate reports it; a wildcard interval rate leaves messages
// that are off alone unless INCLUDE_DISABLED_MESSAGES is set (L1470-1476).
TEST(FeDeviceEmulator, MessageRatesFromTheSpecExampleAndTheWildcardRule) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  const auto rate_of = [&](fe::MessageType type) {
    fe::GetMessageRateMessage get;
    get.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
    get.message_id = fe::to_u16(type);
    std::vector<std::uint8_t> reply;
    CommandEffects effects;
    emulator->receive(1, host.frame(get), reply, effects);
    const Reply r = parse_reply(reply);
    fe::MessageRateResponseMessage m;
    EXPECT_EQ(r.types.size(), 1u);
    EXPECT_TRUE(!r.payloads.empty() && fe::decode_payload(r.payloads[0], m));
    return m.rates.size() == 1 ? m.rates[0].configured_rate : std::uint8_t{0xEE};
  };
  const auto set = [&](std::uint16_t id, fe::MessageRate rate, std::uint8_t flags) {
    fe::SetMessageRateMessage m;
    m.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
    m.message_id = id;
    m.rate = static_cast<std::uint8_t>(rate);
    m.flags = flags;
    std::vector<std::uint8_t> reply;
    CommandEffects effects;
    emulator->receive(1, host.frame(m), reply, effects);
  };
  const std::vector<std::uint8_t> e11 = {0x2e, 0x31, 0x00, 0x00, 0x6a, 0x84, 0x77, 0x24, 0x02, 0x00, 0xa4, 0x33,
                                         0x00, 0x00, 0x00, 0x00, 0x0c, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                                         0x01, 0x01, 0x00, 0x00, 0x01, 0x00, 0x10, 0x27, 0x01, 0x00, 0x00, 0x00};
  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  emulator->receive(1, e11, reply, effects);
  const Reply r = parse_reply(reply);
  ASSERT_EQ(r.types.size(), 1u);
  ASSERT_EQ(r.types[0], fe::to_u16(fe::MessageType::kCommandResponse));
  EXPECT_EQ(r.payloads[0][4], static_cast<std::uint8_t>(fe::Response::kOk));
  EXPECT_EQ(rate_of(fe::MessageType::kPose), static_cast<std::uint8_t>(fe::MessageRate::kOnChange));

  set(fe::to_u16(fe::MessageType::kPoseAux), fe::MessageRate::kOff, 0);
  set(fe::kAllMessages, fe::MessageRate::k1S, 0);
  EXPECT_EQ(rate_of(fe::MessageType::kPose), static_cast<std::uint8_t>(fe::MessageRate::k1S));
  EXPECT_EQ(rate_of(fe::MessageType::kPoseAux), static_cast<std::uint8_t>(fe::MessageRate::kOff));
  set(fe::kAllMessages, fe::MessageRate::k1S, fe::kRateFlagIncludeDisabled);
  EXPECT_EQ(rate_of(fe::MessageType::kPoseAux), static_cast<std::uint8_t>(fe::MessageRate::k1S));
}

// The rates are part of the configuration SaveConfig saves and reverts (spec L1336-1377): a rate
// set without APPLY_AND_SAVE differs from the saved one until SaveConfig saves it; revert to
// saved undoes a later change; APPLY_AND_SAVE writes both copies; revert to default and
// ResetRequest RESET_CONFIG restore the defaults in both. GetMessageRate reports either copy
// and the ACTIVE_DIFFERS_FROM_SAVED flag (L1655-1690).
TEST(FeDeviceEmulator, SaveConfigSavesAndRevertsTheMessageRates) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  const auto send = [&](const std::vector<std::uint8_t>& frame) {
    std::vector<std::uint8_t> reply;
    CommandEffects effects;
    emulator->receive(1, frame, reply, effects);
    return parse_reply(reply);
  };
  struct Rate {
    std::uint8_t configured, effective, flags;
  };
  const auto pose_rate = [&](fe::ConfigSource source) {
    fe::GetMessageRateMessage get;
    get.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
    get.source = static_cast<std::uint8_t>(source);
    get.message_id = fe::to_u16(fe::MessageType::kPose);
    const Reply r = send(host.frame(get));
    fe::MessageRateResponseMessage m;
    EXPECT_TRUE(r.payloads.size() == 1 && fe::decode_payload(r.payloads[0], m));
    EXPECT_EQ(m.rates.size(), 1u);
    return m.rates.empty() ? Rate{0xEE, 0xEE, 0xEE}
                           : Rate{m.rates[0].configured_rate, m.rates[0].effective_rate, m.rates[0].flags};
  };
  const auto set_pose = [&](fe::MessageRate rate, std::uint8_t flags) {
    fe::SetMessageRateMessage m;
    m.protocol = static_cast<std::uint8_t>(fe::ProtocolType::kFusionEngine);
    m.message_id = fe::to_u16(fe::MessageType::kPose);
    m.rate = static_cast<std::uint8_t>(rate);
    m.flags = flags;
    EXPECT_EQ(send(host.frame(m)).payloads.at(0)[4], static_cast<std::uint8_t>(fe::Response::kOk));
  };
  const auto save_action = [&](fe::SaveAction action) {
    fe::SaveConfigMessage m;
    m.action = static_cast<std::uint8_t>(action);
    EXPECT_EQ(send(host.frame(m)).payloads.at(0)[4], static_cast<std::uint8_t>(fe::Response::kOk));
  };
  const auto u8 = [](fe::MessageRate r) { return static_cast<std::uint8_t>(r); };

  set_pose(fe::MessageRate::k1S, 0);
  Rate active = pose_rate(fe::ConfigSource::kActive), saved = pose_rate(fe::ConfigSource::kSaved);
  EXPECT_EQ(active.configured, u8(fe::MessageRate::k1S));
  EXPECT_EQ(active.flags, fe::kRateEntryActiveDiffersFromSaved);
  EXPECT_EQ(saved.configured, u8(fe::MessageRate::kDefault));
  EXPECT_EQ(saved.effective, u8(fe::MessageRate::k1S)) << "effective is what the stream uses";

  save_action(fe::SaveAction::kSave);
  saved = pose_rate(fe::ConfigSource::kSaved);
  EXPECT_EQ(saved.configured, u8(fe::MessageRate::k1S));
  EXPECT_EQ(saved.flags, 0);

  set_pose(fe::MessageRate::kOff, 0);
  EXPECT_EQ(pose_rate(fe::ConfigSource::kActive).configured, u8(fe::MessageRate::kOff));
  save_action(fe::SaveAction::kRevertToSaved);
  active = pose_rate(fe::ConfigSource::kActive);
  EXPECT_EQ(active.configured, u8(fe::MessageRate::k1S));
  EXPECT_EQ(active.flags, 0);

  set_pose(fe::MessageRate::k100Ms, fe::kRateFlagApplyAndSave);
  EXPECT_EQ(pose_rate(fe::ConfigSource::kSaved).configured, u8(fe::MessageRate::k100Ms));
  EXPECT_EQ(pose_rate(fe::ConfigSource::kActive).flags, 0);

  save_action(fe::SaveAction::kRevertToDefault);
  EXPECT_EQ(pose_rate(fe::ConfigSource::kActive).configured, u8(fe::MessageRate::kDefault));
  EXPECT_EQ(pose_rate(fe::ConfigSource::kSaved).configured, u8(fe::MessageRate::kDefault));

  // The restored default streams: a Pose at every epoch again.
  set_pose(fe::MessageRate::kOff, fe::kRateFlagApplyAndSave);
  std::vector<std::uint8_t> streamed;
  emulator->stream(epoch_at(0), streamed);
  EXPECT_EQ(parse_reply(streamed).count(fe::MessageType::kPose), 0u);
  fe::ResetRequestMessage reset;
  reset.reset_mask = fe::reset::kResetConfig;
  EXPECT_EQ(send(host.frame(reset)).payloads.at(0)[4], static_cast<std::uint8_t>(fe::Response::kOk));
  EXPECT_EQ(pose_rate(fe::ConfigSource::kSaved).configured, u8(fe::MessageRate::kDefault));
  streamed.clear();
  emulator->stream(epoch_at(1), streamed);
  EXPECT_EQ(parse_reply(streamed).count(fe::MessageType::kPose), 1u);

  // A configuration source the spec does not define is refused.
  fe::GetMessageRateMessage bad;
  bad.source = 7;
  bad.message_id = fe::to_u16(fe::MessageType::kPose);
  fe::MessageRateResponseMessage m;
  const Reply r = send(host.frame(bad));
  ASSERT_TRUE(r.payloads.size() == 1 && fe::decode_payload(r.payloads[0], m));
  EXPECT_EQ(m.response, static_cast<std::uint8_t>(fe::Response::kValueError));
}

// ResetRequest RESET_CONFIG restores the factory configuration on the link (L1355): a lever arm
// set by a client goes back to the config's, and the engine is told.
TEST(FeDeviceEmulator, ResetConfigRestoresTheConfigurationAndTellsTheEngine) {
  auto emulator = make_fe_device_emulator(config::Config{});
  fe::FusionEngineWriter host;
  std::vector<std::uint8_t> reply;
  CommandEffects effects;
  fe::SetConfigMessage set;
  set.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  set.flags = fe::kConfigFlagApplyAndSave;
  set.value = fe::pack_config(fe::Point3f{{1.0f, 0.0f, 0.5f}});
  emulator->receive(1, host.frame(set), reply, effects);
  ASSERT_EQ(effects.actions.size(), 1u);
  effects = CommandEffects{};
  fe::ResetRequestMessage reset;
  reset.reset_mask = fe::reset::kResetConfig;
  emulator->receive(1, host.frame(reset), reply, effects);
  ASSERT_EQ(effects.actions.size(), 1u);
  EXPECT_EQ(effects.actions[0].kind, EngineAction::Kind::kGnssLeverArm);
  EXPECT_NEAR(effects.actions[0].vector.norm(), 0.0, 1e-12) << "the default config's lever arm";
  fe::GetConfigMessage get;
  get.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  get.source = static_cast<std::uint8_t>(fe::ConfigSource::kSaved);
  reply.clear();
  emulator->receive(1, host.frame(get), reply, effects);
  const Reply r = parse_reply(reply);
  fe::ConfigResponseMessage resp;
  ASSERT_TRUE(r.payloads.size() == 1 && fe::decode_payload(r.payloads[0], resp));
  ASSERT_EQ(resp.value.size(), 12u);
  float xyz[3];
  std::memcpy(xyz, resp.value.data(), sizeof xyz);
  for (float v : xyz) EXPECT_EQ(v, 0.0f);  // -0 from the FRD -> FLU sign flip compares equal
}

}  // namespace
}  // namespace navfuse::apps
