// The fusion runner on hand-made streams: what it counts, what it gates and when it says a pose
// is due, each checked against a count done by hand or recomputed independently in the test.
#include <vector>

#include <gtest/gtest.h>

#include "apps/fusion/fusion_runner.hpp"
#include "core/geodesy/wgs84.hpp"

namespace navfuse::apps {
namespace {

constexpr std::int64_t kStartNs = 1'400'000'000'000'000'000LL;  // a GPS time in 2024
constexpr std::int64_t kImuPeriodNs = 10'000'000;                // 100 Hz

ImuSample still_imu(std::int64_t t_ns, std::uint16_t stream = 0) {
  ImuSample s;
  s.header = {t_ns, TimeSource::kGps, stream, ImuSample::kValidGyro | ImuSample::kValidAccel};
  s.frame = SensorFrame::kVehicle;
  s.accel = Eigen::Vector3d(0.0, 0.0, -9.80);  // at rest, FRD: specific force points up
  s.dt_s = 0.01;
  return s;
}

GnssPosition fix_at(std::int64_t t_ns, TimeSource source, std::uint16_t stream, std::uint8_t sats) {
  GnssPosition p;
  p.header = {t_ns, source, stream,
              GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance};
  p.lat_rad = 0.8;
  p.lon_rad = 0.2;
  p.height_m = 100.0;
  p.fix = GnssFixType::kFix3D;
  p.num_sats = sats;
  return p;
}

FusionRunner::Options options(double rate_hz, FusionRunner::Solutions solutions = FusionRunner::Solutions::kEvery,
                             std::optional<GnssOutagePlan> outages = std::nullopt) {
  return {.output_rate_hz = rate_hz, .solutions = solutions, .gnss_outages = outages};
}

struct Recorder final : FusionObserver {
  std::vector<OutputEpoch> epochs;
  std::size_t offered = 0, fused = 0;
  void on_offered(const Measurement&) override { ++offered; }
  void on_fused(const Measurement&) override { ++fused; }
  void on_epoch(const OutputEpoch& e, const filter::Engine&) override { epochs.push_back(e); }
};

std::uint64_t rejected(const Summary& s, MeasurementKind kind, const std::string& reason) {
  const auto& r = s.kinds[static_cast<std::size_t>(kind)].rejected;
  const auto it = r.find(reason);
  return it == r.end() ? 0 : it->second;
}

TEST(FusionRunner, GatesOtherClocksAndSecondImuAndCountsEveryOffer) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(0.0), rec);
  for (int i = 0; i < 50; ++i) {
    const std::int64_t t = kStartNs + i * kImuPeriodNs;
    runner.offer(still_imu(t));
    if (i % 10 == 5) {
      runner.offer(fix_at(t, TimeSource::kDeviceMonotonic, 1, 9));  // another device's clock
      runner.offer(still_imu(t + 1, 2));                               // a second IMU stream
    }
  }
  Summary s;
  runner.fill_summary(s, 1.0);
  // By hand: 50 IMU samples from stream 0, 5 fixes and 5 IMU samples from other streams.
  EXPECT_EQ(rec.offered, 60u);
  EXPECT_EQ(rec.fused, 50u);
  EXPECT_EQ(runner.gated_total(), 10u);
  EXPECT_EQ(s.kinds[static_cast<std::size_t>(MeasurementKind::kImu)].decoded, 55u);
  EXPECT_EQ(s.kinds[static_cast<std::size_t>(MeasurementKind::kGnssPosition)].decoded, 5u);
  EXPECT_EQ(rejected(s, MeasurementKind::kGnssPosition, "time_base"), 5u);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "second_imu"), 5u);
  EXPECT_EQ(runner.imu_samples(), 50u);
  ASSERT_TRUE(runner.first_imu());
  EXPECT_EQ(runner.first_imu()->time_ns, kStartNs);
  EXPECT_EQ(runner.last_imu_ns(), kStartNs + 49 * kImuPeriodNs);
  // Rate 0: a pose at every epoch; the very first sample only starts the increment, so the
  // filter advances 49 times... or 50 when rates need no previous sample: ask the engine.
  EXPECT_EQ(rec.epochs.size(), runner.engine().imu_epoch());
  for (const OutputEpoch& e : rec.epochs) EXPECT_TRUE(e.pose_due);
  EXPECT_EQ(runner.poses(), rec.epochs.size());
  EXPECT_DOUBLE_EQ(s.run->imu_samples_per_s, 50.0);
}

