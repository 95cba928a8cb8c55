#include "core/time/clock_model.hpp"

#include <gtest/gtest.h>

#include <random>

namespace navfuse::time {
namespace {

TEST(ClockModel, InvalidUntilFirstPair) {
  ClockModel m;
  EXPECT_FALSE(m.valid());
  EXPECT_FALSE(m.to_gps(123).has_value());
}

TEST(ClockModel, FollowsOffsetAndDrift) {
  // Device clock runs 50 ppm fast-of-GPS plus a fixed offset; pairs once per second with 1 us
  // of timestamp jitter. After 60 pairs the mapping is good to a few us across the span.
  ClockModel m;
  const std::int64_t offset_ns = 1'300'000'000'000'000'000LL;
  const double drift = -50e-6;  // gps advances (1 - 50e-6) s per device second
  std::mt19937 rng(7);
  std::normal_distribution<double> jitter_ns(0.0, 1000.0);
  auto gps_of = [&](std::int64_t dev) {
    return offset_ns + dev + static_cast<std::int64_t>(drift * static_cast<double>(dev));
  };
  for (int i = 0; i < 60; ++i) {
    const std::int64_t dev = 5'000'000'000LL + i * 1'000'000'000LL;
    m.add_pair(dev, gps_of(dev) + static_cast<std::int64_t>(jitter_ns(rng)));
  }
  EXPECT_NEAR(m.drift_ppm(), -50.0, 1.0);
  for (std::int64_t dev : {10'000'000'000LL, 40'000'000'000LL, 64'500'000'000LL}) {
    EXPECT_NEAR(static_cast<double>(*m.to_gps(dev) - gps_of(dev)), 0.0, 5000.0) << dev;
  }
}

TEST(ClockModel, JumpRestartsTheFit) {
  ClockModel m;
  m.add_pair(0, 1'000'000'000'000LL);
  m.add_pair(1'000'000'000, 1'001'000'000'000LL);
  // The device rebooted: its clock restarted near zero while GPS moved on.
  m.add_pair(2'000'000, 1'002'000'000'000LL);
  EXPECT_EQ(m.resets(), 1u);
  EXPECT_EQ(*m.to_gps(2'000'000), 1'002'000'000'000LL);
}

}  // namespace
}  // namespace navfuse::time
