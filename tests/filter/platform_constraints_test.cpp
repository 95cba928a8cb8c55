// Platform profiles decide the constraints: the simulator's short drive (static start, stops at
// 137-160 s and 176-190 s, 10 Hz GNSS and speed) run through the engine with the constraint
// switches that options_from_config sets for each `platform:`. A land vehicle applies NHC and
// ZUPTs; a pedestrian never applies NHC but still ZUPTs at the stops; airborne and marine apply
// neither. Every platform still navigates.
#include <gtest/gtest.h>

#include <algorithm>

#include "filter/engine.hpp"
#include "tests/filter/drive_stream.hpp"

namespace navfuse::filter {
namespace {

FilterOptions for_platform(config::Platform platform, FilterOptions base) {
  config::Config c;
  c.platform = platform;
  const FilterOptions from_config = options_from_config(c);
  base.land_vehicle = from_config.land_vehicle;
  base.zero_velocity_updates = from_config.zero_velocity_updates;
  return base;
}

struct DriveResult {
  FilterStats stats;
  bool navigated = false;
};

DriveResult run_drive(config::Platform platform) {
  static const test::DriveStream drive = test::make_drive_stream(190.0);
  Engine e{for_platform(platform, drive.options)};
  for (const auto& m : drive.measurements) e.process(m);
  const auto modes = e.modes_reached();
  return {e.stats(), std::find(modes.begin(), modes.end(), NavMode::kNavigation) != modes.end()};
}

TEST(PlatformConstraints, OptionsFollowThePlatform) {
  config::Config c;
  EXPECT_FALSE(options_from_config(c).land_vehicle);  // default: generic, no motion assumptions
  EXPECT_FALSE(options_from_config(c).course_alignment);
  EXPECT_TRUE(options_from_config(c).zero_velocity_updates);
  EXPECT_EQ(options_from_config(c).kinematic_alignment_speed_mps, 2.0);
  c.platform = config::Platform::kLand;
  EXPECT_TRUE(options_from_config(c).land_vehicle);
  EXPECT_TRUE(options_from_config(c).course_alignment);
  c.platform = config::Platform::kPedestrian;
  EXPECT_FALSE(options_from_config(c).land_vehicle);
  EXPECT_TRUE(options_from_config(c).zero_velocity_updates);
  EXPECT_EQ(options_from_config(c).kinematic_alignment_speed_mps, 0.5);
  c.alignment.min_speed_mps = 0.8;
  c.alignment.initial_heading_deg = 270.0;  // = -90 deg
  EXPECT_EQ(options_from_config(c).kinematic_alignment_speed_mps, 0.8);
  EXPECT_NEAR(*options_from_config(c).initial_heading_rad, -0.5 * 3.14159265358979323846, 1e-15);
  for (auto p : {config::Platform::kAirborne, config::Platform::kMarine}) {
    c.platform = p;
    EXPECT_FALSE(options_from_config(c).land_vehicle);
    EXPECT_FALSE(options_from_config(c).zero_velocity_updates);
  }
}

TEST(PlatformConstraints, LandAppliesNhcAndZupt) {
  const DriveResult land = run_drive(config::Platform::kLand);
  EXPECT_TRUE(land.navigated);
  EXPECT_GT(land.stats.nhc_updates, 100u);  // 10 Hz over ~130 s of driving
  EXPECT_GT(land.stats.zupts, 50u);         // 5 Hz over ~40 s of stops
}

TEST(PlatformConstraints, PedestrianNeverAppliesNhcButStopsAtRest) {
  const DriveResult walk = run_drive(config::Platform::kPedestrian);
  EXPECT_TRUE(walk.navigated);
  EXPECT_EQ(walk.stats.nhc_updates, 0u);
  EXPECT_GT(walk.stats.zupts, 50u);
}

TEST(PlatformConstraints, AirborneAndMarineApplyNeither) {
  for (auto p : {config::Platform::kAirborne, config::Platform::kMarine}) {
    const DriveResult r = run_drive(p);
    EXPECT_TRUE(r.navigated);
    EXPECT_EQ(r.stats.nhc_updates, 0u);
    EXPECT_EQ(r.stats.zupts, 0u);
  }
}

}  // namespace
}  // namespace navfuse::filter
