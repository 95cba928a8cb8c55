// The FusionEngine installation geometry of `run --configure-device` (commands.hpp): the
// SetConfig payload against the spec's own example E6 (L1011-1016, digest §12: output lever arm
// [0.6, 0.0, 1.2] m), each frame's CRC checked by the framer, the FRD -> FLU sign change by hand,
// the read-back check against hand-made ConfigResponses, and the whole exchange against the
// device-compatible responder.
#include <gtest/gtest.h>

#include "frontends/fusionengine/commands.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/responder.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

constexpr std::size_t kHeaderSize = 24;

std::vector<std::uint8_t> payload_of(const std::vector<std::uint8_t>& frame) {
  const auto frames = test::frames_of(frame);  // only a frame whose CRC holds is found
  EXPECT_EQ(frames.size(), 1u);
  return {frame.begin() + static_cast<std::ptrdiff_t>(kHeaderSize), frame.end()};
}

TEST(FeGeometry, SetConfigPayloadIsTheSpecExample) {
  FusionEngineWriter writer;
  const auto frame = set_point_config(writer, ConfigType::kOutputLeverArm, Point3f{{0.6f, 0.0f, 1.2f}});
  EXPECT_EQ(payload_of(frame), test::from_hex("1300 0000 0c00 0000 9a99 193f 0000 0000 9a99 993f"));
  // GetConfig ACTIVE (L1309-1332): type u16, source 0, reserved.
  EXPECT_EQ(payload_of(get_config(writer, ConfigType::kGnssLeverArm)), test::from_hex("1200 00 00"));
  // E11 (L1490-1497): Pose at max rate (On Change) on UART1 (Serial, index 1).
  const InterfaceId uart1{static_cast<std::uint8_t>(TransportType::kSerial), 1};
  EXPECT_EQ(payload_of(set_message_rate(writer, MessageType::kPose, MessageRate::kOnChange, uart1)),
            test::from_hex("0101 0000 0100 1027 0100 0000"));
  // GetMessageRate (L1528-1552): interface, protocol 1, source ACTIVE, message id.
  EXPECT_EQ(payload_of(get_message_rate(writer, MessageType::kPose, uart1)), test::from_hex("0101 0000 01 00 1027"));
}

TEST(FeGeometry, StepsSetAndReadBackEachLeverArmInFlu) {
  config::Config c;
  c.imu.mounting_rpy_deg = {0, 0, 90};  // the device's body is the vehicle: no mounting enters
  c.gnss.lever_arm_m = {0.5, 0.25, -1.0};
  c.gnss.secondary_lever_arm_m = {-0.5, 0.25, -1.0};
  const auto steps = fusion_setup_steps(c);
  ASSERT_EQ(steps.size(), 12u);  // device, GNSS, GNSS aux lever arm, 3 message rates: set, get
  // Device lever arm 0 (type 0x10), then GNSS (0x12) (0.5, -0.25, 1.0) and aux (0x18) (-0.5, -0.25, 1.0) FLU.
  EXPECT_EQ(payload_of(steps[0].command), test::from_hex("1000 0000 0c00 0000 00000000 00000000 00000000"));
  EXPECT_EQ(payload_of(steps[2].command), test::from_hex("1200 0000 0c00 0000 0000003f 000080be 0000803f"));
  EXPECT_EQ(payload_of(steps[4].command), test::from_hex("1800 0000 0c00 0000 000000bf 000080be 0000803f"));
  for (std::size_t i = 0; i < steps.size(); ++i) EXPECT_EQ(static_cast<bool>(steps[i].verify), i % 2 == 1) << i;
  EXPECT_EQ(steps[2].sets, "FusionEngine GnssLeverArm (ConfigType 0x12, body FLU, m) to (0.5000, -0.2500, 1.0000)");
  // Without a second antenna, no aux lever arm.
  c.gnss.secondary_lever_arm_m = {0, 0, 0};
  EXPECT_EQ(fusion_setup_steps(c).size(), 10u);
  // IMUOutput (11000 = 0x2AF8) at On Change on the Current interface (0xFE).
  EXPECT_EQ(payload_of(steps[6].command), test::from_hex("FE00 0000 0100 F82A 0100 0000"));

  // Against the device-compatible handler (started from another config): nothing refused, every
  // setting reads back.
  // The rates are answered by the stream's own link (apps/run/fe_device_emulator.hpp), not this
  // handler: only the configuration steps here.
  DeviceControl device(config::Config{});
  std::vector<std::uint8_t> reply;
  for (const SetupStep& step : std::span(steps).first(6)) {
    reply.clear();
    device.feed(step.command, reply);
    EXPECT_EQ(find_refusal(reply), "");
    if (step.verify) {
      EXPECT_EQ(step.verify(reply), "");
    }
  }
  EXPECT_EQ(device.config().gnss.lever_arm_m, (config::Vec3{0.5, 0.25, -1.0}));
}

