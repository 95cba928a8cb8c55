// The VN-300 installation geometry of `run --configure-device` (commands_geometry.hpp): the
// register writes against sentences whose XOR checksums were computed by hand (an 8-bit XOR of
// the text between '$' and '*', ICD §1.2), the vehicle-to-body conversion against a hand-rotated
// vector, and the read-back checks against the ICD's own example replies (L3849, L4258).
#include <gtest/gtest.h>

#include <algorithm>

#include "frontends/vectornav/ascii_registers.hpp"
#include "frontends/vectornav/commands_geometry.hpp"

namespace navfuse::frontends::vectornav::cmd {
namespace {

std::vector<std::string> sentences_of(const std::vector<SetupStep>& steps) {
  std::vector<std::string> out;
  for (const auto& s : steps) out.emplace_back(s.command.begin(), s.command.end());
  return out;
}

std::span<const std::uint8_t> bytes_of(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

TEST(VnGeometry, WritesTheConfigLeverArmAndBaselineThenReadsThemBack) {
  // The ICD's antenna A example (L3865: X 0.75 m, Y -0.5 m, Z 0) and a second antenna 1 m ahead
  // of it: the factory baseline (1, 0, 0) (L4258).
  config::Config c;
  c.gnss.lever_arm_m = {0.75, -0.5, 0.0};
  c.gnss.secondary_lever_arm_m = {1.75, -0.5, 0.0};
  const auto steps = fusion_setup_steps(c);
  const auto text = sentences_of(steps);
  auto at = [&](const std::string& s) { return std::find(text.begin(), text.end(), s) - text.begin(); };
  const auto write57 = at("$VNWRG,57,0.75,-0.5,0*72\r\n");
  const auto write93 = at("$VNWRG,93,1,0,0,0.0254,0.0254,0.0254*50\r\n");
  const auto read57 = at("$VNRRG,57*71\r\n");
  const auto read93 = at("$VNRRG,93*79\r\n");
  const auto resume = at("$VNASY,1*4E\r\n");
  ASSERT_LT(resume, static_cast<std::ptrdiff_t>(text.size())) << ::testing::PrintToString(text);
  EXPECT_LT(write57, read57);
  EXPECT_LT(write93, read93);
  EXPECT_LT(read93, resume);
  EXPECT_EQ(resume + 1, static_cast<std::ptrdiff_t>(text.size()));  // output resumes last
  // Only the reads carry a check.
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const bool is_read = static_cast<std::ptrdiff_t>(i) == read57 || static_cast<std::ptrdiff_t>(i) == read93;
    EXPECT_EQ(static_cast<bool>(steps[i].verify), is_read) << text[i];
  }
  EXPECT_EQ(steps[static_cast<std::size_t>(write57)].sets,
            "VN-300 GNSS antenna A offset (Reg 57, body frame, m) to (0.7500, -0.5000, 0.0000)");
  // The device answering as the ICD prints it.
  EXPECT_EQ(steps[static_cast<std::size_t>(read93)].verify(
                bytes_of("$VNRRG,93,+01.000,+00.000,+00.000,00.0254,00.0254,00.0254*60\r\n")),
            "");
  EXPECT_EQ(steps[static_cast<std::size_t>(read57)].verify(bytes_of("$VNRRG,57,+00.750,-00.500,+00.000*69\r\n")), "");
}

TEST(VnGeometry, BaselineUncertaintyIsTheConfigKey) {
  config::Config c;
  c.gnss.lever_arm_m = {0.75, -0.5, 0.0};
  c.gnss.secondary_lever_arm_m = {1.75, -0.5, 0.0};
  c.gnss.baseline_std_m = 0.05;
  const auto steps = fusion_setup_steps(c);
  const auto text = sentences_of(steps);
  // Checksum: XOR of the characters between '$' and '*', computed by hand.
  const auto write93 = std::find(text.begin(), text.end(), "$VNWRG,93,1,0,0,0.05,0.05,0.05*56\r\n");
  ASSERT_NE(write93, text.end()) << ::testing::PrintToString(text);
  // The read-back holds the device to the uncertainty too: the factory 0.0254 is a mismatch.
  const auto read93 = std::find(text.begin(), text.end(), "$VNRRG,93*79\r\n");
  ASSERT_NE(read93, text.end());
  const auto& verify = steps[static_cast<std::size_t>(read93 - text.begin())].verify;
  EXPECT_NE(verify(bytes_of("$VNRRG,93,+01.000,+00.000,+00.000,00.0254,00.0254,00.0254*60\r\n")), "");
}

TEST(VnGeometry, LeverArmsAreSentInTheBodyFrameNavfuseRotatesFrom) {
  // Sensor yawed +90 deg in the vehicle: sensor x = vehicle right, so C_vs = Rz(90) and a
  // vehicle-frame (1, 0.5, -1) is (0.5, -1, -1) on the sensor's axes.
  config::Config c;
  c.imu.mounting_rpy_deg = {0, 0, 90};
  c.gnss.lever_arm_m = {1.0, 0.5, -1.0};
  const auto text = sentences_of(fusion_setup_steps(c));
  EXPECT_NE(std::find(text.begin(), text.end(), "$VNWRG,57,0.5,-1,-1*73\r\n"), text.end())
      << ::testing::PrintToString(text);
  // No second antenna configured: Reg 93 is left alone.
  for (const auto& s : text) EXPECT_EQ(s.find(",93"), std::string::npos) << s;
}

TEST(VnGeometry, ReadBackChecksNameTheSettingAndBothValues) {
  const Eigen::Vector3d sent(0.75, -0.5, 0.0);
  // The ICD's example read of a fresh device (L3849): all zero.
  const std::string fresh = verify_antenna_offset(bytes_of("$VNRRG,57,0,0,0*6D\r\n"), sent);
  EXPECT_NE(fresh.find("Reg 57"), std::string::npos) << fresh;
  EXPECT_NE(fresh.find("sent (0.7500, -0.5000, 0.0000), read (0.0000, 0.0000, 0.0000)"), std::string::npos) << fresh;
  // 10 cm off in y.
  EXPECT_NE(verify_antenna_offset(bytes_of("$VNRRG,57,+00.750,-00.400,+00.000*68\r\n"), sent), "");
  // Nothing, a bad checksum, another register: no reply.
  for (const std::string& reply : {std::string(), std::string("$VNRRG,57,+00.750,-00.500,+00.000*00\r\n"),
                                  std::string("$VNRRG,93,+01.000,+00.000,+00.000,00.0254,00.0254,00.0254*60\r\n")}) {
    const std::string why = verify_antenna_offset(bytes_of(reply), sent);
    EXPECT_NE(why.find("no read-back reply"), std::string::npos) << reply << " -> " << why;
  }
  // The reply among other output (a binary packet and an echo before it) is still found.
  const std::string mixed = std::string("\xFA\x01\x02\x03", 4) + "$VNASY,0*4F\r\n$VNRRG,57,+00.750,-00.500,+00.000*69\r\n";
  EXPECT_EQ(verify_antenna_offset(bytes_of(mixed), sent), "");
  // Baseline and uncertainty are compared together.
  const CompassBaseline baseline{{1, 0, 0}, Eigen::Vector3d::Constant(0.05)};
  const std::string why = verify_compass_baseline(
      bytes_of("$VNRRG,93,+01.000,+00.000,+00.000,00.0254,00.0254,00.0254*60\r\n"), baseline);
  EXPECT_NE(why.find("Reg 93"), std::string::npos) << why;
  EXPECT_NE(why.find("read (1.0000, 0.0000, 0.0000, 0.0254, 0.0254, 0.0254)"), std::string::npos) << why;
}

}  // namespace
}  // namespace navfuse::frontends::vectornav::cmd