TEST(FusionRunner, KindsTheFilterDoesNotFuseAreIgnoredWhateverTheirClock) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(0.0), rec);
  runner.offer(still_imu(kStartNs));
  Pressure baro;  // not fused unless configured (FilterOptions::fuses), on another device's clock
  baro.header = {kStartNs, TimeSource::kDeviceMonotonic, 1, Pressure::kValidPressure};
  runner.offer(baro);
  Summary s;
  runner.fill_summary(s, 1.0);
  EXPECT_EQ(rejected(s, MeasurementKind::kPressure, "time_base"), 0u) << "the gate and the filter share one list";
  EXPECT_EQ(rejected(s, MeasurementKind::kPressure, "ignored"), 1u);

  // Switched on, the same pressure is one the filter would fuse at a wrong time: gated.
  filter::FilterOptions with_baro;
  with_baro.baro.enabled = true;
  Recorder rec2;
  FusionRunner fusing(with_baro, options(0.0), rec2);
  fusing.offer(still_imu(kStartNs));
  fusing.offer(baro);
  Summary s2;
  fusing.fill_summary(s2, 1.0);
  EXPECT_EQ(rejected(s2, MeasurementKind::kPressure, "time_base"), 1u);
}

TEST(FusionRunner, RejectedImuSampleIsNoEpoch) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(0.0), rec);
  runner.offer(still_imu(kStartNs));
  runner.offer(still_imu(kStartNs + kImuPeriodNs));
  const std::size_t before = rec.epochs.size();
  runner.offer(still_imu(kStartNs + kImuPeriodNs / 2));  // time goes backwards: the filter rejects it
  EXPECT_EQ(rec.epochs.size(), before);
  EXPECT_EQ(runner.imu_samples(), 3u);  // given to the filter, all three
  runner.offer(still_imu(kStartNs + 2 * kImuPeriodNs));
  EXPECT_EQ(rec.epochs.size(), before + 1);
}

TEST(FusionRunner, PosesAtTheOutputRateOnTheMeasurementTimeAxis) {
  Recorder rec;
  // 100 Hz IMU, 20 Hz poses: slots of 50 ms, the first epoch at or after each slot boundary.
  FusionRunner runner(filter::FilterOptions{}, options(20.0, FusionRunner::Solutions::kPoses), rec);
  for (int i = 0; i < 200; ++i) runner.offer(still_imu(kStartNs + i * kImuPeriodNs));
  std::int64_t last_slot = -1;
  std::size_t due = 0;
  for (const OutputEpoch& e : rec.epochs) {
    // Recomputed independently of OutputRate: a new 50 ms slot of GPS time starts a pose.
    const std::int64_t slot = e.solution.header.time_ns / 50'000'000;
    if (e.pose_due) {
      ++due;
      EXPECT_GT(slot, last_slot);
      // After the first (the first epoch of all), each pose is the sample on a slot boundary:
      // kStartNs and the 10 ms samples lie on the 50 ms grid.
      if (last_slot >= 0) {
        EXPECT_EQ(e.solution.header.time_ns % 50'000'000, 0);
      }
      last_slot = slot;
    }
  }
  EXPECT_EQ(due, runner.poses());
  EXPECT_NEAR(static_cast<double>(due), rec.epochs.size() / 5.0, 1.0);
}

TEST(FusionRunner, GnssUpdatedOnlyAtThePoseAfterAFusedFix) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(10.0), rec);
  for (int i = 0; i < 3000; ++i) {  // 30 s at rest with a 1 Hz fix on GPS time
    const std::int64_t t = kStartNs + i * kImuPeriodNs;
    runner.offer(still_imu(t));
    if (i % 100 == 3) runner.offer(fix_at(t, TimeSource::kGps, 1, static_cast<std::uint8_t>(5 + i / 100 % 7)));
  }
  ASSERT_GT(runner.engine().stats().of(MeasurementKind::kGnssPosition).used, 0u);
  std::uint64_t at_last_pose = 0;
  std::size_t updates = 0;
  for (const OutputEpoch& e : rec.epochs) {
    if (!e.pose_due) {
      EXPECT_FALSE(e.gnss_updated);
      continue;
    }
    EXPECT_EQ(e.gnss_updated, e.gnss_fused_total != at_last_pose);
    updates += e.gnss_updated;
    at_last_pose = e.gnss_fused_total;
  }
  EXPECT_GT(updates, 0u);
  EXPECT_EQ(rec.epochs.back().num_sats, 5 + 2999 / 100 % 7);
}