TEST(FeGeometry, ReadBackChecksAndRefusals) {
  FusionEngineWriter device;
  const Point3f sent{{0.5f, -0.25f, 1.0f}};
  auto response = [&](std::uint8_t code, const Point3f& value) {
    ConfigResponseMessage r;
    r.config_type = to_u16(ConfigType::kGnssLeverArm);
    r.response = code;
    if (code == 0) r.value = pack_config(value);
    return device.frame(r);
  };
  EXPECT_EQ(verify_point_config(response(0, sent), ConfigType::kGnssLeverArm, sent), "");
  const std::string off = verify_point_config(response(0, Point3f{{0.5f, -0.25f, 0.9f}}), ConfigType::kGnssLeverArm, sent);
  EXPECT_NE(off.find("GnssLeverArm (ConfigType 0x12"), std::string::npos) << off;
  EXPECT_NE(off.find("sent (0.5000, -0.2500, 1.0000), read (0.5000, -0.2500, 0.9000)"), std::string::npos) << off;
  // The answer for another setting is no answer.
  EXPECT_NE(verify_point_config(response(0, sent), ConfigType::kGnssAuxLeverArm, sent).find("no read-back reply"),
            std::string::npos);
  const std::string refused = verify_point_config(response(2, sent), ConfigType::kGnssLeverArm, sent);
  EXPECT_NE(refused.find("read-back refused (FusionEngine ConfigResponse response 2 (unsupported feature))"),
            std::string::npos)
      << refused;
  // Message rates.
  auto rates = [&](std::uint8_t code, std::uint8_t configured) {
    MessageRateResponseMessage r;
    r.response = code;
    if (code == 0) r.rates.push_back({1, 0, to_u16(MessageType::kImuOutput), configured, configured});
    return device.frame(r);
  };
  EXPECT_EQ(verify_message_rate(rates(0, 1), MessageType::kImuOutput, MessageRate::kOnChange), "");
  const std::string slow = verify_message_rate(rates(0, 0xFF), MessageType::kImuOutput, MessageRate::kOnChange);
  EXPECT_NE(slow.find("IMUOutput (11000) output rate"), std::string::npos) << slow;
  EXPECT_NE(slow.find("sent rate 1, read rate 255"), std::string::npos) << slow;
  EXPECT_NE(verify_message_rate(rates(0, 1), MessageType::kPose, MessageRate::kOnChange).find("no read-back reply"),
            std::string::npos);
  EXPECT_NE(verify_message_rate(rates(2, 1), MessageType::kImuOutput, MessageRate::kOnChange).find("read-back refused"),
            std::string::npos);
  // A SetConfig the device refuses: CommandResponse VALUE_ERROR (L1579-1590).
  EXPECT_EQ(find_refusal(device.frame(CommandResponseMessage{7, 3})), "FusionEngine CommandResponse response 3 (value error)");
  EXPECT_EQ(find_refusal(device.frame(CommandResponseMessage{7, 0})), "");
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine
