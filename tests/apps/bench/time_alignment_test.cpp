// Time alignment: interpolation between neighbours, shorter-arc angles, and no data invented
// outside a track or across a gap.
#include "apps/bench/time_alignment.hpp"

#include <gtest/gtest.h>

#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

constexpr double kDeg = rot::kDegToRad;
constexpr std::int64_t kMs = 1'000'000;

TrackSample sample(std::int64_t t_ns, double yaw_deg) {
  TrackSample s;
  s.time_ns = t_ns;
  s.mode = NavMode::kNavigation;
  s.valid = NavSolution::kValidPosition | NavSolution::kValidAttitude | NavSolution::kValidHeading;
  s.lat_rad = 0.5;
  s.lon_rad = 1.0;
  s.rpy_rad = {0.0, 0.0, yaw_deg * kDeg};
  return s;
}

SolutionTrack track_of(const std::vector<TrackSample>& v) {
  SolutionTrack track;
  for (const auto& s : v) track.append(s);
  return track;
}

TEST(TimeAlignment, InterpolatesLinearlyBetweenNeighbours) {
  std::vector<TrackSample> v = {sample(0, 10.0), sample(100 * kMs, 20.0)};
  v[1].height_m = 4.0;
  v[1].vel_ned_mps = {2.0, -4.0, 1.0};
  v[1].lat_rad = 0.5 + 1e-6;
  v[1].pos_std_ned_m = {1.0, 1.0, 2.0};
  const SolutionTrack samples = track_of(v);
  TrackInterpolator track(samples.with_any(), 200 * kMs);
  const auto s = track.at(25 * kMs);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->time_ns, 25 * kMs);
  EXPECT_DOUBLE_EQ(s->height_m, 1.0);
  EXPECT_DOUBLE_EQ(s->lat_rad, 0.5 + 0.25e-6);
  EXPECT_NEAR(s->rpy_rad.z(), 12.5 * kDeg, 1e-12);
  EXPECT_TRUE(s->vel_ned_mps.isApprox(Eigen::Vector3d(0.5, -1.0, 0.25)));
  EXPECT_TRUE(s->pos_std_ned_m.isApprox(Eigen::Vector3d(0.25, 0.25, 0.5)));
}

TEST(TimeAlignment, HeadingTakesTheShorterArcThroughPlusMinus180) {
  // 179 deg -> -179 deg is 2 deg of turn through 180, so the midpoint is +-180, not 0.
  std::vector<TrackSample> v = {sample(0, 179.0), sample(10 * kMs, -179.0)};
  const SolutionTrack samples = track_of(v);
  TrackInterpolator track(samples.with_any(), 100 * kMs);
  const auto mid = track.at(5 * kMs);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(std::abs(mid->rpy_rad.z()), 180.0 * kDeg, 1e-9);
  const auto quarter = track.at(kMs * 5 / 2);
  ASSERT_TRUE(quarter);
  EXPECT_NEAR(quarter->rpy_rad.z(), 179.5 * kDeg, 1e-9);
  const auto three_quarters = track.at(kMs * 15 / 2);
  ASSERT_TRUE(three_quarters);
  EXPECT_NEAR(three_quarters->rpy_rad.z(), -179.5 * kDeg, 1e-9);
}

TEST(TimeAlignment, LongitudeTakesTheShorterArcAcrossTheAntimeridian) {
  std::vector<TrackSample> v = {sample(0, 0.0), sample(10 * kMs, 0.0)};
  v[0].lon_rad = rot::kPi - 1e-6;
  v[1].lon_rad = -rot::kPi + 1e-6;
  const SolutionTrack samples = track_of(v);
  TrackInterpolator track(samples.with_any(), 100 * kMs);
  const auto mid = track.at(5 * kMs);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(std::abs(mid->lon_rad), rot::kPi, 1e-12);
}

TEST(TimeAlignment, ExactTimesReturnTheSampleItself) {
  std::vector<TrackSample> v = {sample(0, 1.0), sample(10 * kMs, 2.0), sample(20 * kMs, 3.0)};
  v[1].mode = NavMode::kDeadReckoning;
  const SolutionTrack samples = track_of(v);
  TrackInterpolator track(samples.with_any(), 15 * kMs);
  TrackInterpolator::Miss miss = TrackInterpolator::Miss::kGap;
  const auto s = track.at(10 * kMs, &miss);
  ASSERT_TRUE(s);
  EXPECT_EQ(miss, TrackInterpolator::Miss::kNone);
  EXPECT_EQ(s->mode, NavMode::kDeadReckoning);
  EXPECT_DOUBLE_EQ(s->rpy_rad.z(), 2.0 * kDeg);
  // The last sample is inside the track, not outside it.
  EXPECT_TRUE(track.at(20 * kMs));
}

