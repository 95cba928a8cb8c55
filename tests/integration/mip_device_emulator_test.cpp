// The --mip-out link's answers to the CV7's filter-configuration commands: each either changes
// the estimate (an engine action) and is ACKed, or is NACKed with the code the MIP reply table
// gives (digest L8873-8881: 0x03 invalid parameter, 0x04 command failed). Packets are written
// byte by byte from the command layouts (digest §6.1, §6.15, §7.3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "apps/run/mip_device_emulator.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::apps {
namespace {

namespace mip = frontends::mip;

constexpr std::uint8_t kWrite = 0x01, kRead = 0x02;

void put_f32(std::vector<std::uint8_t>& out, float v) {
  std::uint32_t u = 0;
  std::memcpy(&u, &v, 4);
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(u >> shift));
}

struct Answer {
  std::vector<mip::ReplyEntry> replies;
  CommandEffects effects;
};

Answer send(MipDeviceEmulator& emulator, std::uint8_t set, std::uint8_t desc, const std::vector<std::uint8_t>& data) {
  Answer a;
  std::vector<std::uint8_t> reply;
  emulator.receive(1, mip::make_packet(set, desc, data), reply, a.effects);
  mip::Framer framer;
  framer.feed(reply, [&](const mip::PacketView& p) { mip::parse_reply(p.payload, a.replies); });
  return a;
}

TEST(MipDeviceEmulator, QuaternionAndDcmMountingTakeEffect) {
  MipDeviceEmulator emulator;
  // (0x0C,0x32) write q = (cos 45, sin 45, 0, 0): the doc's example 2, roll -90 deg
  // (p_veh = q^-1 p_sensor q; frontends/mip/sensor_to_vehicle.hpp).
  std::vector<std::uint8_t> q{kWrite};
  const float h = static_cast<float>(std::sqrt(0.5));
  for (float v : {h, h, 0.0f, 0.0f}) put_f32(q, v);
  Answer a = send(emulator, 0x0C, 0x32, q);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  ASSERT_EQ(a.effects.actions.size(), 1u);
  EXPECT_EQ(a.effects.actions[0].kind, EngineAction::Kind::kMounting);
  EXPECT_TRUE(a.effects.actions[0].vector.isApprox(Eigen::Vector3d(-M_PI / 2, 0, 0), 1e-6)) << a.effects.actions[0].vector;

  // (0x0C,0x33) the doc's example 3 matrix: yaw 90 then pitch 90. At pitch 90 deg only the
  // rotation is defined, so compare the matrix the action's angles make.
  std::vector<std::uint8_t> m{kWrite};
  for (float v : {0.0f, -1.0f, 0.0f, 0.0f, 0.0f, 1.0f, -1.0f, 0.0f, 0.0f}) put_f32(m, v);
  a = send(emulator, 0x0C, 0x33, m);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  ASSERT_EQ(a.effects.actions.size(), 1u);
  EXPECT_NEAR(a.effects.actions[0].vector.y(), M_PI / 2, 1e-3);  // pitch

  // A matrix that is no rotation: invalid parameter, nothing applied.
  std::vector<std::uint8_t> bad{kWrite};
  for (float v : {2.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}) put_f32(bad, v);
  a = send(emulator, 0x0C, 0x33, bad);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kInvalidParameter);
  EXPECT_TRUE(a.effects.actions.empty());
}

TEST(MipDeviceEmulator, SpeedLeverArmAndAntennaOffsetTakeEffect) {
  MipDeviceEmulator emulator;
  std::vector<std::uint8_t> arm{kWrite, 0x01};  // source 1 (must be 1)
  for (float v : {-0.5f, 0.75f, 0.25f}) put_f32(arm, v);
  Answer a = send(emulator, 0x0D, 0x61, arm);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  ASSERT_EQ(a.effects.actions.size(), 1u);
  EXPECT_EQ(a.effects.actions[0].kind, EngineAction::Kind::kWheelLeverArm);
  EXPECT_TRUE(a.effects.actions[0].vector.isApprox(Eigen::Vector3d(-0.5, 0.75, 0.25)));
  arm[1] = 2;
  a = send(emulator, 0x0D, 0x61, arm);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kInvalidParameter);
  EXPECT_TRUE(a.effects.actions.empty());

  std::vector<std::uint8_t> antenna{kWrite};  // (0x0D,0x13): function, offset [m] vehicle frame
  for (float v : {1.0f, 0.0f, -1.5f}) put_f32(antenna, v);
  a = send(emulator, 0x0D, 0x13, antenna);
  ASSERT_EQ(a.effects.actions.size(), 1u);
  EXPECT_EQ(a.effects.actions[0].kind, EngineAction::Kind::kGnssLeverArm);
  EXPECT_EQ(a.effects.actions[0].antenna, 0);
  EXPECT_TRUE(a.effects.actions[0].vector.isApprox(Eigen::Vector3d(1.0, 0.0, -1.5)));
}

// The commands issue 17 found ACKed with no effect: each write now says "command failed".
TEST(MipDeviceEmulator, CommandsTheEngineCannotTakeAreNackedCommandFailed) {
  MipDeviceEmulator emulator;
  struct Case {
    std::uint8_t set, desc;
    std::vector<std::uint8_t> data;
  };
  std::vector<std::uint8_t> heading;  // (0x0D,0x03): heading [rad]
  put_f32(heading, 0.5f);
  std::vector<std::uint8_t> ext_heading;  // (0x0D,0x17): heading, uncertainty [rad], type
  put_f32(ext_heading, 0.5f);
  put_f32(ext_heading, 0.1f);
  ext_heading.push_back(1);
  std::vector<std::uint8_t> odometer{kWrite, 2};  // (0x0C,0x43): mode, scaling, uncertainty
  put_f32(odometer, 1000.0f);
  put_f32(odometer, 0.01f);
  const std::vector<Case> cases = {
      {0x0D, 0x03, heading},
      {0x0D, 0x17, ext_heading},
      {0x0D, 0x50, {kWrite, 0x00, 0x03, 0x00}},  // aiding control: source 3 (speed), enable 0
      {0x0D, 0x63, {kWrite, 0x01}},              // wheeled-vehicle constraint on
      {0x0C, 0x43, odometer},
  };
  for (const auto& c : cases) {
    const Answer a = send(emulator, c.set, c.desc, c.data);
    ASSERT_EQ(a.replies.size(), 1u) << int(c.set) << "," << int(c.desc);
    EXPECT_EQ(a.replies[0].cmd_desc, c.desc);
    EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kCommandFailed) << int(c.set) << "," << int(c.desc);
    EXPECT_TRUE(a.effects.actions.empty());
  }
  // Reading such a setting changes nothing and is still answered.
  const Answer read = send(emulator, 0x0D, 0x63, {kRead});
  ASSERT_EQ(read.replies.size(), 1u);
  EXPECT_EQ(read.replies[0].code, mip::ReplyCode::kAck);
}

}  // namespace
}  // namespace navfuse::apps
