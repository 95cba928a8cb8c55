// The --mip-out link's answers to the CV7's filter-configuration commands: each either changes
// the estimate (an engine action) and is ACKed, or is NACKed with the code the MIP reply table
// gives (digest L8873-8881: 0x03 invalid parameter, 0x04 command failed). Packets are written
// byte by byte from the command layouts (digest §6.1, §6.5, §6.7, §6.8, §6.15, §7.3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <vector>

#include "apps/run/mip_device_emulator.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/packet.hpp"
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

// The commands issue 17 found ACKed with no effect that the engine still cannot take: each
// write says "command failed".
TEST(MipDeviceEmulator, CommandsTheEngineCannotTakeAreNackedCommandFailed) {
  MipDeviceEmulator emulator;
  struct Case {
    std::uint8_t set, desc;
    std::vector<std::uint8_t> data;
  };
  std::vector<std::uint8_t> odometer{kWrite, 2};  // (0x0C,0x43): mode, scaling, uncertainty
  put_f32(odometer, 1000.0f);
  put_f32(odometer, 0.01f);
  const std::vector<Case> cases = {
      {0x0C, 0x43, odometer},
      {0x0D, 0x53, {kWrite, 0x02, 0x00, 0x10}},  // adaptive filter: moderate, 16 ms
  };
  for (const auto& c : cases) {
    const Answer a = send(emulator, c.set, c.desc, c.data);
    ASSERT_EQ(a.replies.size(), 1u) << int(c.set) << "," << int(c.desc);
    EXPECT_EQ(a.replies[0].cmd_desc, c.desc);
    EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kCommandFailed) << int(c.set) << "," << int(c.desc);
    EXPECT_TRUE(a.effects.actions.empty());
  }
  // Reading such a setting changes nothing and is still answered.
  const Answer read = send(emulator, 0x0C, 0x43, {kRead});
  ASSERT_EQ(read.replies.size(), 1u);
  EXPECT_EQ(read.replies[0].code, mip::ReplyCode::kAck);
}

// (0x0D,0x03) set initial heading [rad] (digest §6.4): becomes the engine's initial heading;
// beyond +-pi an invalid parameter.
TEST(MipDeviceEmulator, InitialHeadingBecomesTheEnginesInitialHeading) {
  MipDeviceEmulator emulator;
  std::vector<std::uint8_t> heading;
  put_f32(heading, -2.5f);
  Answer a = send(emulator, 0x0D, 0x03, heading);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  ASSERT_EQ(a.effects.actions.size(), 1u);
  EXPECT_EQ(a.effects.actions[0].kind, EngineAction::Kind::kInitialHeading);
  EXPECT_DOUBLE_EQ(a.effects.actions[0].heading_rad, -2.5);
  heading.clear();
  put_f32(heading, 3.5f);
  a = send(emulator, 0x0D, 0x03, heading);
  EXPECT_EQ(a.replies.at(0).code, mip::ReplyCode::kInvalidParameter);
  EXPECT_TRUE(a.effects.actions.empty());
}

// (0x0D,0x63) wheeled-vehicle constraint: enable byte -> the engine's non-holonomic constraint
// (digest §6.7, L8707-8720).
TEST(MipDeviceEmulator, WheeledVehicleConstraintSwitchesTheNonholonomicConstraint) {
  MipDeviceEmulator emulator;
  for (const std::uint8_t enable : {0, 1}) {
    const Answer a = send(emulator, 0x0D, 0x63, {kWrite, enable});
    ASSERT_EQ(a.replies.size(), 1u);
    EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
    ASSERT_EQ(a.effects.actions.size(), 1u);
    EXPECT_EQ(a.effects.actions[0].kind, EngineAction::Kind::kNonholonomic);
    EXPECT_EQ(a.effects.actions[0].enable, enable == 1);
  }
  // Read after write reports it (setting kept by the responder).
  const Answer read = send(emulator, 0x0D, 0x63, {kRead});
  ASSERT_EQ(read.replies.size(), 1u);
  EXPECT_EQ(read.replies[0].code, mip::ReplyCode::kAck);
  EXPECT_TRUE(read.effects.actions.empty());
}

