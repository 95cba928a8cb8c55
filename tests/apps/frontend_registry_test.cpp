// What the apps take from FrontendInfo instead of comparing format names (issue 13): every
// registered front-end is complete, its default profile is the `device:` a user would write for
// that device in a config (README "Configuration"), and `navfuse sim` finds its formats, its
// odometry protocol and its device-solution rates through the registry.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "apps/common/frontend_registry.hpp"
#include "apps/simcmd/device_solution_model.hpp"

namespace navfuse::apps {
namespace {

TEST(FrontendRegistry, EveryFrontendIsCompleteAndNamesItsDeviceProfile) {
  // The devices of README "Configuration", by the INPUT prefix of DESIGN.md.
  const std::map<std::string, std::string> device_of = {
      {"fe", "fusionengine"}, {"mip", "cv7"}, {"vn", "vn300"}, {"unicore", "um220"},
      // Research-data files (issue 14), no device of their own.
      {"rtklib", "generic"}, {"imutxt", "generic"}};
  ASSERT_EQ(frontends_list().size(), device_of.size());
  for (const frontends::FrontendInfo* f : frontends_list()) {
    SCOPED_TRACE(std::string(f->format));
    ASSERT_TRUE(device_of.contains(std::string(f->format)));
    EXPECT_EQ(find_frontend(f->format), f);
    EXPECT_NE(f->probe, nullptr);
    EXPECT_NE(f->make_decoder, nullptr);
    EXPECT_EQ(f->make_decoder()->format(), f->format);
    EXPECT_EQ(std::optional(f->default_profile), config::device_profile_from_string(device_of.at(std::string(f->format))));
    // A set-up sequence and its reply check come together.
    EXPECT_EQ(f->setup_steps == nullptr, f->find_refusal == nullptr);
  }
}

TEST(FrontendRegistry, SetUpIsSentToTheDevicesThatNeedIt) {
  // VN-300, CV7 and UM220 must be told what to stream; every device but the UM220 (which has no
  // lever-arm command) is given the installation geometry, read back: a FusionEngine device,
  // which streams by default, gets only that (apps/run/device_setup.hpp).
  const config::Config config;
  for (const char* format : {"vn", "mip", "unicore", "fe"}) {
    const frontends::FrontendInfo* f = find_frontend(format);
    ASSERT_NE(f, nullptr);
    ASSERT_NE(f->setup_steps, nullptr) << format;
    const auto steps = f->setup_steps(config);
    EXPECT_FALSE(steps.empty()) << format;
    std::size_t read_backs = 0;
    for (const auto& s : steps) read_backs += s.verify ? 1 : 0;
    EXPECT_EQ(read_backs > 0, std::string_view(format) != "unicore") << format;
  }
}

TEST(FrontendRegistry, SimFindsFormatsOdometryAndSolutionRates) {
  // Every device protocol can be written; the research-data readers (rtklib, imutxt) cannot.
  EXPECT_EQ(writable_formats(), (std::vector<std::string>{"fe", "mip", "vn", "unicore"}));
  // Simulated odometry goes where a host sends it to a fusion device: FusionEngine's wheel and
  // vehicle speed input messages.
  ASSERT_NE(odometry_input_frontend(), nullptr);
  EXPECT_EQ(odometry_input_frontend()->format, "fe");
  // VN-300 and CV7 output their INS solution with the IMU; the UM220 at 5 Hz, FusionEngine 10 Hz.
  EXPECT_EQ(device_error_class(*find_frontend("vn"), 400.0).rate_hz, 400.0);
  EXPECT_EQ(device_error_class(*find_frontend("mip"), 100.0).rate_hz, 100.0);
  EXPECT_EQ(device_error_class(*find_frontend("unicore"), 100.0).rate_hz, 5.0);
  EXPECT_EQ(device_error_class(*find_frontend("fe"), 100.0).rate_hz, 10.0);
}

}  // namespace
}  // namespace navfuse::apps
