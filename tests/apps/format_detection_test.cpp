// Detection with the text readers registered: every demo log and every shared capture is still
// detected as the format it is (the unchecked text formats must not steal a binary or NMEA /
// Unicore ASCII log), and the walk's files as imutxt and rtklib.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "apps/common/input_spec.hpp"

namespace navfuse::apps {
namespace {

struct Case {
  std::string path;
  std::string format;
};

void expect_detected(const Case& c) {
  SCOPED_TRACE(c.path);
  const InputSpec spec = resolve_input(c.path);
  EXPECT_TRUE(spec.format_detected);
  EXPECT_EQ(spec.frontend->format, c.format);
}

TEST(FormatDetection, DemoLogsKeepTheirFormats) {
  const std::string demo = std::string(NAVFUSE_SOURCE_DIR) + "/data/demo/";
  for (const Case& c : {Case{demo + "atlas.p1log", "fe"}, Case{demo + "vn300_wheel.p1log", "fe"},
                        Case{demo + "cv7.mip", "mip"}, Case{demo + "vn300.vnb", "vn"},
                        Case{demo + "um220.log", "unicore"}}) {
    expect_detected(c);
  }
}

TEST(FormatDetection, SharedCapturesKeepTheirFormats) {
  const std::string shared = std::string(NAVFUSE_SHARED_DIR) + "/captures/";
  if (!std::filesystem::exists(shared)) GTEST_SKIP() << "captures not present";
  for (const Case& c : {Case{shared + "fe_example_data.p1log", "fe"}, Case{shared + "mip_sdk_mip_data.bin", "mip"},
                        Case{shared + "real/walk_0827/imu.txt", "imutxt"},
                        Case{shared + "real/walk_0827/gnss.pos", "rtklib"}}) {
    expect_detected(c);
  }
}

}  // namespace
}  // namespace navfuse::apps
