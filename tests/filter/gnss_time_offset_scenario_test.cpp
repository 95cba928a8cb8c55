// Issue 14 item 2: the GNSS-to-IMU time offset as an estimated state (gnss.estimate_time_offset).
// The simulator stamps the IMU samples 80 ms before the true time of their motion
// (sim::ImuSpec::time_offset_s), a latency of the kind a USB IMU or a receiver's RTK engine adds.
// Seen from the IMU's clock, a fix stamped t is the antenna at t - 80 ms, so the state must find
// -80 ms (truth from the simulation). The same drive with the offset left unmodelled shows what it
// costs: at 20 m/s, 80 ms is 1.6 m along the track against fixes of 2 cm.
//
// GNSS and IMU only, as on the held-out car drive of issue 14 (imutxt + rtklib): the state is the
// GNSS stream's offset. The simulated odometer is stamped on GNSS time, so with it the odometer
// would be 80 ms off too, which only wheel.time_offset_s describes (on this drive it pulls the
// estimate to -28 ms: a wrong odometer timing cannot be left to the GNSS state).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "apps/sim/reality_scenarios.hpp"
#include "tests/filter/scenario_harness.hpp"

namespace navfuse::filter {
namespace {

constexpr double kImuLate_s = 0.08;

sim::Scenario late_imu_rtk_drive() {
  sim::Scenario s = *sim::find_scenario("rtk_drive");
  s.imu.time_offset_s = kImuLate_s;
  return s;
}

struct OffsetRun {
  test::Rms horizontal;  // after the first 5 minutes of driving
  double offset_s = 0.0, offset_std_s = 0.0;
  std::uint64_t fixes_used = 0, fixes_rejected = 0;
};

OffsetRun run(const sim::Scenario& s, const FilterOptions& o, double score_from_s = 330.0) {
  OffsetRun r;
  const auto gnss_and_imu_only = [](Measurement& m) { return kind_of(m) != MeasurementKind::kVehicleSpeed; };
  const test::RunSummary summary = test::run_scenario(
      s, o,
      [&](const test::Epoch& e) {
        const NavSolution& sol = e.engine->solution();
        r.offset_s = sol.calibration.gnss_time_offset_s.value;
        r.offset_std_s = sol.calibration.gnss_time_offset_s.std;
        if (e.t_s >= score_from_s && sol.mode == NavMode::kNavigation) r.horizontal.add(e.horizontal_m());
      },
      gnss_and_imu_only);
  const auto& gnss = summary.stats.of(MeasurementKind::kGnssPosition);
  r.fixes_used = gnss.used;
  r.fixes_rejected = gnss.rejected_total();
  return r;
}

void print(const char* label, const OffsetRun& r) {
  std::printf("%s: horizontal RMS %.4f m, offset %.2f +- %.2f ms, fixes used %llu rejected %llu\n", label,
              r.horizontal.value(), r.offset_s * 1e3, r.offset_std_s * 1e3,
              static_cast<unsigned long long>(r.fixes_used), static_cast<unsigned long long>(r.fixes_rejected));
}

TEST(GnssTimeOffsetScenario, TheStateFindsTheOffsetAndKeepsTheRtkGoal) {
  const sim::Scenario s = late_imu_rtk_drive();
  FilterOptions estimated = test::options_for(s);
  estimated.states.gnss_time_offset = true;
  estimated.initial_gnss_time_offset_std_s = 0.1;  // "about 100 ms" is what an integrator knows
  const OffsetRun r = run(s, estimated);
  print("estimated", r);

  const double truth_s = -kImuLate_s;
  EXPECT_NEAR(r.offset_s, truth_s, 0.002);
  EXPECT_LT(std::abs(r.offset_s - truth_s), 3.0 * r.offset_std_s + 2e-4) << "std claims too much";
  EXPECT_LT(r.offset_std_s, 0.002);
  // The clean rtk_drive goal (scenario_test.cpp: 2 cm), with the offset found instead of given.
  EXPECT_GT(r.horizontal.n, 100000u);
  EXPECT_LE(r.horizontal.value(), 0.02);
  EXPECT_GE(r.fixes_used, 99 * (r.fixes_used + r.fixes_rejected) / 100);
}

TEST(GnssTimeOffsetScenario, LeftUnmodelledTheOffsetCostsTheRtkGoal) {
  // The same drive without the state: the comparison the state is judged by.
  const sim::Scenario s = late_imu_rtk_drive();
  const OffsetRun r = run(s, test::options_for(s));
  print("unmodelled", r);
  EXPECT_GT(r.horizontal.value(), 0.05);
}

TEST(GnssTimeOffsetScenario, OnADriveWithoutOffsetTheStateStaysAtZero) {
  const sim::Scenario s = *sim::find_scenario("rtk_drive");
  FilterOptions o = test::options_for(s);
  o.states.gnss_time_offset = true;
  const OffsetRun r = run(s, o);
  print("no offset", r);
  EXPECT_LT(std::abs(r.offset_s), 0.002);
  EXPECT_LE(r.horizontal.value(), 0.02);
}

// The held-out car drive's rig as its user would leave it when the IMU's latency is not known:
// parking_drive (IMU 125 ms late, tight car-park turns, vibration), land platform, the data
// sheet, the offset not configured but estimated from the default prior (50 ms). The offset is
// seen only in manoeuvres; the first ones come while the heading and velocity still settle from
// the alignment. Before the state's two-minute settling walk and the low-passed acceleration in
// its models (filter_core.cpp, gnss_position.cpp), the state kept what it took there: 31-63 ms
// +- 0.3 in these three draws, 0.44-0.66 m horizontal RMS. Now within 15 ms (114-115 ms when
// written; the std claims far less than that error, see README) and under 10 cm.
TEST(GnssTimeOffsetScenario, AnUnknownLatencyOfTheParkingDrivesImuIsFoundFromTheDefaultPrior) {
  for (const std::uint64_t seed : {27u, 29u, 31u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    sim::Scenario s = sim::parking_drive();
    s.seed = seed;
    FilterOptions o = test::options_for(s);
    o.land_vehicle = true;
    o.course_alignment = true;
    o.imu_time_offset_s = 0.0;  // not known
    o.states.gnss_time_offset = true;
    const OffsetRun r = run(s, o, 180.0);
    print("parking drive, offset estimated", r);
    // IMU stamps 125 ms late: seen from the IMU's clock, a fix stamped t is the antenna at t + 125 ms.
    EXPECT_NEAR(r.offset_s, -sim::kParkingImuTimeOffset_s, 0.015);
    EXPECT_GT(r.horizontal.n, 30000u);
    EXPECT_LE(r.horizontal.value(), 0.1);
  }
}

}  // namespace
}  // namespace navfuse::filter
