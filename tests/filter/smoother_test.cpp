// The forward record and the RTS smoother: the record replaces what re-propagation recomputes,
// recording leaves the forward solution untouched, the recorded transition matrix is the one the
// covariance step applied, and the smoother follows a short simulated drive (apps/sim truth).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "apps/sim/scenarios.hpp"
#include "tests/filter/scenario_harness.hpp"
#include "tests/filter/smoother_harness.hpp"

namespace navfuse::filter {
namespace {

std::vector<unsigned char> bytes_of(std::int64_t v) {
  std::vector<unsigned char> b(sizeof v);
  std::memcpy(b.data(), &v, sizeof v);
  return b;
}

TEST(ForwardRecord, AnIndexWrittenAgainTruncatesThere) {
  ForwardRecorder rec;
  for (std::int64_t i = 0; i < 5; ++i) rec.write(static_cast<std::uint64_t>(i), RecordType::kRestart, bytes_of(100 + i));
  ASSERT_EQ(rec.size(), 5u);
  // A re-propagation from the state that wrote record 2 writes index 2 again.
  rec.write(2, RecordType::kBreak, bytes_of(42));
  rec.write(3, RecordType::kBreak, bytes_of(43));
  EXPECT_EQ(rec.size(), 4u);
  EXPECT_EQ(rec.replaced(), 3u);
  ForwardRecordEntry e;
  const std::int64_t expected[] = {100, 101, 42, 43};
  const RecordType types[] = {RecordType::kRestart, RecordType::kRestart, RecordType::kBreak, RecordType::kBreak};
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_TRUE(rec.read(i, e)) << rec.error();
    EXPECT_EQ(e.type, types[i]);
    EXPECT_EQ(e.time_ns, expected[i]);
  }
  // An index beyond the end is a bug in the caller: reported, nothing written.
  rec.write(9, RecordType::kBreak, bytes_of(1));
  EXPECT_EQ(rec.size(), 4u);
  EXPECT_FALSE(rec.error().empty());
}

// Runs drive_short with or without recording; the forward solution at every IMU epoch.
std::vector<NavSolution> forward_solutions(const sim::Scenario& s, ForwardRecorder* recorder,
                                           bool adaptation = true) {
  sim::Simulator sim(s);
  FilterOptions options = test::options_for(s);
  options.adaptation.enabled = adaptation;
  Engine engine(options);
  engine.record_to(recorder);
  std::vector<NavSolution> out;
  Measurement m;
  while (sim.next(m)) {
    engine.process(m);
    if (kind_of(m) == MeasurementKind::kImu) out.push_back(engine.solution());
  }
  if (recorder != nullptr) recorder->close(engine.core());
  return out;
}

TEST(ForwardRecord, RecordingLeavesTheForwardSolutionUnchanged) {
  const sim::Scenario s = sim::make_scenario("delayed_gnss");
  sim::Scenario shortened = sim::make_scenario("drive_short");
  shortened.gnss.latency_s = s.gnss.latency_s;  // late fixes: the record is re-propagated
  ForwardRecorder rec;
  const std::vector<NavSolution> plain = forward_solutions(shortened, nullptr);
  const std::vector<NavSolution> recorded = forward_solutions(shortened, &rec);
  ASSERT_EQ(plain.size(), recorded.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    ASSERT_EQ(std::memcmp(&plain[i].lat_rad, &recorded[i].lat_rad, sizeof(double)), 0) << i;
    ASSERT_EQ(plain[i].vel_ned_mps, recorded[i].vel_ned_mps) << i;
    ASSERT_EQ(plain[i].q_nb.coeffs(), recorded[i].q_nb.coeffs()) << i;
    ASSERT_EQ(plain[i].pos_std_ned_m, recorded[i].pos_std_ned_m) << i;
  }
  EXPECT_TRUE(rec.error().empty()) << rec.error();
  EXPECT_GT(rec.replaced(), 0u) << "300 ms late fixes must re-propagate recorded spans";
  // After the re-propagations the record is one history: IMU times strictly increasing, each
  // propagation between an interval start and the next, and the IMU states those of the final
  // forward pass (the last one is the filter's final state, checked against kClose).
  ForwardRecordEntry e, last_imu;
  std::int64_t previous_imu_ns = INT64_MIN;
  bool in_interval = false;
  std::size_t imu = 0, propagations = 0, updates = 0;
  for (std::size_t i = 0; i < rec.size(); ++i) {
    ASSERT_TRUE(rec.read(i, e));
    switch (e.type) {
      case RecordType::kImu:
        ASSERT_GT(e.time_ns, previous_imu_ns) << "record " << i;
        previous_imu_ns = e.time_ns;
        last_imu = e;
        ++imu;
        break;
      case RecordType::kIntervalStart:
        EXPECT_FALSE(in_interval) << "record " << i;
        in_interval = true;
        break;
      case RecordType::kPropagation:
        EXPECT_TRUE(in_interval) << "record " << i;
        in_interval = false;
        ++propagations;
        break;
      case RecordType::kUpdate:
        ++updates;
        EXPECT_FALSE(in_interval && e.time_ns != previous_imu_ns);
        break;
      default:
        break;
    }
  }
  EXPECT_GT(imu, 30000u);
  EXPECT_GT(propagations, imu / 12);  // 200 Hz IMU, 20 Hz covariance grid (plus update flushes)
  EXPECT_GT(updates, 500u);
  ASSERT_EQ(rec.type(rec.size() - 1), RecordType::kClose);
  ASSERT_TRUE(rec.read(rec.size() - 1, e));
  EXPECT_EQ(e.time_ns, last_imu.time_ns);
}

TEST(ForwardRecord, TransitionMatrixIsTheOneThePropagationApplied) {
  // P- = Phi P+ Phi^T + Q_d, Q_d = Q T + (F Q + Q F^T) T^2 / 2 (process_model.cpp): what is left
  // after removing Phi P+ Phi^T from the recorded prior must be that small noise term. A wrong Phi
  // leaves errors of the size of P itself.
  sim::Scenario s = sim::make_scenario("drive_short");
  ForwardRecorder rec;
  // Without innovation adaptation, so that Q is the data-sheet density the check below assumes
  // (adaptation scales it; the recorded prior, which the smoother uses, includes that).
  forward_solutions(s, &rec, /*adaptation=*/false);
  const StateVector q = process_noise_density(test::options_for(s));
  ForwardRecordEntry start, prior;
  bool have_start = false;
  std::size_t checked = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < rec.size(); ++i) {
    const RecordType t = rec.type(i);
    if (t == RecordType::kIntervalStart) have_start = rec.read(i, start);
    if (t != RecordType::kPropagation || !have_start) continue;
    ASSERT_TRUE(rec.read(i, prior));
    have_start = false;
    if (!start.navigating) continue;  // vertical gyro: the heading row is reset after the step
    const int n = prior.n;
    const double dt = static_cast<double>(prior.time_ns - start.time_ns) * 1e-9;
    Eigen::MatrixXd expected = prior.phi.topLeftCorner(n, n) * start.p.topLeftCorner(n, n) *
                               prior.phi.topLeftCorner(n, n).transpose();
    expected.diagonal() += q.head(n) * dt;
    const Eigen::MatrixXd diff = prior.p.topLeftCorner(n, n) - expected;
    // Relative to the variances involved: |diff_ij| <= tol sqrt(P_ii P_jj).
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const double scale = std::sqrt(prior.p(r, r) * prior.p(c, c));
        if (scale > 0.0) worst = std::max(worst, std::abs(diff(r, c)) / scale);
      }
    }
    ++checked;
  }
  std::printf("transition matrix: %zu intervals, worst relative mismatch %.2e\n", checked, worst);
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(worst, 1e-3);
}

