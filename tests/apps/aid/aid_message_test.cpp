#include "apps/aid/aid_message.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(AidMessage, PositionLlhInDegreesBecomesRadians) {
  AidSpec s{"position", {37.5, -122.25, 12.0}, {0.5, 0.5, 1.0}, "llh", {0.1, 0.2, 0.3}, 1'000'000'000};
  const auto m = std::get<navfuse::aid_position_t>(make_aid_message(s));
  EXPECT_STREQ(aid_channel(m), "NAVFUSE_AID_POSITION");
  const ExternalPosition p = to_measurement(m);
  EXPECT_EQ(p.frame, PositionFrame::kLlh);
  EXPECT_DOUBLE_EQ(p.value.x(), 37.5 * kDeg);
  EXPECT_DOUBLE_EQ(p.value.y(), -122.25 * kDeg);
  EXPECT_DOUBLE_EQ(p.value.z(), 12.0);
  EXPECT_FLOAT_EQ(static_cast<float>(p.std_m.z()), 1.0f);
  EXPECT_EQ(p.header.valid, 0x7u);
  EXPECT_EQ(p.header.time_ns, 1'000'000'000);
  EXPECT_EQ(p.header.time_source, TimeSource::kGps);
  EXPECT_NEAR(p.lever_arm_m.y(), 0.2, 1e-7);
}

TEST(AidMessage, OneStdAppliesToEveryAxis) {
  AidSpec s{"velocity", {1, 2, 3}, {0.2}, "vehicle", {}, 5};
  const ExternalVelocity v = to_measurement(std::get<navfuse::aid_velocity_t>(make_aid_message(s)));
  EXPECT_EQ(v.frame, VelocityFrame::kVehicle);
  EXPECT_FLOAT_EQ(static_cast<float>(v.std_mps.x()), 0.2f);
  EXPECT_FLOAT_EQ(static_cast<float>(v.std_mps.z()), 0.2f);
}

TEST(AidMessage, HeadingAndSpeed) {
  const ExternalHeading h = to_measurement(std::get<navfuse::aid_heading_t>(make_aid_message({"heading", {90}, {2}, "", {}, 0})));
  EXPECT_NEAR(h.heading_rad, 90 * kDeg, 1e-7);
  EXPECT_NEAR(h.std_rad, 2 * kDeg, 1e-7);
  const VehicleSpeed sp = to_measurement(std::get<navfuse::aid_speed_t>(make_aid_message({"speed", {-3.5}, {0.1}, "", {}, 0})));
  EXPECT_FLOAT_EQ(static_cast<float>(sp.speed_mps), -3.5f);
  EXPECT_TRUE(sp.is_signed);
}

TEST(AidMessage, BadInputsNameTheProblem) {
  auto error_of = [](const AidSpec& s) {
    try {
      make_aid_message(s);
    } catch (const CommandError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of({"position", {1, 2}, {1}, "", {}, 0}).find("takes 3"), std::string::npos);
  EXPECT_NE(error_of({"heading", {10}, {0}, "", {}, 0}).find("> 0"), std::string::npos);
  EXPECT_NE(error_of({"heading", {10}, {-1}, "", {}, 0}).find("> 0"), std::string::npos);
  EXPECT_NE(error_of({"velocity", {1, 2, 3}, {1}, "body", {}, 0}).find("unknown frame 'body'"), std::string::npos);
  EXPECT_NE(error_of({"altitude", {1}, {1}, "", {}, 0}).find("unknown aiding kind"), std::string::npos);
  EXPECT_NE(error_of({"speed", {std::nan("")}, {1}, "", {}, 0}).find("finite"), std::string::npos);
  EXPECT_NE(error_of({"position", {95, 0, 0}, {1}, "llh", {}, 0}).find("out of range"), std::string::npos);
}

TEST(AidMessage, CsvRowsAndLineNumbersInErrors) {
  const std::string path = ::testing::TempDir() + "/aid.csv";
  {
    std::ofstream out(path);
    out << "kind,time_gps_s,frame,v1,v2,v3,std1,std2,std3\n"
        << "position,100.5,llh,10,20,30,1,1,2\n"
        << "speed,101,,4.5,0.05\n";
  }
  const auto rows = read_aid_csv(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].time_gps_ns, 100'500'000'000);
  EXPECT_EQ(rows[0].std, (std::vector<double>{1, 1, 2}));
  EXPECT_EQ(rows[1].values, (std::vector<double>{4.5}));
  {
    std::ofstream out(path);
    out << "position,100.5,llh,10,20,30,1,1,2\nheading,1,,x\n";
  }
  try {
    read_aid_csv(path);
    FAIL() << "expected an error";
  } catch (const CommandError& e) {
    EXPECT_NE(std::string(e.what()).find(":2:"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace navfuse::apps
