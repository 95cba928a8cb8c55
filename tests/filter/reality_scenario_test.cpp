// Issue 14 item 5: the filter on simulated drives with the effects real drives show (engine and
// road vibration, RTK fix-type changes, multipath jumps; apps/sim/reality_scenarios.hpp), with the
// IMU's data-sheet noise in the config (test::options_for: not inflated for the vibration), holds
// the accuracy goals of the comparable clean scenarios in scenario_test.cpp (README "Accuracy").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/sim/reality_scenarios.hpp"
#include "tests/filter/scenario_harness.hpp"

namespace navfuse::filter {
namespace {

using test::Epoch;
using test::Rms;

bool navigating(const Epoch& e) {
  const NavMode m = e.engine->solution().mode;
  return m == NavMode::kNavigation || m == NavMode::kDeadReckoning;
}

double seconds_since_start(const sim::Scenario& s, std::int64_t time_ns) {
  return static_cast<double>(time_ns - s.start_time_ns) * 1e-9;
}

// Per GNSS position fix: its time, fix type and whether the filter used it.
struct FixUse {
  double t_s = 0.0;
  GnssFixType fix = GnssFixType::kNone;
  bool used = false;
  double error_m = 0.0;  // horizontal distance of the fix from the true antenna position
};

// Runs `s` and records every epoch's horizontal error vector and every fix's use.
struct Track {
  std::vector<double> t_s;
  std::vector<Eigen::Vector2d> err_m;  // horizontal error (north, east), navigating epochs only
  std::vector<FixUse> fixes;
  test::RunSummary summary;
};

Track run_track(const sim::Scenario& s) {
  Track tr;
  std::uint64_t used_before = 0;
  bool pending = false;
  const Engine* engine = nullptr;
  const sim::TruthSample* truth = nullptr;  // at the latest IMU epoch = the fix time (no latency)
  const auto used_now = [&] { return engine ? engine->stats().of(MeasurementKind::kGnssPosition).used : 0; };
  tr.summary = test::run_scenario(
      s, test::options_for(s),
      [&](const Epoch& e) {
        engine = e.engine;
        truth = e.truth;
        if (pending) {
          tr.fixes.back().used = used_now() > used_before;
          pending = false;
        }
        if (!navigating(e)) return;
        tr.t_s.push_back(e.t_s);
        tr.err_m.push_back(e.pos_err_ned_m.head<2>());
      },
      [&](Measurement& m) {
        if (kind_of(m) == MeasurementKind::kGnssPosition) {
          const auto& p = std::get<GnssPosition>(m);
          double error_m = 0.0;
          if (truth != nullptr) {
            const geo::Llh antenna = sim::lever_arm_position(*truth, s.gnss.lever_arm_m);
            error_m = geo::ned_offset_m(antenna, {p.lat_rad, p.lon_rad, p.height_m}).head<2>().norm();
          }
          tr.fixes.push_back({seconds_since_start(s, p.header.time_ns), p.fix, false, error_m});
          used_before = used_now();
          pending = true;
        }
        return true;
      });
  return tr;
}

// Horizontal RMS over the epochs whose time satisfies `keep`.
template <typename Keep>
double rms_where(const Track& tr, Keep keep) {
  Rms r;
  for (std::size_t i = 0; i < tr.t_s.size(); ++i) {
    if (keep(tr.t_s[i])) r.add(tr.err_m[i].norm());
  }
  return r.value();
}

bool in_any(const std::vector<sim::TimeInterval>& spans, double t_s, double margin_after_s = 0.0) {
  return std::any_of(spans.begin(), spans.end(), [&](const sim::TimeInterval& i) {
    return t_s >= i.start_s && t_s < i.end_s + margin_after_s;
  });
}

// Horizontal, roll and pitch RMS outside the outage (and 10 s after it), and the error at the
// outage's end against the distance driven in it.
struct OutageDriveResult {
  Rms horizontal, roll, pitch, yaw;
  double outage_err_m = 0.0, distance_m = 0.0;
  test::RunSummary summary;
};

OutageDriveResult run_outage_drive(const sim::Scenario& s, const FilterOptions& o) {
  const double start = sim::kDriveOutageStart_s, end = start + sim::kDriveOutageDuration_s;
  OutageDriveResult r;
  double last_t = 0.0;
  r.summary = test::run_scenario(s, o, [&](const Epoch& e) {
    if (e.t_s > start && e.t_s <= end) r.distance_m += e.truth->vel_ned_mps.head<2>().norm() * (e.t_s - last_t);
    if (e.t_s <= end) r.outage_err_m = e.horizontal_m();
    last_t = e.t_s;
    if (!navigating(e) || (e.t_s >= start && e.t_s <= end + 10.0)) return;
    r.horizontal.add(e.horizontal_m());
    if (e.t_s >= 330.0) {  // after 5 minutes of driving, as in scenario_test.cpp
      r.roll.add(e.rpy_err_rad.x());
      r.pitch.add(e.rpy_err_rad.y());
      r.yaw.add(e.rpy_err_rad.z());
    }
  });
  return r;
}

void print_outage_drive(const char* label, const OutageDriveResult& r) {
  const auto& gnss = r.summary.stats.of(MeasurementKind::kGnssPosition);
  std::printf("%s: horizontal RMS %.3f m, roll/pitch/yaw RMS %.4f / %.4f / %.4f deg, outage %.2f m "
              "over %.0f m (%.3f %%); fixes used %llu, rejected %llu; max process-noise scale %.1f; "
              "zero-velocity updates %llu\n",
              label, r.horizontal.value(), r.roll.value() * rot::kRadToDeg, r.pitch.value() * rot::kRadToDeg,
              r.yaw.value() * rot::kRadToDeg, r.outage_err_m, r.distance_m, 100.0 * r.outage_err_m / r.distance_m,
              static_cast<unsigned long long>(gnss.used), static_cast<unsigned long long>(gnss.rejected_total()),
              r.summary.stats.max_process_noise_scale, static_cast<unsigned long long>(r.summary.stats.zupts));
}

TEST(RealityScenario, VibrationKeepsTheStandaloneAndOutageGoals) {
  // Clean goals (scenario_test.cpp, README "Accuracy"): standalone drive horizontal RMS <= 0.6 m,
  // 120 s outage at 20 m/s with wheel speed <= 0.2 % of the distance: held. Roll/pitch RMS after
  // 5 minutes <= 0.05 deg: NOT held (0.085 / 0.063 deg when written). It is beyond this vibration
  // for any tuning: the control below, the same filter told the vibration's true noise
  // (broadband RMS at 20 m/s folded into VRW / ARW), reaches 0.057 / 0.047 deg. Guarded at
  // 0.1 deg so that a regression shows.
  const sim::Scenario s = sim::make_scenario("vibration_drive");
  const OutageDriveResult r = run_outage_drive(s, test::options_for(s));
  print_outage_drive("vibration, data-sheet noise", r);
  FilterOptions told = test::options_for(s);
  const double dt = 1.0 / s.imu.rate_hz, v = sim::kDriveCruiseSpeed_mps;
  const sim::VibrationSpec& vib = s.imu.vibration;
  told.imu.accel_vrw_mps_rts =
      std::hypot(told.imu.accel_vrw_mps_rts, (vib.accel_rms_idle_mps2 + vib.accel_rms_per_mps * v) * std::sqrt(dt));
  told.imu.gyro_arw_rad_rts = std::hypot(
      told.imu.gyro_arw_rad_rts, (vib.gyro_rms_idle_dps + vib.gyro_rms_per_mps * v) * rot::kDegToRad * std::sqrt(dt));
  print_outage_drive("vibration, control with its true noise in the config", run_outage_drive(s, told));

  EXPECT_GT(r.horizontal.n, 150000u);
  EXPECT_LE(r.horizontal.value(), 0.6);
  EXPECT_GT(r.distance_m, 2000.0);
  EXPECT_LE(r.outage_err_m, 0.002 * r.distance_m);
  EXPECT_LE(r.roll.value() * rot::kRadToDeg, 0.1);
  EXPECT_LE(r.pitch.value() * rot::kRadToDeg, 0.1);
}

TEST(RealityScenario, RtkFixChangesKeepCentimetresWhenFixedAndDoNotJump) {
  const sim::Scenario s = sim::make_scenario("rtk_fix_changes");
  const std::vector<sim::GnssFixInterval> schedule = sim::rtk_fix_change_schedule();
  std::vector<sim::TimeInterval> degraded;
  for (const auto& f : schedule) degraded.push_back(f.interval);
  const Track tr = run_track(s);

  // Fixed stretches: the rtk_drive goal (<= 2 cm RMS) from 5 s after each re-fix.
  const double fixed_rms = rms_where(tr, [&](double t) { return t > 60.0 && !in_any(degraded, t, 5.0); });
  // Degraded stretches: the filter is no worse than the receiver's own solution there.
  const double degraded_rms = rms_where(tr, [&](double t) { return in_any(degraded, t); });
  Rms gnss_degraded;
  std::size_t fixed_n = 0, fixed_used = 0;
  for (const FixUse& f : tr.fixes) {
    if (in_any(degraded, f.t_s)) gnss_degraded.add(f.error_m);
    // Fixed fixes used: the 98 % (none rejected for the filter being overconfident).
    if (f.fix != GnssFixType::kRtkFixed || f.t_s < 60.0) continue;
    ++fixed_n;
    fixed_used += f.used;
  }
  std::printf("fix changes: horizontal RMS %.4f m in RTK-fixed stretches (goal 0.02); %.3f m in the "
              "degraded stretches, the receiver's own fixes there %.3f m; %zu of %zu RTK-fixed fixes "
              "used (%.2f %%)\n",
              fixed_rms, degraded_rms, gnss_degraded.value(), fixed_used, fixed_n,
              100.0 * static_cast<double>(fixed_used) / static_cast<double>(fixed_n));
  EXPECT_LE(fixed_rms, 0.02);
  EXPECT_LE(degraded_rms, gnss_degraded.value());
  EXPECT_GE(static_cast<double>(fixed_used), 0.98 * static_cast<double>(fixed_n));

  // Transitions back to fixed. The step of the output against the truth's motion is the change
  // of the error vector from one 200 Hz epoch to the next. The float solution carried a slowly
  // varying error that the filter followed (it cannot tell it from the truth); the first fixed
  // fix removes it from the filter at once, and the output takes it over output.jump_blend_s
  // (0.25 s; filter/output_blend.hpp) instead of jumping: no step larger than an ordinary RTK
  // update makes, 3 sigma of the difference of two fixed fixes' horizontal noise (3 * sqrt(2) *
  // 0.02 m = 0.085 m; before the blending the steps were the whole float error, 0.30-0.50 m). And
  // the error 1.5 s after the re-fix is back at the fixed level (<= 5 cm, 2.5x the 2 cm RMS goal
  // at a single epoch): the first fixed fixes may wait ~0.5 s at the gate for the covariance
  // re-inflation, then the blend has removed 98 % of the correction after 1 s.
  int transitions = 0;
  for (const sim::GnssFixInterval& f : schedule) {
    const double t_fix = f.interval.end_s;
    if (in_any(degraded, t_fix)) continue;  // followed by another degraded type
    ++transitions;
    double max_step = 0.0, err_before = 0.0, err_after = 0.0, max_step_before = 0.0;
    for (std::size_t i = 1; i < tr.t_s.size(); ++i) {
      const double t = tr.t_s[i];
      const double step = (tr.err_m[i] - tr.err_m[i - 1]).norm();
      if (t < t_fix) err_before = tr.err_m[i].norm();
      if (t >= t_fix - 10.0 && t < t_fix - 1.0) max_step_before = std::max(max_step_before, step);
      if (t >= t_fix && t < t_fix + 2.0) max_step = std::max(max_step, step);
      if (t <= t_fix + 1.5) err_after = tr.err_m[i].norm();
    }
    std::printf("  re-fix at %.0f s (from %s): error before %.3f m, largest step %.4f m (bound %.3f; "
                "in the float stretch %.4f m), error 1.5 s after %.4f m\n",
                t_fix, std::string(to_string(f.fix)).c_str(), err_before, max_step, 0.085, max_step_before, err_after);
    EXPECT_LE(max_step, 0.085) << t_fix;
    EXPECT_LE(err_after, 0.05) << t_fix;
  }
  EXPECT_EQ(transitions, 5);
  // The three re-fixes that remove decimetres were blended; the two of 5-8 cm are below
  // output.jump_blend_min_m and pass straight through.
  EXPECT_EQ(tr.summary.stats.output_jumps_blended, 3u);
}

TEST(RealityScenario, UrbanMultipathKeepsTheRtkGoal) {
  const sim::Scenario s = sim::make_scenario("urban_multipath");
  const std::vector<sim::TimeInterval> urban = sim::urban_segments();
  const std::vector<sim::MultipathEvent> events = sim::multipath_events(s.gnss.multipath, s.seed);
  const Track tr = run_track(s);
  const double open_rms = rms_where(tr, [&](double t) { return t > 60.0 && !in_any(urban, t, 5.0); });
  const double urban_rms = rms_where(tr, [&](double t) { return in_any(urban, t); });
  double urban_max = 0.0;
  for (std::size_t i = 0; i < tr.t_s.size(); ++i) {
    if (in_any(urban, tr.t_s[i])) urban_max = std::max(urban_max, tr.err_m[i].norm());
  }
  std::size_t hit = 0, hit_used = 0, clean_urban = 0, clean_urban_used = 0;
  for (const FixUse& f : tr.fixes) {
    if (!in_any(urban, f.t_s)) continue;
    bool active = false;
    sim::multipath_offset(events, f.t_s, &active);
    if (active) {
      ++hit;
      hit_used += f.used;
    } else {
      ++clean_urban;
      clean_urban_used += f.used;
    }
  }
  std::printf("multipath: %zu events; horizontal RMS %.4f m outside the urban segments, %.4f m "
              "(max %.3f m) inside; multipath fixes used %zu of %zu, clean urban fixes used %zu of "
              "%zu; recoveries %llu\n",
              events.size(), open_rms, urban_rms, urban_max, hit_used, hit, clean_urban_used,
              clean_urban, static_cast<unsigned long long>(tr.summary.stats.gnss_recoveries));
  // Outside the urban segments: the rtk_drive goal, held.
  EXPECT_LE(open_rms, 0.02);
  // Inside them too (0.0122 m RMS, max 0.17 m, 1 of 821 offset fixes used, 2670 of 2679 clean, when
  // written): each event starts with a step between consecutive fixes that the inertial track
  // does not make, and its fixes are held out until they return (control/gnss_jump_check.hpp).
  // Before that check the innovation adaptation took the persistent, mutually agreeing residuals
  // for a filter that drifted off a healthy stream and followed the offsets: 0.66 m RMS, 79 % of
  // the offset fixes used.
  EXPECT_LE(urban_rms, 0.02);
  EXPECT_LE(hit_used, hit / 100);
  EXPECT_GE(clean_urban_used, clean_urban * 99 / 100);
}

}  // namespace
}  // namespace navfuse::filter

