// The keys that switch estimated states, gate and time the filter and tune its constraints: strict
// switches (true / false only), `~` for "the platform decides", physical ranges refused with the
// key named, and the dump reading back to the same values.
#include <gtest/gtest.h>

#include <string>

#include "core/config/config.hpp"
#include "tests/core/config/config_error_of.hpp"

namespace navfuse::config {
namespace {

using test::error_of;

TEST(SwitchKeys, ParseTrueAndFalseOnly) {
  const Config on = load_from_string(
      "imu: {estimate_gyro_scale: true, estimate_accel_scale: true, estimate_mounting: true}\n"
      "gnss: {estimate_lever_arm: true, estimate_time_offset: true}\n");
  EXPECT_TRUE(on.gnss.estimate_time_offset);
  EXPECT_TRUE(on.imu.estimate_gyro_scale);
  EXPECT_TRUE(on.imu.estimate_accel_scale);
  EXPECT_TRUE(on.imu.estimate_mounting);
  EXPECT_TRUE(on.gnss.estimate_lever_arm);
  const Config off = load_from_string("imu: {estimate_mounting: false}\n");
  EXPECT_FALSE(off.imu.estimate_mounting);
  EXPECT_FALSE(defaults_for(DeviceProfile::kCv7).gnss.estimate_lever_arm);

  EXPECT_EQ(error_of("imu:\n  estimate_mounting: yes\n"),
            "config.yaml: imu.estimate_mounting: expected true or false, got \"yes\" (line 2)");
  for (const char* bad : {"1", "on", "True", "\"true\"", "'false'", "[true]", ""}) {
    const std::string yaml = std::string("gnss: {estimate_lever_arm: ") + bad + "}\n";
    EXPECT_NE(error_of(yaml).find("gnss.estimate_lever_arm: expected true or false"), std::string::npos)
        << yaml;
  }
}

TEST(SwitchKeys, OptionalSwitchesAreUnsetUntilGivenAndClearedByTilde) {
  const Config unset = load_from_string("platform: land\n");
  EXPECT_FALSE(unset.nhc.enabled);
  EXPECT_FALSE(unset.zupt.enabled);
  EXPECT_FALSE(unset.alignment.course);
  const Config set = load_from_string(
      "nhc: {enabled: false}\nzupt: {enabled: true}\nalignment: {course: false}\n");
  ASSERT_TRUE(set.nhc.enabled);
  EXPECT_FALSE(*set.nhc.enabled);
  ASSERT_TRUE(set.zupt.enabled);
  EXPECT_TRUE(*set.zupt.enabled);
  ASSERT_TRUE(set.alignment.course);
  EXPECT_FALSE(*set.alignment.course);
  EXPECT_FALSE(load_from_string("nhc: {enabled: ~}\n").nhc.enabled);
  EXPECT_NE(error_of("zupt: {enabled: off}\n").find("zupt.enabled: expected true or false, got \"off\""),
            std::string::npos);
}

TEST(FilterKeys, ParsedIntoTheirMembers) {
  const Config c = load_from_string(
      "imu: {max_gap_s: 0.5, initial_gyro_scale_std_ppm: 300, initial_accel_scale_std_ppm: 2000,"
      " initial_mounting_std_deg: 2.5}\n"
      "gnss: {timeout_s: 5, recovery_s: 7.5, initial_lever_arm_std_m: 0.3}\n"
      "alignment: {initial_heading_std_deg: 10, level_time_s: 2, level_timeout_s: 30}\n"
      "nhc: {lateral_std_mps: 0.2, vertical_std_mps: 0.3, min_speed_mps: 0, interval_s: 0.5}\n"
      "zupt: {std_mps: 0.01, window_s: 0.5, max_rate_rad_s: 0.02, max_accel_std_mps2: 0.2,"
      " max_speed_mps: 0.1}\n"
      "gates: {chi2_1d: 10.83, chi2_2d: 13.82, chi2_3d: 16.27}\n"
      "timing: {max_latency_s: 0}\n");
  EXPECT_EQ(c.imu.max_gap_s, 0.5);
  EXPECT_EQ(c.imu.initial_gyro_scale_std_ppm, 300);
  EXPECT_EQ(c.imu.initial_accel_scale_std_ppm, 2000);
  EXPECT_EQ(c.imu.initial_mounting_std_deg, 2.5);
  EXPECT_EQ(c.gnss.timeout_s, 5);
  EXPECT_EQ(c.gnss.recovery_s, 7.5);
  EXPECT_EQ(c.gnss.initial_lever_arm_std_m, 0.3);
  EXPECT_EQ(c.alignment.initial_heading_std_deg, 10);
  EXPECT_EQ(c.alignment.level_time_s, 2);
  EXPECT_EQ(c.alignment.level_timeout_s, 30);
  EXPECT_EQ(c.nhc.lateral_std_mps, 0.2);
  EXPECT_EQ(c.nhc.vertical_std_mps, 0.3);
  EXPECT_EQ(c.nhc.min_speed_mps, 0);
  EXPECT_EQ(c.nhc.interval_s, 0.5);
  EXPECT_EQ(c.zupt.std_mps, 0.01);
  EXPECT_EQ(c.zupt.window_s, 0.5);
  EXPECT_EQ(c.zupt.max_rate_rad_s, 0.02);
  EXPECT_EQ(c.zupt.max_accel_std_mps2, 0.2);
  EXPECT_EQ(c.zupt.max_speed_mps, 0.1);
  EXPECT_EQ(c.gates.chi2_1d, 10.83);
  EXPECT_EQ(c.gates.chi2_2d, 13.82);
  EXPECT_EQ(c.gates.chi2_3d, 16.27);
  EXPECT_EQ(c.timing.max_latency_s, 0);
}

TEST(FilterKeys, OutOfPhysicalRangeRefusedNamingTheKey) {
  const struct {
    const char* yaml;
    const char* message;
  } refused[] = {
      {"gnss: {timeout_s: 0}", "gnss.timeout_s: must be in (0, 600], got 0"},
      {"gnss: {recovery_s: 1e4}", "gnss.recovery_s: must be in (0, 600], got 1e4"},
      {"gnss: {baseline_std_m: 0}", "gnss.baseline_std_m: must be in (0, 100], got 0"},
      {"gnss: {initial_lever_arm_std_m: -0.1}", "gnss.initial_lever_arm_std_m: must be in (0, 100], got -0.1"},
      {"gnss: {initial_time_offset_std_s: 0}", "gnss.initial_time_offset_std_s: must be in (0, 1], got 0"},
      {"gnss: {initial_time_offset_std_s: 2}", "gnss.initial_time_offset_std_s: must be in (0, 1], got 2"},
      {"imu: {max_gap_s: 0}", "imu.max_gap_s: must be in (0, 10], got 0"},
      {"imu: {initial_gyro_scale_std_ppm: 0}", "imu.initial_gyro_scale_std_ppm: must be in (0, 100000], got 0"},
      {"imu: {initial_mounting_std_deg: 200}", "imu.initial_mounting_std_deg: must be in (0, 180], got 200"},
      {"alignment: {initial_heading_std_deg: 0}", "alignment.initial_heading_std_deg: must be in (0, 180], got 0"},
      {"alignment: {initial_tilt_std_deg: -1}", "alignment.initial_tilt_std_deg: must be in (0, 180], got -1"},
      {"alignment: {initial_velocity_std_mps: 0}", "alignment.initial_velocity_std_mps: must be in (0, 100], got 0"},
      {"nhc: {lateral_std_mps: 0}", "nhc.lateral_std_mps: must be in (0, 100], got 0"},
      {"nhc: {min_speed_mps: -1}", "nhc.min_speed_mps: must be in [0, 100], got -1"},
      {"zupt: {std_mps: .nan}", "zupt.std_mps: expected a finite number"},
      {"zupt: {max_rate_rad_s: 50}", "zupt.max_rate_rad_s: must be in (0, 10], got 50"},
      {"gates: {chi2_3d: 0.5}", "gates.chi2_3d: must be in [1, 1e+06], got 0.5"},
      {"gates: {gnss_position: 0}", "gates.gnss_position: must be in [1, 1e+06], got 0"},
      {"gates: {odometry: .inf}", "gates.odometry: expected a finite number"},
      {"timing: {max_latency_s: 11}", "timing.max_latency_s: must be in [0, 10], got 11"},
  };
  for (const auto& r : refused) {
    EXPECT_NE(error_of(r.yaml).find(r.message), std::string::npos) << r.yaml << " -> " << error_of(r.yaml);
  }
}

TEST(FilterKeys, DumpReadsBackToTheSameValues) {
  const Config c = load_from_string(
      "platform: pedestrian\nimu: {estimate_mounting: true, initial_gyro_scale_std_ppm: 123.25}\n"
      "nhc: {enabled: true}\nzupt: {enabled: false}\nalignment: {course: true}\n"
      "gates: {chi2_2d: 9.21}\ntiming: {max_latency_s: 0.35}\n");
  const std::string yaml = to_yaml(c);
  EXPECT_NE(yaml.find("  estimate_mounting: true"), std::string::npos);
  EXPECT_NE(yaml.find("  estimate_gyro_scale: false"), std::string::npos);
  EXPECT_NE(yaml.find("nhc:\n  enabled: true"), std::string::npos);
  EXPECT_NE(yaml.find("zupt:\n  enabled: false"), std::string::npos);
  EXPECT_NE(yaml.find("  course: true"), std::string::npos);
  const Config back = load_from_string(yaml, "dump");
  EXPECT_TRUE(back.imu.estimate_mounting);
  EXPECT_EQ(back.imu.initial_gyro_scale_std_ppm, 123.25);
  EXPECT_EQ(back.nhc.enabled, std::optional<bool>(true));
  EXPECT_EQ(back.zupt.enabled, std::optional<bool>(false));
  EXPECT_EQ(back.alignment.course, std::optional<bool>(true));
  EXPECT_EQ(back.gates.chi2_2d, 9.21);
  EXPECT_EQ(back.timing.max_latency_s, 0.35);
  EXPECT_EQ(to_yaml(back), yaml);
  // Unset switches print as `~` and stay unset.
  const std::string unset = to_yaml(defaults_for(DeviceProfile::kGeneric));
  EXPECT_NE(unset.find("nhc:\n  enabled: ~"), std::string::npos);
  EXPECT_FALSE(load_from_string(unset).nhc.enabled);
}

}  // namespace
}  // namespace navfuse::config
