// `navfuse config --dump`: the demo config's values in the dump, dump -> load -> dump identical
// through files, errors naming the key, and README's list of every key equal to the dump of the
// defaults (the key table says it once; this test keeps README from drifting).
#include <gtest/gtest.h>

#include <string>

#include "apps/common/command_error.hpp"
#include "apps/configcmd/config_command.hpp"
#include "core/config/config.hpp"
#include "tests/apps/test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::read_text;
using testing::scratch_dir;
using testing::write_text;

const std::string kSource = NAVFUSE_SOURCE_DIR;

TEST(ConfigDump, DemoConfigValuesAppearWithEveryDefault) {
  const std::string dump = dump_config(kSource + "/data/demo/vn300.yaml", "");
  // Values set in data/demo/vn300.yaml (by hand from that file):
  EXPECT_NE(dump.find("device: vn300"), std::string::npos);
  EXPECT_NE(dump.find("platform: land"), std::string::npos);
  EXPECT_NE(dump.find("  gyro_arw_deg_rthr: 0.1  #"), std::string::npos);
  EXPECT_NE(dump.find("  accel_bias_instability_mps2: 0.000196  #"), std::string::npos);
  EXPECT_NE(dump.find("  initial_gyro_bias_std_deg_hr: 20.1  #"), std::string::npos);
  EXPECT_NE(dump.find("gnss:\n  lever_arm_m: [0.8, -0.4, -1.3]"), std::string::npos);
  EXPECT_NE(dump.find("wheel:\n  lever_arm_m: [-1.2, 0, 0.3]"), std::string::npos);
  // Keys the file leaves out, at their defaults:
  EXPECT_NE(dump.find("  timeout_s: 2  #"), std::string::npos);
  EXPECT_NE(dump.find("  chi2_3d: 21.11  #"), std::string::npos);
  EXPECT_NE(dump.find("nhc:\n  enabled: ~"), std::string::npos);
  // Every key of the table once.
  for (const auto& binding : config::key_table()) {
    const std::string leaf(binding.key.substr(binding.key.rfind('.') + 1));
    EXPECT_NE(dump.find(leaf + ": "), std::string::npos) << binding.key;
  }
}

TEST(ConfigDump, DumpLoadDumpIsIdentical) {
  const auto dir = scratch_dir();
  for (const char* demo : {"vn300", "cv7", "um220", "fusionengine"}) {
    const std::string first = dump_config(kSource + "/data/demo/" + demo + ".yaml", "");
    write_text(dir / "dumped.yaml", first);
    EXPECT_EQ(dump_config((dir / "dumped.yaml").string(), ""), first) << demo;
  }
  const std::string um220 = dump_config("", "um220");
  write_text(dir / "um220.yaml", um220);
  EXPECT_EQ(dump_config((dir / "um220.yaml").string(), ""), um220);
  EXPECT_EQ(um220, config::to_yaml(config::defaults_for(config::DeviceProfile::kUm220)));
}

TEST(ConfigDump, BadConfigOrDeviceIsAnErrorNamingTheKey) {
  const auto dir = scratch_dir();
  write_text(dir / "bad.yaml", "nhc:\n  enabled: maybe\n");
  try {
    dump_config((dir / "bad.yaml").string(), "");
    FAIL() << "accepted a bad switch";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find("nhc.enabled: expected true or false, got \"maybe\" (line 2)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(dump_config("", "vn400"), CommandError);
  EXPECT_THROW(dump_config((dir / "bad.yaml").string(), "cv7"), CommandError);
}

TEST(ConfigDump, ReadmeListsEveryKeyAsTheDumpPrintsIt) {
  const std::string readme = read_text(kSource + "/README.md");
  const std::string start = "<!-- navfuse config --dump -->\n```yaml\n";
  const auto begin = readme.find(start);
  ASSERT_NE(begin, std::string::npos) << "README: no `navfuse config --dump` block";
  const auto body = begin + start.size();
  const auto end = readme.find("```\n", body);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(readme.substr(body, end - body), dump_config("", ""))
      << "README's key list differs from `navfuse config --dump`: paste the dump into README";
}

}  // namespace
}  // namespace navfuse::apps