TEST(TimeAlignment, NeverExtrapolatesBeforeOrAfterTheTrack) {
  std::vector<TrackSample> v = {sample(100 * kMs, 1.0), sample(110 * kMs, 2.0)};
  const SolutionTrack samples = track_of(v);
  TrackInterpolator track(samples.with_any(), 1000 * kMs);
  TrackInterpolator::Miss miss = TrackInterpolator::Miss::kNone;
  EXPECT_FALSE(track.at(99 * kMs, &miss));
  EXPECT_EQ(miss, TrackInterpolator::Miss::kOutside);
  miss = TrackInterpolator::Miss::kNone;
  EXPECT_FALSE(track.at(111 * kMs, &miss));
  EXPECT_EQ(miss, TrackInterpolator::Miss::kOutside);
  const SolutionTrack none;
  TrackInterpolator empty(none.with_any(), 1000 * kMs);
  EXPECT_FALSE(empty.at(0, &miss));
}

TEST(TimeAlignment, NeverBridgesAGap) {
  // 10 Hz with one dropout of 1 s: the default limit is 3 median intervals = 300 ms.
  std::vector<TrackSample> v;
  for (int i = 0; i <= 10; ++i) v.push_back(sample(i * 100 * kMs, 0.0));
  for (int i = 20; i <= 30; ++i) v.push_back(sample(i * 100 * kMs, 0.0));
  const SolutionTrack dropout = track_of(v);
  const TrackView samples = dropout.with_any();
  EXPECT_EQ(median_interval_ns(samples), 100 * kMs);
  EXPECT_EQ(default_max_gap_ns(samples), 300 * kMs);
  TrackInterpolator track(samples, default_max_gap_ns(samples));
  TrackInterpolator::Miss miss = TrackInterpolator::Miss::kNone;
  EXPECT_FALSE(track.at(1500 * kMs, &miss));
  EXPECT_EQ(miss, TrackInterpolator::Miss::kGap);
  // The samples bounding the gap are still there.
  EXPECT_TRUE(track.at(1000 * kMs));
  EXPECT_TRUE(track.at(2000 * kMs));
  // One lost message (200 ms between neighbours) is bridged.
  v.erase(v.begin() + 5);
  const SolutionTrack one_lost = track_of(v);
  const TrackView fewer = one_lost.with_any();
  TrackInterpolator tolerant(fewer, default_max_gap_ns(fewer));
  EXPECT_TRUE(tolerant.at(500 * kMs));
  // Asked out of order, the interpolator starts its pass again and still answers.
  EXPECT_TRUE(track.at(1000 * kMs));
  EXPECT_FALSE(track.at(1500 * kMs, &miss));
  EXPECT_EQ(miss, TrackInterpolator::Miss::kGap);
}

TEST(SolutionTrack, MergesPartialSolutionsOfOneEpochAndDropsReorderedOnes) {
  SolutionTrack track;
  TrackSample pos = sample(10 * kMs, 0.0);
  pos.valid = NavSolution::kValidPosition;
  pos.height_m = 12.0;
  TrackSample att = sample(10 * kMs, 45.0);
  att.valid = NavSolution::kValidAttitude | NavSolution::kValidHeading;
  att.height_m = 99.0;  // not carried: must not overwrite the position's height
  EXPECT_TRUE(track.append(pos));
  EXPECT_TRUE(track.append(att));
  ASSERT_EQ(track.size(), 1u);
  SolutionTrack::Reader reader = track.reader();
  TrackSample s;
  ASSERT_TRUE(reader.next(s));
  EXPECT_TRUE(has(s, Quantity::kPosition));
  EXPECT_TRUE(has(s, Quantity::kHeading));
  EXPECT_FALSE(has(s, Quantity::kVelocity));
  EXPECT_DOUBLE_EQ(s.height_m, 12.0);
  EXPECT_DOUBLE_EQ(s.rpy_rad.z(), 45.0 * kDeg);
  EXPECT_FALSE(track.append(sample(5 * kMs, 0.0)));
  EXPECT_EQ(track.dropped(), 1u);
  EXPECT_EQ(track.with(Quantity::kVelocity, false).size(), 0u);
  EXPECT_EQ(track.with_any().size(), 1u);
  EXPECT_EQ(track.with_any().first_ns(), 10 * kMs);
}

}  // namespace
}  // namespace navfuse::apps::bench