// (0x0D,0x50) aiding measurement control: each CV7 source (digest §6.5, L8500-8512) switches
// the measurement kinds it feeds; ALL (0xFFFF) and unknown sources are not for Write.
TEST(MipDeviceEmulator, AidingControlSwitchesTheSourcesMeasurementKinds) {
  MipDeviceEmulator emulator;
  Answer a = send(emulator, 0x0D, 0x50, {kWrite, 0x00, 0x03, 0x00});  // SPEED off
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  std::vector<MeasurementKind> kinds;
  for (const auto& action : a.effects.actions) {
    EXPECT_EQ(action.kind, EngineAction::Kind::kAiding);
    EXPECT_FALSE(action.enable);
    kinds.push_back(action.aiding);
  }
  EXPECT_EQ(kinds, (std::vector<MeasurementKind>{MeasurementKind::kWheelSpeed, MeasurementKind::kVehicleSpeed,
                                                 MeasurementKind::kWheelTicks}));
  a = send(emulator, 0x0D, 0x50, {kWrite, 0x00, 0x00, 0x01});  // GNSS_POS_VEL on
  ASSERT_EQ(a.effects.actions.size(), 2u);
  EXPECT_EQ(a.effects.actions[0].aiding, MeasurementKind::kGnssPosition);
  EXPECT_EQ(a.effects.actions[1].aiding, MeasurementKind::kGnssVelocity);
  EXPECT_TRUE(a.effects.actions[0].enable);
  for (const std::uint8_t hi : {0x00, 0xFF}) {
    a = send(emulator, 0x0D, 0x50, {kWrite, hi, hi == 0 ? std::uint8_t{9} : std::uint8_t{0xFF}, 0x00});
    ASSERT_EQ(a.replies.size(), 1u);
    EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kInvalidParameter);
    EXPECT_TRUE(a.effects.actions.empty());
  }
}

// Legacy external heading (0x0D,0x17 / 0x0D,0x1F, digest §6.8): the SENSOR frame's true heading
// becomes an ExternalHeading of the vehicle, at the newest epoch's time or at the GPS time
// given; an uncertainty <= 0 is an invalid parameter, a magnetic heading command failed.
TEST(MipDeviceEmulator, LegacyExternalHeadingIsFusedAsTheVehiclesHeading) {
  // Sensor yawed +30 deg in the vehicle: a sensor heading of 100 deg is a vehicle heading of 70.
  MipDeviceEmulator emulator(Eigen::Vector3d(0, 0, 30 * M_PI / 180));
  OutputEpoch epoch;
  epoch.solution.header.time_ns = 1'400'000'000'000'000'000;
  std::vector<std::uint8_t> out;
  emulator.stream(epoch, out);

  const auto heading_field = [](float heading, float uncertainty, std::uint8_t type) {
    std::vector<std::uint8_t> d;
    put_f32(d, heading);
    put_f32(d, uncertainty);
    d.push_back(type);
    return d;
  };
  Answer a = send(emulator, 0x0D, 0x17, heading_field(static_cast<float>(100 * M_PI / 180), 0.02f, 1));
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  ASSERT_EQ(a.effects.aiding.size(), 1u);
  const auto* h = std::get_if<ExternalHeading>(&a.effects.aiding[0]);
  ASSERT_NE(h, nullptr);
  EXPECT_NEAR(h->heading_rad, 70 * M_PI / 180, 1e-6);
  EXPECT_NEAR(h->std_rad, 0.02, 1e-7);
  EXPECT_EQ(h->header.time_ns, epoch.solution.header.time_ns);
  EXPECT_EQ(h->header.time_source, TimeSource::kGps);

  // With time: week 2100, TOW 3600.25 s -> 2100 * 604800 + 3600.25 s after the GPS epoch.
  std::vector<std::uint8_t> timed;
  const double tow = 3600.25;
  std::uint64_t u = 0;
  std::memcpy(&u, &tow, 8);
  for (int shift = 56; shift >= 0; shift -= 8) timed.push_back(static_cast<std::uint8_t>(u >> shift));
  timed.push_back(2100 >> 8);
  timed.push_back(2100 & 0xFF);
  const auto rest = heading_field(static_cast<float>(-170 * M_PI / 180), 0.05f, 1);
  timed.insert(timed.end(), rest.begin(), rest.end());
  a = send(emulator, 0x0D, 0x1F, timed);
  ASSERT_EQ(a.replies.size(), 1u);
  EXPECT_EQ(a.replies[0].code, mip::ReplyCode::kAck);
  ASSERT_EQ(a.effects.aiding.size(), 1u);
  h = std::get_if<ExternalHeading>(&a.effects.aiding[0]);
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->header.time_ns, (2100LL * 604800 + 3600) * 1'000'000'000LL + 250'000'000);
  EXPECT_NEAR(h->heading_rad, 160 * M_PI / 180, 1e-6);  // -170 - 30 wrapped

  a = send(emulator, 0x0D, 0x17, heading_field(0.5f, 0.0f, 1));
  EXPECT_EQ(a.replies.at(0).code, mip::ReplyCode::kInvalidParameter);
  a = send(emulator, 0x0D, 0x17, heading_field(0.5f, 0.1f, 2));
  EXPECT_EQ(a.replies.at(0).code, mip::ReplyCode::kCommandFailed);
  a = send(emulator, 0x0D, 0x17, heading_field(4.0f, 0.1f, 1));
  EXPECT_EQ(a.replies.at(0).code, mip::ReplyCode::kInvalidParameter);
  EXPECT_TRUE(a.effects.aiding.empty());
}

