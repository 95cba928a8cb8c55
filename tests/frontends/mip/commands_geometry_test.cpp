// The CV7 installation geometry of `run --configure-device` (commands_geometry.hpp): packets
// against bytes built by hand from the command tables (digest §6.9: 0x0D,0x54 and 0x0D,0x61;
// function selectors §2.6) with the Fletcher checksum of digest §2.3 computed separately, the
// doc's antenna-offset example (L248-263: X -0.32, Y 0.11, Z -0.64 m) as the values, read-back
// checks against hand-built replies, and the whole exchange against the CV7 responder.
#include <gtest/gtest.h>

#include "frontends/mip/commands_geometry.hpp"
#include "frontends/mip/responder.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

config::Config doc_example_config() {
  config::Config c;
  c.gnss.lever_arm_m = {-0.32, 0.11, -0.64};
  return c;
}

const Eigen::Vector3d kDocOffset(-0.32, 0.11, -0.64);
constexpr const char* kSetting = "CV7 GNSS antenna 1 offset";

TEST(MipGeometry, GeometryGoesInWhileIdleWithARead) {
  const auto steps = cv7_setup_steps(doc_example_config());
  const auto base = cv7_setup_sequence();
  // The fusion sequence without its Resume, then write / read of antenna 1 and of the speed
  // lever arm (zero: the config has none), then Resume.
  ASSERT_EQ(steps.size(), base.size() - 1 + 4 + 1);
  for (std::size_t i = 0; i + 1 < base.size(); ++i) EXPECT_EQ(steps[i].command, base[i]) << i;
  const std::size_t g = base.size() - 1;
  // (0x0D,0x54) write: LEN 0x10, fn 1, receiver 1, Vector3f big-endian.
  EXPECT_EQ(steps[g].command, test::hex("75650D10 1054 01 01 BEA3D70A 3DE147AE BF23D70A 7589"));
  EXPECT_EQ(steps[g + 1].command, test::hex("75650D04 0454 02 01 46DE"));  // read: fn 2 + key
  EXPECT_EQ(steps[g + 2].command, test::hex("75650D10 1061 01 01 00000000 00000000 00000000 6A67"));
  EXPECT_EQ(steps[g + 3].command, test::hex("75650D04 0461 02 01 5305"));
  EXPECT_EQ(steps.back().command, base.back());  // Resume
  // A write names what it sets, for the report of a refusal.
  EXPECT_EQ(steps[g].sets, "CV7 GNSS antenna 1 offset (0x0D,0x54, device vehicle frame, m) to (-0.3200, 0.1100, -0.6400)");
  for (std::size_t i = 0; i < steps.size(); ++i) EXPECT_EQ(static_cast<bool>(steps[i].verify), i == g + 1 || i == g + 3) << i;
}

TEST(MipGeometry, SecondAntennaAndMountingAreInTheDeviceFrame) {
  // Sensor yawed +90 deg: a vehicle-frame (1, 0.5, -1) is (0.5, -1, -1) on the sensor axes.
  config::Config c;
  c.imu.mounting_rpy_deg = {0, 0, 90};
  c.gnss.lever_arm_m = {1.0, 0.5, -1.0};
  c.gnss.secondary_lever_arm_m = {1.0, -0.5, -1.0};  // -> (-0.5, -1, -1)
  const auto steps = cv7_setup_steps(c);
  const auto g = cv7_setup_sequence().size() - 1;
  EXPECT_EQ(steps[g].command, build_command_packet(antenna_offset(1, {0.5, -1, -1})));
  EXPECT_EQ(steps[g + 2].command, build_command_packet(antenna_offset(2, {-0.5, -1, -1})));
  EXPECT_EQ(steps[g + 3].command, test::hex("75650D04 0454 02 02 47DF"));
}

TEST(MipGeometry, ReadBackChecks) {
  auto check = [](const std::string& hex) {
    return verify_vector_setting(test::hex(hex), 0x0D, 0x54, 1, kDocOffset, kSetting);
  };
  // ACK, then the 0xD4 response: receiver 1 and the offset as written.
  EXPECT_EQ(check("75650D13 04F15400 0FD401 BEA3D70A 3DE147AE BF23D70A 3FFB"), "");
  // z read back as -0.60 m.
  const std::string off = check("75650D13 04F15400 0FD401 BEA3D70A 3DE147AE BF19999A 87F1");
  EXPECT_NE(off.find(kSetting), std::string::npos) << off;
  EXPECT_NE(off.find("sent (-0.3200, 0.1100, -0.6400), read (-0.3200, 0.1100, -0.6000)"), std::string::npos) << off;
  // NACK "invalid parameter" to the read.
  EXPECT_NE(check("75650D04 04F15403 375B").find("read-back refused (MIP NACK 3)"), std::string::npos);
  EXPECT_NE(check("").find("no read-back reply"), std::string::npos);
}

TEST(MipGeometry, TheResponderHoldsWhatWasWrittenAndRefusesMoreThanTenMetres) {
  CommandResponder device;
  std::vector<std::uint8_t> reply;
  std::vector<Measurement> aiding;
  for (const SetupStep& step : cv7_setup_steps(doc_example_config())) {
    device.handle_packet(step.command, reply, aiding);
    EXPECT_EQ(find_refusal(reply), "");
    if (step.verify) {
      EXPECT_EQ(step.verify(reply), "");
    }
  }
  // 0x0D,0x54 is limited to 10 m (digest §6.9, L8617): invalid parameter, and nothing stored.
  config::Config far = doc_example_config();
  far.gnss.lever_arm_m = {12.0, 0.0, 0.0};
  for (const SetupStep& step : cv7_setup_steps(far)) {
    device.handle_packet(step.command, reply, aiding);
    if (step.command == build_command_packet(antenna_offset(1, {12.0, 0.0, 0.0}))) {
      EXPECT_EQ(find_refusal(reply), "MIP NACK 3 for command (0x0D,0x54)");
    }
  }
  device.handle_packet(*build_command_packet(read_of(antenna_offset(1, {}), 1)), reply, aiding);
  EXPECT_EQ(verify_vector_setting(reply, 0x0D, 0x54, 1, kDocOffset, kSetting), "");
}

}  // namespace
}  // namespace navfuse::frontends::mip
