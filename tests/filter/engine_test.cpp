// Engine behaviour on closed-form streams (no simulator): levelling, modes, bad-input rejection,
// ignored kinds, late / future / too-late measurements, reset and dead reckoning.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter {
namespace {

constexpr double kLat = 45.0 * rot::kDegToRad;
const Eigen::Vector3d kRpy = Eigen::Vector3d(2.0, -1.0, 30.0) * rot::kDegToRad;

test::LineTrajectory static_trajectory() {
  test::LineTrajectory t({kLat, 0.1, 200.0}, Eigen::Vector3d::Zero(), kRpy, 200.0);
  t.gyro_bias_rps = Eigen::Vector3d(5.0, -8.0, 10.0) * rot::kDegToRad / 3600.0;
  t.accel_bias_mps2 = Eigen::Vector3d(0.02, -0.03, 0.01);
  return t;
}

// A timed stream: IMU at 200 Hz, 5 Hz GNSS position (1 m noise) and velocity when `gnss`.
struct Stream {
  std::vector<Measurement> items;
  test::LineTruth final_truth;
};

Stream make_static_stream(double seconds, bool gnss, std::uint64_t seed = 3) {
  Stream s;
  test::LineTrajectory traj = static_trajectory();
  std::mt19937_64 rng(seed);
  const int n = static_cast<int>(seconds * 200.0);
  for (int k = 1; k <= n; ++k) {
    s.items.emplace_back(traj.next());
    if (gnss && k % 40 == 0) {
      s.items.emplace_back(test::make_fix(traj.truth(), Eigen::Vector3d::Zero(), 1.0, &rng));
      s.items.emplace_back(test::make_velocity(traj.truth(), 0.05, &rng));
    }
  }
  s.final_truth = traj.truth();
  return s;
}

FilterOptions options_with_heading() {
  FilterOptions o;
  o.initial_heading_rad = kRpy.z();
  return o;
}

TEST(Engine, LevelsWhileStaticWithinAccelBiasLimit) {
  Engine e{FilterOptions{}};
  const Stream s = make_static_stream(30.0, false);
  for (const auto& m : s.items) e.process(m);
  EXPECT_EQ(e.solution().mode, NavMode::kVerticalGyro);
  EXPECT_EQ(e.imu_epoch(), 30u * 200u);  // increments: every sample propagates
  // The tilt error of a stationary levelling is the accelerometer bias over g (unobservable);
  // the goal allows that plus 0.02 deg.
  const double bias_limit = 0.03 / 9.8 + 0.02 * rot::kDegToRad;
  const Eigen::Vector3d rpy = e.solution().rpy_rad;
  EXPECT_LT(std::abs(rpy.x() - kRpy.x()), bias_limit);
  EXPECT_LT(std::abs(rpy.y() - kRpy.y()), bias_limit);
  EXPECT_TRUE((e.solution().header.valid & NavSolution::kValidAttitude) != 0);
  EXPECT_TRUE((e.solution().header.valid & NavSolution::kValidHeading) == 0);
  EXPECT_TRUE((e.solution().status_flags & NavSolution::kStatusStationary) != 0);
}

TEST(Engine, ReachesNavigationWithConfiguredHeadingAndGnss) {
  Engine e{options_with_heading()};
  const Stream s = make_static_stream(20.0, true);
  for (const auto& m : s.items) e.process(m);
  EXPECT_EQ(e.solution().mode, NavMode::kNavigation);
  EXPECT_TRUE(e.solution_valid());
  const auto modes = e.modes_reached();
  EXPECT_NE(std::find(modes.begin(), modes.end(), NavMode::kInitializing), modes.end());
  EXPECT_NE(std::find(modes.begin(), modes.end(), NavMode::kNavigation), modes.end());
  const geo::Llh est{e.solution().lat_rad, e.solution().lon_rad, e.solution().height_m};
  EXPECT_LT(geo::ned_offset_m(s.final_truth.llh, est).head<2>().norm(), 1.0);
  EXPECT_LT(e.solution().vel_ned_mps.norm(), 0.05);
  EXPECT_EQ(e.solution().gnss_fix, GnssFixType::kFix3D);
  EXPECT_GT(e.stats().of(MeasurementKind::kGnssPosition).used, 90u);
  EXPECT_GT(e.stats().zupts, 50u);
}

TEST(Engine, BadInputsAreRejectedCountedAndLeaveStateUnchanged) {
  Engine e{options_with_heading()};
  Stream s = make_static_stream(10.0, true);
  for (const auto& m : s.items) e.process(m);
  const NavSolution before = e.solution();
  const std::uint64_t epoch = e.imu_epoch();

  ImuSample nan_imu = std::get<ImuSample>(s.items.front());
  nan_imu.header.time_ns = before.header.time_ns + 5'000'000;
  nan_imu.gyro.x() = std::numeric_limits<double>::quiet_NaN();
  e.process(nan_imu);

  ImuSample old_imu = std::get<ImuSample>(s.items.front());  // time reversal
  e.process(old_imu);

  GnssPosition bad_std = test::make_fix(s.final_truth, Eigen::Vector3d::Zero(), 1.0, nullptr);
  bad_std.cov_ned_m2(1, 1) = -1.0;
  e.process(bad_std);

  GnssVelocity inf_vel = test::make_velocity(s.final_truth, 0.05, nullptr);
  inf_vel.vel_ned_mps.z() = std::numeric_limits<double>::infinity();
  e.process(inf_vel);

  ExternalHeading zero_std;
  zero_std.header.time_ns = before.header.time_ns;
  zero_std.header.valid = ExternalHeading::kValidHeading;
  zero_std.std_rad = 0.0;
  e.process(zero_std);

  const FilterStats& st = e.stats();
  EXPECT_EQ(st.of(MeasurementKind::kImu).rejected_for(RejectReason::kNan), 1u);
  EXPECT_EQ(st.of(MeasurementKind::kImu).rejected_for(RejectReason::kTimeBackwards), 1u);
  EXPECT_EQ(st.of(MeasurementKind::kGnssPosition).rejected_for(RejectReason::kNegativeStd), 1u);
  EXPECT_EQ(st.of(MeasurementKind::kGnssVelocity).rejected_for(RejectReason::kNan), 1u);
  EXPECT_EQ(st.of(MeasurementKind::kExternalHeading).rejected_for(RejectReason::kNegativeStd), 1u);
  EXPECT_EQ(e.imu_epoch(), epoch);
  const NavSolution& after = e.solution();
  EXPECT_EQ(after.lat_rad, before.lat_rad);
  EXPECT_EQ(after.lon_rad, before.lon_rad);
  EXPECT_EQ(after.height_m, before.height_m);
  EXPECT_EQ(after.vel_ned_mps, before.vel_ned_mps);
  EXPECT_EQ(after.q_nb.coeffs(), before.q_nb.coeffs());
  EXPECT_EQ(after.pos_std_ned_m, before.pos_std_ned_m);
}

TEST(Engine, UnusableKindsAreCountedAsIgnored) {
  Engine e{FilterOptions{}};
  e.process(Magnetometer{});
  e.process(Pressure{});
  e.process(NavSolution{});
  // Wheel ticks are fused (issue 17): one with no valid counter is rejected, not ignored.
  e.process(WheelTicks{});
  EXPECT_EQ(e.stats().of(MeasurementKind::kMagnetometer).ignored, 1u);
  EXPECT_EQ(e.stats().of(MeasurementKind::kPressure).ignored, 1u);
  EXPECT_EQ(e.stats().of(MeasurementKind::kDeviceSolution).ignored, 1u);
  EXPECT_EQ(e.stats().of(MeasurementKind::kWheelTicks).ignored, 0u);
  EXPECT_EQ(e.stats().of(MeasurementKind::kWheelTicks).rejected_for(RejectReason::kInvalid), 1u);
}

// Delivers every non-IMU measurement `delay_samples` IMU samples after its stamp.
std::vector<Measurement> delayed(const std::vector<Measurement>& in, int delay_samples) {
  std::vector<Measurement> out;
  std::vector<std::pair<int, Measurement>> queue;
  int imu_index = 0;
  for (const auto& m : in) {
    if (kind_of(m) != MeasurementKind::kImu) {
      queue.emplace_back(imu_index + delay_samples, m);
      continue;
    }
    out.push_back(m);
    ++imu_index;
    for (auto it = queue.begin(); it != queue.end();) {
      if (it->first <= imu_index) {
        out.push_back(it->second);
        it = queue.erase(it);
      } else {
        ++it;
      }
    }
  }
  return out;
}

TEST(Engine, LateMeasurementsGiveTheSameStateAsTimelyOnes) {
  // 300 ms latency (60 samples): re-propagation from the snapshot must reproduce the in-order
  // result, not approximate it.
  const Stream s = make_static_stream(30.0, true);
  Engine timely{options_with_heading()};
  Engine late{options_with_heading()};
  for (const auto& m : s.items) timely.process(m);
  for (const auto& m : delayed(s.items, 60)) late.process(m);
  // Fixes still in flight at the end are not delivered to `late`: compare at the last common fix
  // by running the timely engine on the same set.
  Engine reference{options_with_heading()};
  const auto late_stream = delayed(s.items, 60);
  std::vector<Measurement> same_set;
  for (const auto& m : s.items) {
    if (kind_of(m) == MeasurementKind::kImu ||
        std::find_if(late_stream.begin(), late_stream.end(), [&](const Measurement& x) {
          return kind_of(x) == kind_of(m) && header_of(x).time_ns == header_of(m).time_ns;
        }) != late_stream.end()) {
      same_set.push_back(m);
    }
  }
  for (const auto& m : same_set) reference.process(m);
  EXPECT_GT(late.stats().replays, 100u);
  EXPECT_EQ(late.stats().of(MeasurementKind::kGnssPosition).used,
            reference.stats().of(MeasurementKind::kGnssPosition).used);
  const NavSolution& a = reference.solution();
  const NavSolution& b = late.solution();
  EXPECT_NEAR(a.lat_rad, b.lat_rad, 1e-12);
  EXPECT_NEAR(a.lon_rad, b.lon_rad, 1e-12);
  EXPECT_NEAR(a.height_m, b.height_m, 1e-6);
  EXPECT_LT((a.vel_ned_mps - b.vel_ned_mps).norm(), 1e-8);
  EXPECT_LT((a.pos_std_ned_m - b.pos_std_ned_m).norm(), 1e-9);
}

TEST(Engine, AMeasurementFusedOnArrivalSurvivesALaterReplay) {
  // A GNSS velocity stamped between two IMU samples and delivered just after the second is fused
  // on arrival, at that sample, after the sample's snapshot was taken. A fix delivered 5 samples
  // late then re-propagates from the newest snapshot before it, which can be that one: the
  // velocity must not be lost (it was: the snapshot lacked it, and its timestamp, before the
  // snapshot's horizon, kept it from being fused again; a fix delivered later re-propagates from
  // an older snapshot and hid the loss). Velocities every 7th sample meet the snapshots' 20-sample spacing at
  // every phase. Moving, so that no zero-velocity update hides what a velocity update does.
  test::LineTrajectory traj({kLat, 0.1, 200.0}, Eigen::Vector3d(10.0, 0.0, 0.0), Eigen::Vector3d::Zero(), 200.0);
  std::mt19937_64 rng(11);
  std::vector<Measurement> reference, late;  // reference: in time, what `late` delivers
  std::vector<std::pair<int, Measurement>> queue;  // (deliver after this many IMU samples, m)
  const auto deliver = [&](int imu_count) {
    for (auto it = queue.begin(); it != queue.end();) {
      if (it->first > imu_count) {
        ++it;
        continue;
      }
      late.push_back(it->second);
      it = queue.erase(it);
    }
  };
  const int n = 20 * 200;
  for (int k = 1; k <= n; ++k) {
    const ImuSample imu = traj.next();
    reference.emplace_back(imu);
    late.emplace_back(imu);
    deliver(k);
    if (k % 7 == 0 && k < n) {
      GnssVelocity v = test::make_velocity(traj.truth(), 0.05, &rng);
      v.header.time_ns += 3'000'000;  // 0.6 of the 5 ms interval after the sample
      reference.emplace_back(v);
      queue.emplace_back(k + 1, v);
    }
    if (k % 40 == 0 && k + 5 <= n) {
      const GnssPosition fix = test::make_fix(traj.truth(), Eigen::Vector3d::Zero(), 1.0, &rng);
      reference.emplace_back(fix);
      queue.emplace_back(k + 5, fix);
    }
  }
  FilterOptions o;
  o.initial_heading_rad = 0.0;
  Engine a{o};
  Engine b{o};
  for (const Measurement& m : reference) a.process(m);
  for (const Measurement& m : late) b.process(m);
  ASSERT_EQ(b.solution().mode, NavMode::kNavigation);
  EXPECT_GT(b.stats().replays, 50u);
  const std::uint64_t velocities = a.stats().of(MeasurementKind::kGnssVelocity).used;
  EXPECT_GT(velocities, 500u);
  EXPECT_EQ(b.stats().of(MeasurementKind::kGnssVelocity).used, velocities);
  EXPECT_NEAR(a.solution().lat_rad, b.solution().lat_rad, 1e-13);
  EXPECT_NEAR(a.solution().lon_rad, b.solution().lon_rad, 1e-13);
  EXPECT_LT((a.solution().vel_ned_mps - b.solution().vel_ned_mps).norm(), 1e-10);
  EXPECT_LT((a.solution().vel_std_ned_mps - b.solution().vel_std_ned_mps).norm(), 1e-12);
}

TEST(Engine, TooLateAndFutureMeasurements) {
  Engine e{options_with_heading()};
  test::LineTrajectory traj = static_trajectory();
  std::mt19937_64 rng(1);
  for (int k = 0; k < 200 * 5; ++k) e.process(traj.next());
  // 2 s old: beyond max_latency_s (1 s).
  test::LineTruth old = traj.truth();
  old.time_ns -= 2'000'000'000;
  e.process(test::make_fix(old, Eigen::Vector3d::Zero(), 1.0, &rng));
  EXPECT_EQ(e.stats().of(MeasurementKind::kGnssPosition).rejected_for(RejectReason::kTooLate), 1u);
  // 50 ms in the future: held until the IMU reaches it, then fused.
  test::LineTruth ahead = traj.truth();
  ahead.time_ns += 50'000'000;
  e.process(test::make_fix(ahead, Eigen::Vector3d::Zero(), 1.0, &rng));
  EXPECT_EQ(e.stats().of(MeasurementKind::kGnssPosition).used, 0u);
  for (int k = 0; k < 10; ++k) e.process(traj.next());
  EXPECT_EQ(e.stats().of(MeasurementKind::kGnssPosition).used, 1u);
  EXPECT_EQ(e.solution().mode, NavMode::kNavigation);
}

TEST(Engine, DeadReckoningAfterGnssTimeoutAndResetCommand) {
  Engine e{options_with_heading()};
  Stream s = make_static_stream(10.0, true);
  for (const auto& m : s.items) e.process(m);
  ASSERT_EQ(e.solution().mode, NavMode::kNavigation);
  test::LineTrajectory traj = static_trajectory();
  // Continue the IMU (same clock) without GNSS for 3 s.
  std::int64_t t = e.solution().header.time_ns;
  for (int k = 0; k < 600; ++k) {
    ImuSample imu = traj.next();
    t += 5'000'000;
    imu.header.time_ns = t;
    e.process(imu);
  }
  EXPECT_EQ(e.solution().mode, NavMode::kDeadReckoning);
  EXPECT_TRUE((e.solution().status_flags & NavSolution::kStatusGnssOutage) != 0);
  e.reset(Engine::kResetFilter);
  EXPECT_EQ(e.solution().mode, NavMode::kInitializing);
  EXPECT_EQ(e.stats().resets, 1u);
  EXPECT_FALSE(e.solution_valid());
}

// The restarts the filter makes on its own are counted by cause, apart from commanded ones
// (a device link announces them): an IMU gap beyond max_imu_gap_s, then a position std beyond
// divergence_position_std_m while navigating.
TEST(Engine, OwnRestartsAreCountedByCause) {
  FilterOptions o = options_with_heading();
  o.max_imu_gap_s = 0.5;
  Engine e{o};
  Stream s = make_static_stream(10.0, true);
  std::int64_t last_imu_ns = 0;
  for (const auto& m : s.items) {
    e.process(m);
    if (const auto* imu = std::get_if<ImuSample>(&m)) last_imu_ns = imu->header.time_ns;
  }
  ASSERT_EQ(e.solution().mode, NavMode::kNavigation);
  e.reset(Engine::kResetFilter);  // commanded: a restart, not one of the filter's own
  EXPECT_EQ(e.stats().resets, 1u);
  EXPECT_EQ(e.time_gap_restarts(), 0u);

  test::LineTrajectory traj = static_trajectory();
  ImuSample imu = traj.next();
  imu.header.time_ns = last_imu_ns + 600'000'000;  // 0.6 s > 0.5 s
  e.process(imu);
  EXPECT_EQ(e.time_gap_restarts(), 1u);
  EXPECT_EQ(e.divergence_restarts(), 0u);
  EXPECT_EQ(e.stats().resets, 2u);

  // A 1 m fix cannot hold the position within 0.1 m: once navigating, the filter is "lost".
  FilterOptions tight = options_with_heading();
  tight.divergence_position_std_m = 0.1;
  Engine d{tight};
  for (const auto& m : make_static_stream(10.0, true).items) d.process(m);
  EXPECT_GE(d.divergence_restarts(), 1u);
  EXPECT_EQ(d.time_gap_restarts(), 0u);
  EXPECT_EQ(d.stats().resets, d.divergence_restarts());
}

// Run-time switches (MIP 0x0D,0x63 and 0x0D,0x50 on a device link): driving north at 10 m/s
// with 5 Hz GNSS, the non-holonomic constraint applies until switched off, and GNSS positions
// are fused until their aiding is switched off (then counted as ignored), and again once back on.
TEST(Engine, NonholonomicConstraintAndAidingSwitchAtRunTime) {
  FilterOptions o;
  o.initial_heading_rad = 0.0;
  Engine e{o};
  test::LineTrajectory traj({kLat, 0.1, 200.0}, Eigen::Vector3d(10.0, 0.0, 0.0), Eigen::Vector3d::Zero(), 200.0);
  std::mt19937_64 rng(5);
  const auto drive = [&](double seconds) {
    const int n = static_cast<int>(seconds * 200.0);
    for (int k = 1; k <= n; ++k) {
      e.process(traj.next());
      if (k % 40 == 0) {
        e.process(test::make_fix(traj.truth(), Eigen::Vector3d::Zero(), 1.0, &rng));
        e.process(test::make_velocity(traj.truth(), 0.05, &rng));
      }
    }
  };
  drive(10.0);
  ASSERT_EQ(e.solution().mode, NavMode::kNavigation);
  const std::uint64_t nhc = e.stats().nhc_updates;
  EXPECT_GT(nhc, 0u);
  e.set_nonholonomic(false);
  drive(2.0);
  EXPECT_EQ(e.stats().nhc_updates, nhc);
  e.set_nonholonomic(true);
  drive(2.0);
  EXPECT_GT(e.stats().nhc_updates, nhc);

  const KindStats before = e.stats().of(MeasurementKind::kGnssPosition);
  e.set_aiding(MeasurementKind::kGnssPosition, false);
  EXPECT_FALSE(e.fuses(MeasurementKind::kGnssPosition));
  drive(2.0);  // 10 fixes
  const KindStats off = e.stats().of(MeasurementKind::kGnssPosition);
  EXPECT_EQ(off.used, before.used);
  EXPECT_EQ(off.ignored, before.ignored + 10);
  e.set_aiding(MeasurementKind::kGnssPosition, true);
  drive(2.0);
  // 10 more fixes; the newest may still wait for the IMU to reach its time.
  EXPECT_GE(e.stats().of(MeasurementKind::kGnssPosition).used, before.used + 9);
  e.set_aiding(MeasurementKind::kImu, false);  // not aiding: stays on
  EXPECT_TRUE(e.fuses(MeasurementKind::kImu));
}

// MIP 0x0D,0x03 on a device link: a heading given before levelling is taken at levelling, one
// given while levelled without a heading at once; with a heading known it is ignored.
TEST(Engine, InitialHeadingCommandAlignsAnUnalignedFilter) {
  for (const bool before_levelling : {true, false}) {
    Engine e{FilterOptions{}};
    const Stream s = make_static_stream(6.0, false);  // IMU only: levelled after 1 s, no heading
    if (before_levelling) {
      EXPECT_TRUE(e.set_initial_heading(1.0));
    }
    const std::size_t half = s.items.size() / 2;
    for (std::size_t i = 0; i < s.items.size(); ++i) {
      if (i == half && !before_levelling) {
        ASSERT_EQ(e.solution().mode, NavMode::kVerticalGyro);
        EXPECT_TRUE(e.set_initial_heading(1.0));
      }
      e.process(s.items[i]);
    }
    EXPECT_NE(e.solution().mode, NavMode::kVerticalGyro) << before_levelling;
    // The IMU's own heading is kRpy.z() (30 deg): the filter holds what it was told instead.
    EXPECT_NEAR(e.solution().rpy_rad.z(), 1.0, 0.01) << before_levelling;
    EXPECT_FALSE(e.set_initial_heading(-1.0));  // aligned: ignored
    EXPECT_NEAR(e.solution().rpy_rad.z(), 1.0, 0.01);
  }
}

// alignment.initial_tilt_std_deg / initial_velocity_std_mps replace the priors levelling derives
// (at rest: tilt from the accelerometer bias prior over g, 0.01 / 9.8 rad = 0.06 deg; velocity
// 0.05 m/s). Read in the first solution after levelling, before any update could move them
// (zero-velocity updates off).
TEST(Engine, ConfiguredLevellingPriorsReplaceTheDerivedOnes) {
  const auto first_levelled = [](const FilterOptions& o) {
    Engine e{o};
    for (const auto& m : make_static_stream(3.0, false).items) {
      e.process(m);
      if (e.solution().mode == NavMode::kVerticalGyro) return e.solution();
    }
    ADD_FAILURE() << "never levelled";
    return e.solution();
  };
  FilterOptions o;
  o.zero_velocity_updates = false;
  const NavSolution derived = first_levelled(o);
  EXPECT_NEAR(derived.att_std_rpy_rad.x(), 0.01 / 9.80665, 0.2 * 0.01 / 9.80665);
  EXPECT_NEAR(derived.vel_std_ned_mps.x(), 0.05, 0.005);

  o.initial_tilt_std_rad = 3.0 * rot::kDegToRad;
  o.initial_velocity_std_mps = 0.5;
  const NavSolution configured = first_levelled(o);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(configured.att_std_rpy_rad(i), 3.0 * rot::kDegToRad, 0.01 * rot::kDegToRad) << i;
  }
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(configured.vel_std_ned_mps(i), 0.5, 0.005) << i;
}

}  // namespace
}  // namespace navfuse::filter