TEST(RtsSmoother, ShortDriveOutageFollowsTruth) {
  // drive_short: a 30 s outage (95-125 s) at 20 m/s, no wheel speed. The smoothed solution ties
  // the outage to the fixes on both sides: its worst horizontal error there is well below the
  // forward filter's (which drifts only ~0.9 m here; the 120 s outage of the scenario test is the
  // one-tenth case), and inside its own 3-sigma.
  sim::Scenario s = sim::make_scenario("drive_short");
  s.wheel.vehicle_speed = false;
  const std::int64_t outage_start = 95'000'000'000, outage_end = 125'000'000'000;
  double smoothed_max = 0.0;
  std::size_t in_outage = 0, outside_3_sigma = 0;
  const test::SmoothedRun run = test::run_smoothed(s, test::options_for(s), [&](const SmoothedSample& x, const sim::TruthSample& t,
                                                                             const test::TruthError& e) {
    const std::int64_t since = t.time_ns - s.start_time_ns;
    if (since < outage_start || since > outage_end) return;
    smoothed_max = std::max(smoothed_max, e.pos.head<2>().norm());
    for (int i = 0; i < 2; ++i) outside_3_sigma += std::abs(e.pos(i)) > 3.0 * std::sqrt(x.p(sx::kPos + i, sx::kPos + i));
    ++in_outage;
  });
  double forward_max = 0.0;
  for (const test::ForwardEpoch& f : run.forward) {
    const std::int64_t since = f.truth.time_ns - s.start_time_ns;
    if (since >= outage_start && since <= outage_end) forward_max = std::max(forward_max, f.error.pos.head<2>().norm());
  }
  std::printf("30 s outage: forward max %.2f m, smoothed max %.3f m (%zu samples; %llu intervals, %llu segments)\n",
              forward_max, smoothed_max, in_outage, static_cast<unsigned long long>(run.smoother.intervals),
              static_cast<unsigned long long>(run.smoother.segments));
  EXPECT_TRUE(run.smoother.error.empty()) << run.smoother.error;
  EXPECT_GT(in_outage, 5000u);
  EXPECT_LT(smoothed_max, 0.5 * forward_max);
  EXPECT_LT(outside_3_sigma, in_outage / 50);
}

}  // namespace
}  // namespace navfuse::filter
