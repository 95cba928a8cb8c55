// Real-receiver GNSS effects: multipath jump events (Poisson in their windows, offsets of the
// given size, covariance unchanged) and the per-fix-type error statistics of a fix-type history.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "apps/sim/gnss_model.hpp"
#include "apps/sim/reality_scenarios.hpp"
#include "apps/sim/scenarios.hpp"
#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr std::int64_t kStart = 1'400'000'000LL * 1'000'000'000LL;

TruthSample standing() {
  TruthSample t;
  t.time_ns = kStart;
  t.llh = {47.0 * rot::kDegToRad, 8.0 * rot::kDegToRad, 400.0};
  return t;
}

TEST(Multipath, EventsArePoissonInTheirWindowsWithTheGivenSizes) {
  MultipathSpec spec;
  spec.windows = {{100.0, 20100.0}, {30000.0, 30500.0}};
  spec.events_per_minute = 6.0;
  const std::vector<MultipathEvent> events = multipath_events(spec, 5);
  // 20500 s at 6 per minute, less the time taken by the events themselves (mean 3 s after each
  // 10 s mean gap): expected 20500 / 13 = 1577, Poisson std 40.
  EXPECT_NEAR(static_cast<double>(events.size()), 20500.0 / 13.0, 160.0);
  int decimetre = 0, metre = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    const MultipathEvent& e = events[i];
    EXPECT_TRUE((e.interval.start_s >= 100.0 && e.interval.end_s <= 20100.0) ||
                (e.interval.start_s >= 30000.0 && e.interval.end_s <= 30500.0));
    if (i > 0) {
      EXPECT_GE(e.interval.start_s, events[i - 1].interval.end_s);  // no overlap
    }
    const double h = e.offset_ned_m.head<2>().norm();
    EXPECT_GE(h, 0.2 - 1e-12);
    EXPECT_LE(h, 3.0 + 1e-12);
    EXPECT_LE(std::abs(e.offset_ned_m.z()), h + 1e-12);
    decimetre += h < 1.0;
    metre += h >= 1.0;
  }
  // Log-uniform magnitudes: P(h < 1 m) = ln(5) / ln(15) = 0.594.
  EXPECT_NEAR(decimetre / static_cast<double>(events.size()), 0.594, 0.04);
  EXPECT_GT(metre, 0);
  // Inside an event its offset; between events none.
  bool active = false;
  const MultipathEvent& e = events[10];
  EXPECT_EQ(multipath_offset(events, 0.5 * (e.interval.start_s + e.interval.end_s), &active), e.offset_ned_m);
  EXPECT_TRUE(active);
  EXPECT_EQ(multipath_offset(events, 50.0, &active), Eigen::Vector3d::Zero());
  EXPECT_FALSE(active);
}

TEST(Multipath, FixesCarryTheOffsetWhileReportingTheirUsualCovariance) {
  GnssSpec spec = gnss_rtk_fixed(10.0);
  spec.multipath.windows = {{0.0, 600.0}};
  const std::vector<MultipathEvent> events = multipath_events(spec.multipath, 9);
  GnssModel model(spec, 9);
  TruthSample t = standing();
  GnssPosition p;
  GnssVelocity v;
  GnssHeading h;
  int hit = 0;
  for (int i = 0; i < 6000; ++i) {
    t.time_ns = kStart + i * model.period_ns();
    const double t_s = i * 0.1;
    const GnssModel::Epoch epoch = model.make_epoch(t, t_s, p, v, h);
    bool active = false;
    const Eigen::Vector3d expected = multipath_offset(events, t_s, &active);
    EXPECT_EQ(epoch.multipath, active);
    hit += active;
    const Eigen::Vector3d err = geo::ned_offset_m(t.llh, {p.lat_rad, p.lon_rad, p.height_m}) - expected;
    EXPECT_LT(err.head<2>().norm(), 0.02 * 5.0);  // what is left is the RTK noise
    EXPECT_DOUBLE_EQ(p.cov_ned_m2(0, 0), 0.02 * 0.02);
    EXPECT_EQ(p.fix, GnssFixType::kRtkFixed);
  }
  EXPECT_GT(hit, 100);
}

TEST(ReceiverFixNoise, FloatErrorsAreSlowBiasesAndFixedOnesWhite) {
  // Reported std devs are the defaults; the float error keeps 90 % of its variance correlated
  // over 60 s: correlation at a 10 s lag 0.9 exp(-10 / 60) = 0.762; fixed: none.
  for (const GnssFixType fix : {GnssFixType::kRtkFixed, GnssFixType::kRtkFloat}) {
    GnssSpec spec = gnss_rtk_fixed(1.0);
    spec.fix = fix;
    spec.noise = receiver_fix_noise(fix);
    EXPECT_EQ(spec.noise.horizontal_std_m, default_gnss_noise(fix).horizontal_std_m);
    GnssModel model(spec, 21);
    TruthSample t = standing();
    GnssPosition p;
    GnssVelocity v;
    GnssHeading h;
    std::vector<double> north;
    for (int i = 0; i < 200000; ++i) {
      t.time_ns = kStart + static_cast<std::int64_t>(i) * model.period_ns();
      model.make_epoch(t, i, p, v, h);
      north.push_back(geo::ned_offset_m(t.llh, {p.lat_rad, p.lon_rad, p.height_m}).x());
    }
    double var = 0.0, cov10 = 0.0;
    for (std::size_t i = 0; i + 10 < north.size(); ++i) {
      var += north[i] * north[i];
      cov10 += north[i] * north[i + 10];
    }
    const double sigma = spec.noise.horizontal_std_m;
    const double n = static_cast<double>(north.size() - 10);
    EXPECT_NEAR(std::sqrt(var / n) / sigma, 1.0, 0.05) << static_cast<int>(fix);
    const double expected = fix == GnssFixType::kRtkFloat ? 0.9 * std::exp(-10.0 / 60.0) : 0.0;
    EXPECT_NEAR(cov10 / var, expected, 0.05) << static_cast<int>(fix);
  }
}

TEST(ReceiverFixNoise, FixChangeScenarioReportsEachTypeWithItsStdDevs) {
  const Scenario s = make_scenario("rtk_fix_changes");
  GnssModel model(s.gnss, s.seed);
  int float_to_fixed = 0;
  GnssFixType previous = GnssFixType::kRtkFixed;
  for (double t_s = 0.0; t_s < 1200.0; t_s += 0.1) {
    GnssFixType fix = GnssFixType::kNone;
    const GnssNoise& noise = model.noise_at(t_s, &fix);
    EXPECT_EQ(noise.horizontal_std_m, default_gnss_noise(fix).horizontal_std_m);
    float_to_fixed += previous == GnssFixType::kRtkFloat && fix == GnssFixType::kRtkFixed;
    previous = fix;
  }
  EXPECT_EQ(float_to_fixed, 5);
}

}  // namespace
}  // namespace navfuse::sim
