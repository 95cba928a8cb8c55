// Issue 16's smoother goals against simulated truth (apps/sim), label "scenario":
// - the reference drive's 120 s GNSS outage at 20 m/s without wheel speed, RTK-fixed GNSS: the
//   smoothed position error over the outage is at most a tenth of the forward filter's (with
//   standalone GNSS, a quarter: the noise of the fixes around the outage sets the floor);
// - Monte-Carlo NEES of the smoothed position, velocity and attitude inside the 95 % bounds;
// - never much worse than the filter it smooths: on the calibration drive with the IMU mounting
//   and clock offset left wrong (the forward filter re-inflates its covariance to follow the
//   fixes), the smoothed horizontal error is no larger than the forward one.
#include <gtest/gtest.h>

#include <cstdio>

#include "apps/sim/scenarios.hpp"
#include "tests/filter/scenario_harness.hpp"
#include "tests/filter/smoother_harness.hpp"

namespace navfuse::filter {
namespace {

struct OutageErrors {
  double forward_max = 0.0, smoothed_max = 0.0;
  test::Rms forward_rms, smoothed_rms;
};

// The reference drive's 120 s outage at 20 m/s, without wheel speed, under `gnss_scenario`'s GNSS.
OutageErrors outage_errors(const char* gnss_scenario) {
  sim::Scenario s = sim::make_scenario(gnss_scenario);
  s.gnss.outages = {{sim::kDriveOutageStart_s, sim::kDriveOutageStart_s + sim::kDriveOutageDuration_s}};
  s.wheel.vehicle_speed = false;
  const std::int64_t start = s.start_time_ns + static_cast<std::int64_t>(sim::kDriveOutageStart_s * 1e9);
  const std::int64_t end = start + static_cast<std::int64_t>(sim::kDriveOutageDuration_s * 1e9);
  OutageErrors r;
  const test::SmoothedRun run = test::run_smoothed(
      s, test::options_for(s), [&](const SmoothedSample&, const sim::TruthSample& t, const test::TruthError& e) {
        if (t.time_ns < start || t.time_ns > end) return;
        r.smoothed_max = std::max(r.smoothed_max, e.pos.head<2>().norm());
        r.smoothed_rms.add(e.pos.head<2>().norm());
      });
  for (const test::ForwardEpoch& f : run.forward) {
    if (f.truth.time_ns < start || f.truth.time_ns > end) continue;
    r.forward_max = std::max(r.forward_max, f.error.pos.head<2>().norm());
    r.forward_rms.add(f.error.pos.head<2>().norm());
  }
  std::printf("%s, 120 s outage, horizontal error: forward max %.2f m RMS %.2f m; smoothed max %.3f m RMS %.3f m "
              "(%zu samples; record %.1f MB, %llu intervals)\n",
              gnss_scenario, r.forward_max, r.forward_rms.value(), r.smoothed_max, r.smoothed_rms.value(),
              r.smoothed_rms.n, static_cast<double>(run.record_bytes) / 1e6,
              static_cast<unsigned long long>(run.smoother.intervals));
  EXPECT_TRUE(run.smoother.error.empty()) << run.smoother.error;
  EXPECT_GT(r.smoothed_rms.n, 20000u);
  return r;
}

TEST(SmootherScenario, RtkOutageErrorATenthOfForward) {
  // RTK-fixed fixes (2 cm, 10 Hz) on both sides: the smoother bridges the outage between them.
  const OutageErrors r = outage_errors("rtk_drive");
  EXPECT_LE(r.smoothed_max, 0.1 * r.forward_max);
  EXPECT_LE(r.smoothed_rms.value(), 0.1 * r.forward_rms.value());
}

TEST(SmootherScenario, StandaloneOutageBridged) {
  // Standalone fixes (1.5 m, 5 Hz): the ends of the bridge are only as good as ~1 s of averaged
  // standalone fixes (~0.5 m), which the forward filter's 5 m drift does not dwarf ten times.
  const OutageErrors r = outage_errors("drive_outage");
  EXPECT_LE(r.smoothed_max, 0.25 * r.forward_max);
  EXPECT_LE(r.smoothed_rms.value(), 0.25 * r.forward_rms.value());
}

TEST(SmootherScenario, NoWorseThanForwardOnAWrongInstallation) {
  // calibration_drive (RTK 10 Hz, wheel speed) with the lever arm right but the IMU mounting
  // pitch/yaw (1.5, -2.0 deg) and its 50 ms clock offset left uncorrected, as before a
  // calibration. The forward filter follows the fixes by re-inflating its covariance (innovation
  // adaptation); the smoother must use the prior the filter used, not the narrower one before the
  // inflation. Before that was recorded: forward 0.040 m RMS, smoothed 2.96 m (max 14 m).
  sim::Scenario s = sim::make_scenario("calibration_drive");
  FilterOptions o = test::options_for(s);
  o.mounting_rpy_rad = Eigen::Vector3d(s.imu.mounting_rpy_deg.x(), 0.0, 0.0) * rot::kDegToRad;
  test::Rms forward, smoothed;
  double forward_max = 0.0, smoothed_max = 0.0;
  const test::SmoothedRun run = test::run_smoothed(s, o, [&](const SmoothedSample& x, const sim::TruthSample&,
                                                           const test::TruthError& e) {
    if (x.forward.mode != NavMode::kNavigation && x.forward.mode != NavMode::kDeadReckoning) return;
    smoothed.add(e.pos.head<2>().norm());
    smoothed_max = std::max(smoothed_max, e.pos.head<2>().norm());
  });
  for (const test::ForwardEpoch& f : run.forward) {
    if (!f.navigating) continue;
    forward.add(f.error.pos.head<2>().norm());
    forward_max = std::max(forward_max, f.error.pos.head<2>().norm());
  }
  std::printf("calibration_drive, mounting and clock offset wrong: horizontal forward RMS %.3f m (max %.3f), "
              "smoothed RMS %.3f m (max %.3f); %llu covariance re-inflations, %llu segments\n",
              forward.value(), forward_max, smoothed.value(), smoothed_max,
              static_cast<unsigned long long>(run.stats.covariance_inflations),
              static_cast<unsigned long long>(run.smoother.segments));
  EXPECT_TRUE(run.smoother.error.empty()) << run.smoother.error;
  EXPECT_GT(run.stats.covariance_inflations, 0u);  // the case this test is about
  EXPECT_GT(smoothed.n, 30000u);
  EXPECT_LE(smoothed.value(), forward.value());
}

TEST(SmootherScenario, MonteCarloNeesConsistency) {
  // 25 runs of the short drive (standalone GNSS, wheel speed, a 30 s outage), different seeds, as
  // the forward filter's NEES test (scenario_test.cpp): the average NEES over runs and 1 Hz
  // epochs from alignment + 30 s must lie in the two-sided 95 % bounds of chi2(k N) / N, N = 25:
  // k = 3 (position, velocity, attitude): [52.94, 100.84] / 25; k = 1 (one attitude axis):
  // [13.12, 40.65] / 25. Until the increments' convention was carried (ImuIncrements) the north
  // tilt had a systematic +6.6e-5 rad error, the simulator's compensated increments given the
  // rotation term again in every turn: north-tilt NEES 1.77, attitude 4.47, both above.
  constexpr int kRuns = 25;
  const double lo3 = 52.94 / kRuns, hi3 = 100.84 / kRuns, lo1 = 13.12 / kRuns, hi1 = 40.65 / kRuns;
  double pos = 0.0, vel = 0.0, att = 0.0;
  Eigen::Vector3d att_axis = Eigen::Vector3d::Zero(), att_mean = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (int r = 0; r < kRuns; ++r) {
    sim::Scenario s = sim::make_scenario("drive_short");
    s.seed = 1000 + static_cast<std::uint64_t>(r);
    std::int64_t aligned_at = INT64_MIN, next_sample = INT64_MIN;
    test::run_smoothed(s, test::options_for(s), [&](const SmoothedSample& x, const sim::TruthSample& t,
                                                   const test::TruthError& e) {
      if (x.forward.mode != NavMode::kNavigation && x.forward.mode != NavMode::kDeadReckoning) return;
      if (aligned_at == INT64_MIN) aligned_at = t.time_ns;
      if (t.time_ns < aligned_at + 30'000'000'000 || t.time_ns < next_sample) return;
      next_sample = t.time_ns + 1'000'000'000;
      pos += test::nees(e.pos, x.p.block<3, 3>(sx::kPos, sx::kPos));
      vel += test::nees(e.vel, x.p.block<3, 3>(sx::kVel, sx::kVel));
      att += test::nees(e.att, x.p.block<3, 3>(sx::kAtt, sx::kAtt));
      for (int i = 0; i < 3; ++i) att_axis(i) += e.att(i) * e.att(i) / x.p(sx::kAtt + i, sx::kAtt + i);
      att_mean += e.att;
      ++n;
    });
  }
  const double count = static_cast<double>(n);
  pos /= count;
  vel /= count;
  att /= count;
  att_axis /= count;
  att_mean /= count;
  std::printf("smoothed NEES over %d runs (%zu epochs): position %.2f, velocity %.2f (bounds %.2f .. %.2f); "
              "attitude %.2f, per axis N %.2f E %.2f D %.2f (bounds %.2f .. %.2f); mean attitude error "
              "%.1e %.1e %.1e rad\n",
              kRuns, n, pos, vel, lo3, hi3, att, att_axis(0), att_axis(1), att_axis(2), lo1, hi1, att_mean(0),
              att_mean(1), att_mean(2));
  EXPECT_GT(n, 2000u);
  EXPECT_GE(pos, lo3);
  EXPECT_LE(pos, hi3);
  EXPECT_GE(vel, lo3);
  EXPECT_LE(vel, hi3);
  EXPECT_GE(att, lo3);
  EXPECT_LE(att, hi3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_GE(att_axis(i), lo1) << i;
    EXPECT_LE(att_axis(i), hi1) << i;
  }
}

}  // namespace
}  // namespace navfuse::filter
