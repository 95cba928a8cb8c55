// The scenarios with real-drive effects (see reality_scenarios.hpp).
#include "apps/sim/reality_scenarios.hpp"

#include <string>

#include "apps/sim/scenarios.hpp"
#include "apps/sim/vibration_model.hpp"

namespace navfuse::sim {
namespace {

GnssFixInterval degraded(double start_s, double end_s, GnssFixType fix) {
  return {{start_s, end_s}, fix, receiver_fix_noise(fix)};
}

Scenario renamed(std::string_view base, std::string_view name) {
  Scenario s = make_scenario(base);
  s.name = std::string(name);
  return s;
}

void add_fix_changes(Scenario& s) {
  s.gnss.noise = receiver_fix_noise(s.gnss.fix);
  s.gnss.fix_schedule = rtk_fix_change_schedule();
}

void add_multipath(Scenario& s) {
  s.gnss.multipath.windows = urban_segments();
  s.gnss.multipath.events_per_minute = 6.0;
  s.gnss.multipath.min_offset_m = 0.2;
  s.gnss.multipath.max_offset_m = 3.0;
}

}  // namespace

std::vector<GnssFixInterval> rtk_fix_change_schedule() {
  // Against reference_drive(): losses of fix in turns, under a bridge while cruising (600 s,
  // standalone), at a stop (893-930 s: the re-fix at 915 s happens standing still).
  using F = GnssFixType;
  return {
      degraded(200.0, 240.0, F::kRtkFloat),                                       // uphill, turn
      degraded(330.0, 360.0, F::kRtkFloat), degraded(360.0, 400.0, F::kDgnss),    // cruise
      degraded(400.0, 450.0, F::kRtkFloat),                                       // stop at 421
      degraded(600.0, 630.0, F::kFix3D), degraded(630.0, 690.0, F::kRtkFloat),    // bridge
      degraded(900.0, 915.0, F::kRtkFloat),                                       // at a stop
      degraded(1000.0, 1060.0, F::kRtkFloat),                                     // U-turn
  };
}

std::vector<TimeInterval> urban_segments() { return {{300.0, 500.0}, {950.0, 1100.0}}; }

std::vector<std::string_view> reality_scenario_names() {
  return {"vibration_drive", "rtk_fix_changes", "urban_multipath", "real_drive"};
}

std::optional<Scenario> find_reality_scenario(std::string_view name) {
  if (name == "vibration_drive") {
    Scenario s = renamed("drive_outage", name);
    s.imu.vibration = car_vibration();
    return s;
  }
  if (name == "rtk_fix_changes") {
    Scenario s = renamed("rtk_drive", name);
    add_fix_changes(s);
    return s;
  }
  if (name == "urban_multipath") {
    Scenario s = renamed("rtk_drive", name);
    add_multipath(s);
    return s;
  }
  if (name == "real_drive") {
    Scenario s = renamed("rtk_drive", name);
    s.imu.vibration = car_vibration();
    add_fix_changes(s);
    add_multipath(s);
    return s;
  }
  return std::nullopt;
}

}  // namespace navfuse::sim
