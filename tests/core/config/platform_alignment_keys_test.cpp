// The platform and alignment keys: parsed, refused with a message naming the key, unset by `~`,
// and printed back by to_yaml() so that the output reads back to the same values.
#include <gtest/gtest.h>

#include <string>

#include "core/config/config.hpp"
#include "tests/core/config/config_error_of.hpp"

namespace navfuse::config {
namespace {

using test::error_of;

TEST(PlatformKey, DefaultsToGenericAndParsesEveryName) {
  EXPECT_EQ(load_from_string("device: cv7\n").platform, Platform::kGeneric);
  EXPECT_EQ(defaults_for(DeviceProfile::kGeneric).platform, Platform::kGeneric);
  EXPECT_EQ(load_from_string("platform: generic\n").platform, Platform::kGeneric);
  EXPECT_EQ(load_from_string("platform: land\n").platform, Platform::kLand);
  EXPECT_EQ(load_from_string("platform: pedestrian\n").platform, Platform::kPedestrian);
  EXPECT_EQ(load_from_string("platform: Airborne\n").platform, Platform::kAirborne);
  EXPECT_EQ(load_from_string("platform: marine\n").platform, Platform::kMarine);
}

TEST(PlatformKey, UnknownOrWrongTypeNamesTheKey) {
  EXPECT_EQ(error_of("platform: walking\n"),
            "config.yaml: platform: expected one of generic, land, pedestrian, airborne, marine, got "
            "\"walking\" (line 1)");
  EXPECT_NE(error_of("platform: [land]\n").find("platform: expected one of"), std::string::npos);
  EXPECT_NE(error_of("platform:\n").find("platform: expected one of"), std::string::npos);
}

TEST(AlignmentKeys, UnsetByDefaultAndParsed) {
  const Config unset = load_from_string("device: vn300\n");
  EXPECT_FALSE(unset.alignment.min_speed_mps);
  EXPECT_FALSE(unset.alignment.initial_heading_deg);
  const Config c = load_from_string(
      "alignment:\n  min_speed_mps: 0.7\n  initial_heading_deg: -123.5\n");
  ASSERT_TRUE(c.alignment.min_speed_mps);
  EXPECT_EQ(*c.alignment.min_speed_mps, 0.7);
  ASSERT_TRUE(c.alignment.initial_heading_deg);
  EXPECT_EQ(*c.alignment.initial_heading_deg, -123.5);
  const Config cleared = load_from_string("alignment: {min_speed_mps: ~, initial_heading_deg: ~}");
  EXPECT_FALSE(cleared.alignment.min_speed_mps);
  EXPECT_FALSE(cleared.alignment.initial_heading_deg);
}

TEST(AlignmentKeys, RefusesNonFiniteAndOutOfRangeNamingTheKey) {
  EXPECT_EQ(error_of("alignment:\n  min_speed_mps: 0\n"),
            "config.yaml: alignment.min_speed_mps: must be in (0, 100], got 0 (line 2)");
  const struct {
    const char* yaml;
    const char* message;
  } refused[] = {
      {"alignment: {min_speed_mps: -1}", "alignment.min_speed_mps: must be in (0, 100], got -1"},
      {"alignment: {min_speed_mps: 250}", "alignment.min_speed_mps: must be in (0, 100], got 250"},
      {"alignment: {min_speed_mps: .nan}", "alignment.min_speed_mps: expected a finite number"},
      {"alignment: {initial_heading_deg: .inf}", "alignment.initial_heading_deg: expected a finite number"},
      {"alignment: {initial_heading_deg: 361}",
       "alignment.initial_heading_deg: must be in [-360, 360], got 361"},
      {"alignment: {initial_heading_deg: north}",
       "alignment.initial_heading_deg: expected a number, got \"north\""},
  };
  for (const auto& r : refused) {
    EXPECT_NE(error_of(r.yaml).find(r.message), std::string::npos) << r.yaml << ": " << error_of(r.yaml);
  }
  // The bounds themselves are allowed.
  EXPECT_EQ(error_of("alignment: {min_speed_mps: 100, initial_heading_deg: -360}"), "");
}

TEST(NhcLeverArmKey, UnsetOrThreeNumbersInRange) {
  EXPECT_FALSE(load_from_string("device: vn300\n").nhc.lever_arm_m);
  const Config c = load_from_string("nhc:\n  lever_arm_m: [-1.5, 0, 0.75]\n");
  ASSERT_TRUE(c.nhc.lever_arm_m);
  EXPECT_EQ(*c.nhc.lever_arm_m, (Vec3{-1.5, 0.0, 0.75}));
  EXPECT_FALSE(load_from_string("nhc: {lever_arm_m: ~}").nhc.lever_arm_m);
  const struct {
    const char* yaml;
    const char* message;
  } refused[] = {
      {"nhc: {lever_arm_m: [1, 2]}", "nhc.lever_arm_m: expected a list of 3 numbers"},
      {"nhc: {lever_arm_m: 1.5}", "nhc.lever_arm_m: expected a list of 3 numbers"},
      {"nhc: {lever_arm_m: [0, 150, 0]}", "nhc.lever_arm_m[1]: must be in [-100, 100], got 150"},
      {"nhc: {lever_arm_m: [0, 0, .nan]}", "nhc.lever_arm_m[2]: expected a finite number"},
  };
  for (const auto& r : refused) {
    EXPECT_NE(error_of(r.yaml).find(r.message), std::string::npos) << r.yaml << ": " << error_of(r.yaml);
  }
}

TEST(PlatformAndAlignment, ToYamlRoundTrips) {
  Config c = defaults_for(DeviceProfile::kCv7);
  c.platform = Platform::kPedestrian;
  c.alignment.initial_heading_deg = 271.25;
  const std::string yaml = to_yaml(c);
  EXPECT_NE(yaml.find("platform: pedestrian  #"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("alignment:\n  min_speed_mps: ~  #"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("  initial_heading_deg: 271.25  #"), std::string::npos) << yaml;
  const Config back = load_from_string(yaml, "to_yaml");
  EXPECT_EQ(back.platform, Platform::kPedestrian);
  EXPECT_FALSE(back.alignment.min_speed_mps);
  EXPECT_EQ(back.alignment.initial_heading_deg, c.alignment.initial_heading_deg);
  EXPECT_EQ(to_yaml(back), yaml);
}

}  // namespace
}  // namespace navfuse::config