TEST(FusionRunner, OneWildImuTimestampIsRejectedAndTheStreamGoesOn) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(0.0), rec);
  constexpr std::int64_t kYearNs = 365LL * 86'400 * 1'000'000'000;
  for (int i = 0; i < 300; ++i) {
    const std::int64_t t = kStartNs + i * kImuPeriodNs;
    runner.offer(still_imu(i == 150 ? t + kYearNs : t));  // one checksum-valid sample a year ahead
  }
  runner.finish();
  Summary s;
  runner.fill_summary(s, 1.0);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "time_jump"), 1u);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "time_backwards"), 0u);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "time_gap"), 0u);
  EXPECT_EQ(runner.imu_samples(), 299u);
  EXPECT_EQ(rec.epochs.back().solution.header.time_ns, kStartNs + 299 * kImuPeriodNs);
}

TEST(FusionRunner, ARealGapIsFusedAfterTheNextSampleConfirmsIt) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(0.0), rec);
  constexpr std::int64_t kGapNs = 5'000'000'000;  // longer than max_imu_gap_s (1 s)
  for (int i = 0; i < 200; ++i) {
    const std::int64_t t = kStartNs + i * kImuPeriodNs + (i >= 100 ? kGapNs : 0);
    runner.offer(still_imu(t));
    if (i == 100) {
      EXPECT_EQ(runner.imu_samples(), 100u) << "the first sample after the gap waits";
    }
    if (i == 101) {
      EXPECT_EQ(runner.imu_samples(), 102u) << "the next one confirms it: both go in";
    }
  }
  runner.finish();
  Summary s;
  runner.fill_summary(s, 1.0);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "time_jump"), 0u);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "time_gap"), 1u) << "the filter restarts across it, as before";
  EXPECT_EQ(runner.imu_samples(), 200u);
}

TEST(FusionRunner, AWildSampleAtTheEndIsRejectedByFinish) {
  Recorder rec;
  FusionRunner runner(filter::FilterOptions{}, options(0.0), rec);
  for (int i = 0; i < 10; ++i) runner.offer(still_imu(kStartNs + i * kImuPeriodNs));
  runner.offer(still_imu(kStartNs + 86'400'000'000'000LL));
  runner.finish();
  Summary s;
  runner.fill_summary(s, 1.0);
  EXPECT_EQ(rejected(s, MeasurementKind::kImu, "time_jump"), 1u);
  EXPECT_EQ(runner.imu_samples(), 10u);
}

}  // namespace
}  // namespace navfuse::apps

namespace navfuse::apps {
namespace {

TEST(GnssOutagePlan, ParsesAndRefusesWithTheOptionNamed) {
  std::string error;
  const auto p = GnssOutagePlan::parse("30:10:5", error);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->period_s, 30.0);
  EXPECT_EQ(p->duration_s, 10.0);
  EXPECT_EQ(p->start_s, 5.0);
  for (const char* bad : {"30", "30:40", "30:0", "x:1", "30:10:-1", "30:10:1:2", "nan:1"}) {
    EXPECT_FALSE(GnssOutagePlan::parse(bad, error)) << bad;
    EXPECT_NE(error.find("--gnss-outage"), std::string::npos);
  }
}

TEST(GnssOutagePlan, WindowsByHand) {
  std::string error;
  const auto p = *GnssOutagePlan::parse("30:10:5", error);
  const std::int64_t first = 1'000'000'000'000LL;
  const auto at = [&](double s) { return first + static_cast<std::int64_t>(s * 1e9); };
  EXPECT_FALSE(p.in_outage(at(4.999), first));
  EXPECT_TRUE(p.in_outage(at(5.0), first));
  EXPECT_TRUE(p.in_outage(at(14.999), first));
  EXPECT_FALSE(p.in_outage(at(15.0), first));
  EXPECT_TRUE(p.in_outage(at(35.0), first));   // the second window: 35-45 s
  EXPECT_FALSE(p.in_outage(at(34.9), first));
  EXPECT_EQ(p.outage_end_ns(at(40.0), first), at(45.0));
}

TEST(FusionRunner, GnssInsideAnOutageWindowIsWithheldAndCounted) {
  Recorder rec;
  std::string error;
  FusionRunner runner(filter::FilterOptions{},
                      options(10.0, FusionRunner::Solutions::kEvery, GnssOutagePlan::parse("10:4", error)), rec);
  for (int i = 0; i < 3000; ++i) {  // 30 s, 1 Hz fixes at 0.03 s past each second
    const std::int64_t t = kStartNs + i * kImuPeriodNs;
    runner.offer(still_imu(t));
    if (i % 100 == 3) runner.offer(fix_at(t, TimeSource::kGps, 1, 8));
  }
  Summary s;
  runner.fill_summary(s, 1.0);
  // Fixes at 0.03, 1.03, ... 29.03 s; windows [0,4), [10,14), [20,24): 4 fixes in each.
  EXPECT_EQ(rejected(s, MeasurementKind::kGnssPosition, "outage"), 12u);
}

}  // namespace
}  // namespace navfuse::apps