namespace navfuse::filter {
namespace {

TEST(RealityScenario, RealDriveAllEffects) {
  // real_drive: RTK with fix-type changes, multipath in the urban segments and car vibration.
  // Outside the degraded and urban stretches (5 s margin after each): the rtk_drive goals,
  // horizontal RMS <= 2 cm and heading RMS <= 0.15 deg.
  const sim::Scenario s = sim::make_scenario("real_drive");
  std::vector<sim::TimeInterval> affected = sim::urban_segments();
  for (const auto& f : sim::rtk_fix_change_schedule()) affected.push_back(f.interval);
  Rms horizontal, heading, all;
  const auto summary = test::run_scenario(s, test::options_for(s), [&](const Epoch& e) {
    if (!navigating(e) || e.t_s < 60.0) return;
    all.add(e.horizontal_m());
    if (in_any(affected, e.t_s, 5.0)) return;
    horizontal.add(e.horizontal_m());
    heading.add(e.rpy_err_rad.z());
  });
  const auto& gnss = summary.stats.of(MeasurementKind::kGnssPosition);
  std::printf("real drive: horizontal RMS %.4f m, heading RMS %.4f deg in the clean stretches (%zu "
              "epochs); %.3f m over the whole drive; fixes used %llu, rejected %llu; re-anchorings %llu\n",
              horizontal.value(), heading.value() * rot::kRadToDeg, horizontal.n, all.value(),
              static_cast<unsigned long long>(gnss.used), static_cast<unsigned long long>(gnss.rejected_total()),
              static_cast<unsigned long long>(summary.stats.gnss_recoveries));
  EXPECT_GT(horizontal.n, 100000u);
  EXPECT_LE(horizontal.value(), 0.02);
  EXPECT_LE(heading.value() * rot::kRadToDeg, 0.15);
}

}  // namespace
}  // namespace navfuse::filter
