// Tick counts to speed (filter/measurements/wheel_ticks.hpp) against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "filter/measurements/wheel_ticks.hpp"

namespace navfuse::filter {
namespace {

TEST(WheelTicks, DeltaAcrossRollover) {
  // Unsigned 2^32 counter: 0xFFFFFFF0 -> 0x10 is 0x20 counts.
  EXPECT_EQ(tick_delta(0xFFFFFFF0u, 0x10u, 0, false), 32);
  // A counter wrapping at 1000: 990 -> 5 is 15 counts.
  EXPECT_EQ(tick_delta(990, 5, 1000, false), 15);
  // Signed counter mapped onto [0, 2000) (FusionEngine's two's-complement range, to_core.cpp):
  // 3 -> 1995 is 8 counts backward; 1995 -> 3 is 8 forward.
  EXPECT_EQ(tick_delta(3, 1995, 2000, true), -8);
  EXPECT_EQ(tick_delta(1995, 3, 2000, true), 8);
  EXPECT_EQ(tick_delta(100, 100, 0, true), 0);
}

WheelTicks ticks_at(double t_s, std::array<std::uint32_t, 4> counts, std::uint8_t channels) {
  WheelTicks t;
  t.header.time_ns = static_cast<std::int64_t>(std::llround(t_s * 1e9));
  t.ticks = counts;
  t.channels = channels;
  t.header.valid = channels == 1 ? WheelTicks::kValidFrontLeft : 0b1111u;
  t.gear = Gear::kForward;
  return t;
}

TEST(WheelTicks, VehicleCounterSpeedAndQuantisation) {
  // 250 counts of 0.02 m in 0.5 s: 10 m/s. Std: hypot(0.05, 0.02 / 0.5 / sqrt(6)) = 0.0529 m/s.
  const auto s = speed_from_ticks(ticks_at(1.0, {1000, 0, 0, 0}, 1), ticks_at(1.5, {1250, 0, 0, 0}, 1), 0.02, 0.05);
  ASSERT_TRUE(s.has_value());
  EXPECT_DOUBLE_EQ(s->interval_s, 0.5);
  EXPECT_NEAR(s->reading.speed_mps, 10.0, 1e-12);
  EXPECT_NEAR(s->reading.std_mps, std::hypot(0.05, 0.04 / std::sqrt(6.0)), 1e-12);
  // Reverse gear on an unsigned counter: the same counts backward.
  WheelTicks back = ticks_at(1.5, {1250, 0, 0, 0}, 1);
  back.gear = Gear::kReverse;
  EXPECT_NEAR(speed_from_ticks(ticks_at(1.0, {1000, 0, 0, 0}, 1), back, 0.02, 0.05)->reading.speed_mps, -10.0, 1e-12);
}

TEST(WheelTicks, FourWheelsUseTheRearPair) {
  // Rear wheels 100 and 110 counts of 0.01 m over 0.1 s: 10 and 11 m/s, mean 10.5 m/s; the front
  // (steered, 130 counts) is not used. Std of the mean of two wheels: per-wheel std / sqrt(2).
  const auto s = speed_from_ticks(ticks_at(0.0, {0, 0, 0, 0}, 4), ticks_at(0.1, {130, 130, 100, 110}, 4), 0.01, 0.05);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->reading.speed_mps, 10.5, 1e-9);
  EXPECT_NEAR(s->reading.std_mps, std::hypot(0.05, 0.1 / std::sqrt(6.0)) / std::sqrt(2.0), 1e-12);
  // No valid pair in both samples: no speed.
  WheelTicks partial = ticks_at(0.1, {130, 130, 100, 110}, 4);
  partial.header.valid = WheelTicks::kValidFrontLeft | WheelTicks::kValidRearLeft;
  EXPECT_FALSE(speed_from_ticks(ticks_at(0.0, {0, 0, 0, 0}, 4), partial, 0.01, 0.05).has_value());
  // Not later than the previous count: no speed.
  EXPECT_FALSE(speed_from_ticks(ticks_at(0.1, {0, 0, 0, 0}, 4), ticks_at(0.1, {1, 1, 1, 1}, 4), 0.01, 0.05));
}

}  // namespace
}  // namespace navfuse::filter
