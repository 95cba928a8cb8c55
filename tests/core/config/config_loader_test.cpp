// Loading configs: every key parsed, strict errors naming the key, to_yaml round trip, and the
// example configs shipped in data/config/.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/config/config.hpp"
#include "tests/core/config/config_error_of.hpp"

namespace navfuse::config {
namespace {

using test::error_of;

TEST(ConfigLoader, EveryKeyIsParsed) {
  // Each key gets a value no profile uses, so reading it back proves the binding.
  const Config c = load_from_string(R"(
device: vn300
imu:
  mounting_rpy_deg: [1.5, -2.5, 3.5]
  gyro_arw_deg_rthr: 0.101
  gyro_bias_instability_deg_hr: 0.102
  gyro_bias_corr_time_s: 103
  accel_vrw_mps_rthr: 0.104
  accel_bias_instability_mps2: 1.05e-5
  accel_bias_corr_time_s: 106
  initial_gyro_bias_std_deg_hr: 107
  initial_accel_bias_std_mps2: 0.108
gnss:
  lever_arm_m: [0.11, 0.12, -0.13]
  secondary_lever_arm_m: [-1.4, 0.15, +0.16]
wheel:
  lever_arm_m: [-2.1, 0, 0.3]
  speed_std_mps: 0.17
output:
  rate_hz: 50
)");
  EXPECT_EQ(c.device, DeviceProfile::kVn300);
  EXPECT_EQ(c.imu.mounting_rpy_deg, (Vec3{1.5, -2.5, 3.5}));
  EXPECT_EQ(c.imu.gyro_arw_deg_rthr, 0.101);
  EXPECT_EQ(c.imu.gyro_bias_instability_deg_hr, 0.102);
  EXPECT_EQ(c.imu.gyro_bias_corr_time_s, 103);
  EXPECT_EQ(c.imu.accel_vrw_mps_rthr, 0.104);
  EXPECT_EQ(c.imu.accel_bias_instability_mps2, 1.05e-5);
  EXPECT_EQ(c.imu.accel_bias_corr_time_s, 106);
  EXPECT_EQ(c.imu.initial_gyro_bias_std_deg_hr, 107);
  EXPECT_EQ(c.imu.initial_accel_bias_std_mps2, 0.108);
  EXPECT_EQ(c.gnss.lever_arm_m, (Vec3{0.11, 0.12, -0.13}));
  EXPECT_EQ(c.gnss.secondary_lever_arm_m, (Vec3{-1.4, 0.15, 0.16}));
  EXPECT_EQ(c.wheel.lever_arm_m, (Vec3{-2.1, 0, 0.3}));
  EXPECT_EQ(c.wheel.speed_std_mps, 0.17);
  EXPECT_EQ(c.output.rate_hz, 50);
}

TEST(ConfigLoader, TableCoversEveryKeyOfTheDesign) {
  // DESIGN.md's key list (contract): each must be in the table.
  const char* design_keys[] = {
      "imu.mounting_rpy_deg", "imu.gyro_arw_deg_rthr", "imu.gyro_bias_instability_deg_hr",
      "imu.gyro_bias_corr_time_s", "imu.accel_vrw_mps_rthr", "imu.accel_bias_instability_mps2",
      "imu.accel_bias_corr_time_s", "imu.initial_gyro_bias_std_deg_hr",
      "imu.initial_accel_bias_std_mps2", "gnss.lever_arm_m", "gnss.secondary_lever_arm_m",
      "wheel.lever_arm_m", "wheel.speed_std_mps", "output.rate_hz"};
  for (const char* key : design_keys) {
    bool found = false;
    for (const KeyBinding& b : key_table()) found = found || b.key == key;
    EXPECT_TRUE(found) << key;
  }
}

TEST(ConfigLoader, ProfileDefaultsThenOverrides) {
  const Config cv7 = defaults_for(DeviceProfile::kCv7);
  const Config c = load_from_string("device: cv7\nimu:\n  gyro_arw_deg_rthr: 0.5\n");
  EXPECT_EQ(c.device, DeviceProfile::kCv7);
  EXPECT_EQ(c.imu.gyro_arw_deg_rthr, 0.5);  // overridden
  EXPECT_EQ(c.imu.gyro_bias_instability_deg_hr, cv7.imu.gyro_bias_instability_deg_hr);
  EXPECT_EQ(c.imu.accel_vrw_mps_rthr, cv7.imu.accel_vrw_mps_rthr);

  // `device` picks the defaults even when it comes after the overrides.
  const Config late = load_from_string("imu: {gyro_arw_deg_rthr: 0.5}\ndevice: um220\n");
  EXPECT_EQ(late.imu.gyro_arw_deg_rthr, 0.5);
  EXPECT_EQ(late.imu.gyro_bias_instability_deg_hr,
            defaults_for(DeviceProfile::kUm220).imu.gyro_bias_instability_deg_hr);
}

TEST(ConfigLoader, EmptyFileIsRefused) {
  // An empty or comment-only file is a wrong or cut file more often than a wish for defaults.
  for (const char* text : {"", "# only a comment\n", "\n\n"}) {
    EXPECT_EQ(error_of(text), "config.yaml: empty configuration: give at least `device:`") << "input: " << text;
  }
  // A section with every key commented out still means "the defaults of this section".
  EXPECT_EQ(to_yaml(load_from_string("imu:\n")), to_yaml(defaults_for(DeviceProfile::kGeneric)));
  const Config only_device = load_from_string("device: fusionengine\n");
  EXPECT_EQ(to_yaml(only_device), to_yaml(defaults_for(DeviceProfile::kFusionEngine)));
}

TEST(ConfigLoader, UnknownKeyIsNamedWithSuggestion) {
  const std::string e = error_of("imu:\n  gyro_arw: 0.1\n");
  EXPECT_NE(e.find("config.yaml: unknown key 'imu.gyro_arw'"), std::string::npos) << e;
  EXPECT_NE(e.find("line 2"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'imu.gyro_arw_deg_rthr'"), std::string::npos) << e;

  const std::string typo = error_of("wheel:\n  sped_std_mps: 0.1\n");
  EXPECT_NE(typo.find("did you mean 'wheel.speed_std_mps'"), std::string::npos) << typo;

  const std::string top = error_of("outptu:\n  rate_hz: 10\n");
  EXPECT_NE(top.find("unknown key 'outptu'"), std::string::npos) << top;
  EXPECT_NE(top.find("did you mean 'output'"), std::string::npos) << top;

  const std::string nothing_close = error_of("zzzzzzzzzzzzzzzz: 1\n");
  EXPECT_NE(nothing_close.find("unknown key 'zzzzzzzzzzzzzzzz'"), std::string::npos);
  EXPECT_EQ(nothing_close.find("did you mean"), std::string::npos) << nothing_close;
}

TEST(ConfigLoader, NestedUnknownSectionIsNamed) {
  const std::string e = error_of("imu:\n  extra:\n    depth: 1\n");
  EXPECT_NE(e.find("unknown key 'imu.extra'"), std::string::npos) << e;
  const std::string top = error_of("filter:\n  gnss:\n    gate: 3\n");
  EXPECT_NE(top.find("unknown key 'filter'"), std::string::npos) << top;
}

TEST(ConfigLoader, WrongTypesNameTheKey) {
  EXPECT_EQ(error_of("imu:\n  gyro_arw_deg_rthr: fast\n"),
            "config.yaml: imu.gyro_arw_deg_rthr: expected a number, got \"fast\" (line 2)");
  EXPECT_NE(error_of("imu: {gyro_arw_deg_rthr: [1, 2]}").find(
                "imu.gyro_arw_deg_rthr: expected a number, got a list of 2"),
            std::string::npos);
  EXPECT_NE(error_of("imu: {gyro_arw_deg_rthr: '0.1'}").find("imu.gyro_arw_deg_rthr: expected a "
                                                             "number, got the string \"0.1\""),
            std::string::npos);
  EXPECT_NE(error_of("imu: {gyro_arw_deg_rthr: }").find("got nothing"), std::string::npos);
  EXPECT_NE(error_of("imu: {gyro_arw_deg_rthr: 1.5x}").find("expected a number"),
            std::string::npos);
  EXPECT_NE(error_of("imu: 5\n").find("config.yaml: imu: expected a section of keys, got \"5\""),
            std::string::npos);
  EXPECT_NE(error_of("device: vn200\n").find("config.yaml: device: expected one of cv7, vn300"),
            std::string::npos);
  EXPECT_NE(error_of("- 1\n- 2\n").find("expected a mapping of keys at the top level"),
            std::string::npos);
}

TEST(ConfigLoader, WrongArrayLengths) {
  EXPECT_NE(error_of("gnss:\n  lever_arm_m: [1, 2]\n")
                .find("gnss.lever_arm_m: expected a list of 3 numbers, got a list of 2 (line 2)"),
            std::string::npos);
  EXPECT_NE(error_of("gnss: {lever_arm_m: [1, 2, 3, 4]}").find("got a list of 4"),
            std::string::npos);
  EXPECT_NE(error_of("gnss: {lever_arm_m: 1}").find("expected a list of 3 numbers"),
            std::string::npos);
  EXPECT_NE(error_of("gnss: {lever_arm_m: [1, x, 3]}")
                .find("gnss.lever_arm_m[1]: expected a number, got \"x\""),
            std::string::npos);
}

TEST(ConfigLoader, NegativeAndNonFiniteValues) {
  EXPECT_NE(error_of("imu: {accel_vrw_mps_rthr: -0.1}")
                .find("imu.accel_vrw_mps_rthr: must be > 0, got -0.1"),
            std::string::npos);
  EXPECT_NE(error_of("imu: {gyro_bias_corr_time_s: 0}")
                .find("imu.gyro_bias_corr_time_s: must be > 0, got 0"),
            std::string::npos);
  EXPECT_NE(error_of("wheel: {speed_std_mps: .nan}").find("expected a finite number, got \".nan\""),
            std::string::npos);
  EXPECT_NE(error_of("output: {rate_hz: .inf}").find("expected a finite number"),
            std::string::npos);
  EXPECT_NE(error_of("gnss: {lever_arm_m: [0, -.inf, 0]}").find("gnss.lever_arm_m[1]: expected a "
                                                                "finite number"),
            std::string::npos);
  EXPECT_NE(error_of("output: {rate_hz: 1e999}").find("out of range"), std::string::npos);
  // Lever arms and mounting angles may be negative.
  EXPECT_EQ(error_of("imu: {mounting_rpy_deg: [-180, -90, -1]}"), "");
}

// Values that would wreck the solution rather than tune it (issue 15 item 8), each refused with
// the key named.
TEST(ConfigLoader, ValuesOutsideThePhysicalRangeAreRefused) {
  EXPECT_EQ(error_of("gnss:\n  lever_arm_m: [1e9, 0, 0]\n"),
            "config.yaml: gnss.lever_arm_m[0]: must be in [-100, 100], got 1e9 (line 2)");
  EXPECT_NE(error_of("gnss: {secondary_lever_arm_m: [0, 0, -100.5]}")
                .find("gnss.secondary_lever_arm_m[2]: must be in [-100, 100], got -100.5"),
            std::string::npos);
  EXPECT_NE(error_of("wheel: {lever_arm_m: [0, 101, 0]}").find("wheel.lever_arm_m[1]: must be in [-100, 100]"),
            std::string::npos);
  EXPECT_EQ(error_of("gnss: {lever_arm_m: [100, -100, 0.5]}"), "");  // the bounds themselves are fine

  EXPECT_NE(error_of("wheel: {speed_std_mps: 0}").find("wheel.speed_std_mps: must be > 0, got 0"),
            std::string::npos);
  EXPECT_NE(error_of("imu: {gyro_arw_deg_rthr: 0}").find("imu.gyro_arw_deg_rthr: must be > 0, got 0"),
            std::string::npos);
  EXPECT_NE(error_of("imu: {accel_vrw_mps_rthr: 0.0}").find("imu.accel_vrw_mps_rthr: must be > 0"),
            std::string::npos);

  EXPECT_NE(error_of("imu: {mounting_rpy_deg: [0, 0, 1e20]}")
                .find("imu.mounting_rpy_deg[2]: must be in [-360, 360], got 1e20"),
            std::string::npos);
  EXPECT_NE(error_of("imu: {mounting_rpy_deg: [-360.1, 0, 0]}").find("imu.mounting_rpy_deg[0]"),
            std::string::npos);
  EXPECT_EQ(error_of("imu: {mounting_rpy_deg: [-360, 360, 0]}"), "");

  EXPECT_NE(error_of("imu: {initial_gyro_bias_std_deg_hr: 1e300}")
                .find("imu.initial_gyro_bias_std_deg_hr: must be in (0, 100000], got 1e300"),
            std::string::npos);
  EXPECT_NE(error_of("imu: {initial_gyro_bias_std_deg_hr: 0}").find("imu.initial_gyro_bias_std_deg_hr: must be"),
            std::string::npos);
  EXPECT_EQ(error_of("imu: {initial_gyro_bias_std_deg_hr: 1e5}"), "");
  EXPECT_NE(error_of("imu: {initial_accel_bias_std_mps2: 101}")
                .find("imu.initial_accel_bias_std_mps2: must be in (0, 100], got 101"),
            std::string::npos);
  EXPECT_EQ(error_of("imu: {initial_accel_bias_std_mps2: 100}"), "");

  // Non-finite numbers are refused for every key, whatever its range.
  for (const KeyBinding& b : key_table()) {
    if (std::holds_alternative<Platform* (*)(Config&)>(b.target)) continue;  // a name, not a number
    // A switch is not a number either: its error says what it takes.
    const bool is_switch = std::holds_alternative<bool* (*)(Config&)>(b.target) ||
                           std::holds_alternative<std::optional<bool>* (*)(Config&)>(b.target);
    const std::string key(b.key);
    const std::string section = key.substr(0, key.find('.'));
    const std::string name = key.substr(key.find('.') + 1);
    const bool list = std::holds_alternative<Vec3* (*)(Config&)>(b.target) ||
                      std::holds_alternative<std::optional<Vec3>* (*)(Config&)>(b.target);
    for (const char* bad : {".nan", ".inf", "-.inf"}) {
      const std::string value = list ? std::string("[0, ") + bad + ", 0]" : std::string(bad);
      const std::string e = error_of(section + ": {" + name + ": " + value + "}");
      EXPECT_NE(e.find(key), std::string::npos) << key << " = " << value << ": " << e;
      EXPECT_NE(e.find(is_switch ? "expected true or false" : "expected a finite number"), std::string::npos)
          << key << " = " << value << ": " << e;
    }
  }
}

TEST(ConfigLoader, DuplicateKeyAndBadYaml) {
  EXPECT_NE(error_of("output:\n  rate_hz: 1\n  rate_hz: 2\n").find("output.rate_hz: duplicate key"),
            std::string::npos);
  const std::string bad = error_of("imu: [1, 2\n");
  EXPECT_NE(bad.find("config.yaml:"), std::string::npos);
  EXPECT_NE(bad.find("invalid YAML"), std::string::npos) << bad;
}

TEST(ConfigLoader, ToYamlRoundTrips) {
  Config c = defaults_for(DeviceProfile::kVn300);
  c.imu.mounting_rpy_deg = {0.1, -179.99999999999997, 1e-300};
  c.gnss.lever_arm_m = {1.0 / 3.0, -2.5, 0.0};
  c.output.rate_hz = 0;
  const std::string yaml = to_yaml(c);
  EXPECT_NE(yaml.find("device: vn300"), std::string::npos);
  EXPECT_NE(yaml.find("imu:\n  mounting_rpy_deg: [0.1, "), std::string::npos) << yaml;
  const Config back = load_from_string(yaml, "to_yaml");
  EXPECT_EQ(back.device, c.device);
  EXPECT_EQ(back.imu.mounting_rpy_deg, c.imu.mounting_rpy_deg);
  EXPECT_EQ(back.gnss.lever_arm_m, c.gnss.lever_arm_m);
  EXPECT_EQ(to_yaml(back), yaml);
}

TEST(ConfigLoader, MissingFileNamesThePath) {
  const std::string path = "/nonexistent-navfuse-dir/config.yaml";
  try {
    load_from_file(path);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(ConfigLoader, FileErrorsNameTheFile) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("navfuse_config_test_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << "imu:\n  gyro_arw: 1\n";
  try {
    load_from_file(path.string());
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": unknown key 'imu.gyro_arw'", 0), 0u)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(ConfigLoader, ShippedExamplesLoad) {
  const std::pair<const char*, DeviceProfile> examples[] = {
      {"vn300.yaml", DeviceProfile::kVn300},
      {"cv7.yaml", DeviceProfile::kCv7},
      {"um220.yaml", DeviceProfile::kUm220},
      {"fusionengine.yaml", DeviceProfile::kFusionEngine},
  };
  for (const auto& [name, device] : examples) {
    const std::string path = std::string(NAVFUSE_SOURCE_DIR) + "/data/config/" + name;
    SCOPED_TRACE(path);
    Config c;
    ASSERT_NO_THROW(c = load_from_file(path));
    EXPECT_EQ(c.device, device);
  }
}

}  // namespace
}  // namespace navfuse::config