float get_f32(std::span<const std::uint8_t> d, std::size_t at) {
  std::uint32_t u = 0;
  for (std::size_t k = 0; k < 4; ++k) u = (u << 8) | d[at + k];
  float v = 0;
  std::memcpy(&v, &u, 4);
  return v;
}

// The 0x82 fields of `bytes` by descriptor (the last of each).
std::map<std::uint8_t, std::vector<std::uint8_t>> filter_fields(const std::vector<std::uint8_t>& bytes) {
  std::map<std::uint8_t, std::vector<std::uint8_t>> fields;
  mip::Framer framer;
  framer.feed(bytes, [&](const mip::PacketView& p) {
    if (p.desc_set != 0x82) return;
    mip::FieldWalker walk(p.payload);
    mip::FieldView f;
    while (walk.next(f)) fields[f.desc].assign(f.data.begin(), f.data.end());
  });
  return fields;
}

// On a device link the 0x82 stream carries the estimated calibration (digest §4.2 L4497-4667):
// odometer scale factor error in the CV7's convention (total SF = user SF (1 + error), navfuse
// measured = (1 + e) true: error = -e / (1 + e)), and the antenna offset correction added to the
// offset in force, each valid only while estimated. A file holds what replay writes.
TEST(MipDeviceEmulator, CalibrationFieldsOnTheLinkWithValidFlags) {
  const Eigen::Vector3d configured(0.8, -0.4, -1.3);
  MipDeviceEmulator emulator(Eigen::Vector3d::Zero(), configured);
  MipDeviceEmulator file(Eigen::Vector3d::Zero(), configured, false);
  OutputEpoch epoch;
  epoch.pose_due = true;
  epoch.solution.header = {1'400'000'000'000'000'000, TimeSource::kGps, 0, NavSolution::kValidBiases};
  auto& cal = epoch.solution.calibration;
  cal.odometer_scale_error = {true, 0.02, 0.004};
  cal.gnss_lever_arm_m.estimated = true;
  cal.gnss_lever_arm_m.value = Eigen::Vector3d(0.85, -0.4, -1.25);
  cal.gnss_lever_arm_m.std = Eigen::Vector3d(0.03, 0.03, 0.05);
  std::vector<std::uint8_t> out, file_out;
  emulator.stream(epoch, out);
  file.stream(epoch, file_out);

  auto f = filter_fields(out);
  ASSERT_EQ(f[0x47].size(), 6u);
  EXPECT_NEAR(get_f32(f[0x47], 0), -0.02 / 1.02, 1e-7);
  EXPECT_EQ(f[0x47][5], 1);  // valid
  EXPECT_NEAR(get_f32(f[0x48], 0), 0.004 / (1.02 * 1.02), 1e-8);
  ASSERT_EQ(f[0x34].size(), 15u);
  EXPECT_EQ(f[0x34][0], 1);  // receiver 1
  EXPECT_NEAR(get_f32(f[0x34], 1), 0.05, 1e-6);
  EXPECT_NEAR(get_f32(f[0x34], 5), 0.0, 1e-6);
  EXPECT_NEAR(get_f32(f[0x34], 9), 0.05, 1e-6);
  EXPECT_EQ(f[0x34][14], 1);
  EXPECT_NEAR(get_f32(f[0x35], 9), 0.05, 1e-7);
  EXPECT_FALSE(filter_fields(file_out).contains(0x47));

  // A new antenna offset written (0x0D,0x13): the correction is relative to it.
  std::vector<std::uint8_t> antenna{kWrite};
  for (float v : {1.0f, 0.0f, -1.5f}) put_f32(antenna, v);
  send(emulator, 0x0D, 0x13, antenna);
  // Odometer scale not estimated: invalid.
  cal.odometer_scale_error = {false, 0.0, 0.0};
  out.clear();
  emulator.stream(epoch, out);
  f = filter_fields(out);
  EXPECT_NEAR(get_f32(f[0x34], 1), -0.15, 1e-6);
  EXPECT_NEAR(get_f32(f[0x34], 9), 0.25, 1e-6);
  EXPECT_EQ(f[0x47][5], 0);
  EXPECT_EQ(f[0x48][5], 0);
}

}  // namespace
}  // namespace navfuse::apps
