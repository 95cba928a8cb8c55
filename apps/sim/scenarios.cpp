// The named scenarios, all in one place (see scenarios.hpp for what each is for).
#include "apps/sim/scenarios.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "apps/sim/reality_scenarios.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

using Seg = MotionSegment;
constexpr double kDeg = rot::kDegToRad;

// Open-road start point (mid-latitude, so earth-rate and transport-rate terms are all non-zero).
TrajectorySpec drive_start() {
  TrajectorySpec t;
  t.start = {37.4275 * kDeg, -122.1697 * kDeg, 30.0};
  t.initial_yaw_rad = 30.0 * kDeg;
  return t;
}

// The common sensor suite of the filter tests: industrial IMU at 200 Hz (increments, sensor
// frame aligned with the vehicle), 5 Hz standalone GNSS with the antenna at (0.8, -0.4, -1.3) m,
// and a 50 Hz vehicle speed at the rear-axle centre with a 0.5 % scale error.
Scenario base_scenario(std::string name, TrajectorySpec trajectory) {
  Scenario s;
  s.name = std::move(name);
  s.trajectory = std::move(trajectory);
  s.imu.rate_hz = 200.0;
  s.imu.quantity = ImuQuantity::kIncrements;
  s.imu.errors = imu_error_spec(ImuGrade::kIndustrial);
  s.gnss = gnss_standalone(5.0);
  s.gnss.lever_arm_m = {0.8, -0.4, -1.3};
  s.wheel.vehicle_speed = true;
  s.wheel.rate_hz = 50.0;
  s.wheel.lever_arm_m = {-1.2, 0.0, 0.3};
  s.wheel.scale_error = 0.005;
  s.wheel.noise_std_mps = 0.05;
  return s;
}

// ~3.7 minutes with what makes an installation observable: turns both ways (lever arm x/y and
// mounting yaw against heading), speed changes (time offset against lever arm x), and climbs and
// road camber (the vertical lever arm is seen only as the vehicle tilts: +-8 deg pitch, +-6 deg
// roll).
TrajectorySpec calibration_trajectory() {
  TrajectorySpec t = drive_start();
  Seg camber{.kind = MotionKind::kCombined, .duration_s = 6.0, .speed_mps = {}, .heading_change_rad = {},
             .pitch_rad = {}, .roll_rad = 6.0 * kDeg};
  Seg camber_left = camber;
  camber_left.roll_rad = -6.0 * kDeg;
  Seg level = camber;
  level.roll_rad = 0.0;
  t.segments = {
      Seg::stationary(30.0),                                    //   0 -  30 static start
      Seg::accelerate(15.0, 10.0), Seg::cruise(10.0),           //  30 -  50
      Seg::turn(90.0 * kDeg, 10.0),                             //  50 -  60
      Seg::climb(8.0 * kDeg, 6.0), Seg::cruise(10.0),           //  60 -  76 uphill
      Seg::climb(0.0, 6.0), Seg::turn(-90.0 * kDeg, 10.0),      //  76 -  92
      camber, Seg::cruise(8.0), camber_left, Seg::cruise(8.0), level,  //  92 - 126 road camber
      Seg::accelerate(20.0, 8.0), Seg::turn(45.0 * kDeg, 12.0),  // 126 - 146
      Seg::climb(-8.0 * kDeg, 6.0), Seg::cruise(8.0),           // 146 - 160 downhill
      Seg::climb(0.0, 6.0), Seg::turn(-45.0 * kDeg, 12.0),      // 160 - 178
      Seg::accelerate(6.0, 10.0), Seg::turn(180.0 * kDeg, 15.0),  // 178 - 203 U-turn
      Seg::accelerate(0.0, 8.0), Seg::stationary(10.0),         // 203 - 221 stop
  };
  return t;
}

// The installation errors a calibration has to find (calibration_drive): an IMU mounted turned
// from the vehicle axes and an IMU clock 50 ms behind GPS time. Its own function so other sensor
// changes to a scenario stay separate from it.
void add_installation_errors(Scenario& s) {
  s.imu.mounting_rpy_deg = {0.3, 1.5, -2.0};
  s.imu.time_offset_s = 0.05;
}

}  // namespace

TrajectorySpec reference_drive() {
  // 1200 s. Speeds and durations keep lateral acceleration below ~3.5 m/s^2 (the smooth step's
  // peak rate is twice its mean). The stretch 506-740 s is at 20 m/s (the outage window).
  TrajectorySpec t = drive_start();
  t.segments = {
      Seg::stationary(30.0),                                     //    0 -   30 static start
      Seg::accelerate(10.0, 10.0), Seg::cruise(20.0),            //   30 -   60
      Seg::turn(90.0 * kDeg, 12.0),                              //   60 -   72
      Seg::accelerate(15.0, 8.0), Seg::cruise(30.0),             //   72 -  110
      Seg::accelerate(0.0, 10.0), Seg::stationary(20.0),         //  110 -  140 stop
      Seg::accelerate(12.0, 10.0), Seg::turn(-90.0 * kDeg, 10.0),  // 140 -  160
      Seg::climb(3.0 * kDeg, 8.0), Seg::cruise(30.0),            //  160 -  198 uphill
      Seg::climb(0.0, 8.0),                                      //  198 -  206
      Seg::accelerate(20.0, 10.0), Seg::turn(45.0 * kDeg, 15.0),  //  206 -  231
      Seg::cruise(60.0), Seg::turn(-135.0 * kDeg, 30.0),         //  231 -  321
      Seg::cruise(100.0),                                        //  321 -  421
      Seg::accelerate(0.0, 15.0), Seg::stationary(30.0),         //  421 -  466 stop
      Seg::accelerate(20.0, 15.0), Seg::turn(90.0 * kDeg, 25.0),  //  466 -  506
      Seg::cruise(134.0),                                        //  506 -  640
      Seg::turn(30.0 * kDeg, 20.0), Seg::cruise(60.0),           //  640 -  720
      Seg::turn(-60.0 * kDeg, 20.0), Seg::cruise(40.0),          //  720 -  780
      Seg::accelerate(10.0, 15.0), Seg::turn(90.0 * kDeg, 12.0),  //  780 -  807
      Seg::cruise(30.0), Seg::climb(-2.0 * kDeg, 8.0),           //  807 -  845 downhill
      Seg::cruise(40.0), Seg::climb(0.0, 8.0),                   //  845 -  893
      Seg::accelerate(0.0, 12.0), Seg::stationary(25.0),         //  893 -  930 stop
      Seg::accelerate(15.0, 12.0), Seg::turn(-90.0 * kDeg, 14.0),  // 930 -  956
      Seg::cruise(80.0), Seg::turn(180.0 * kDeg, 30.0),          //  956 - 1066 U-turn
      Seg::cruise(80.0), Seg::accelerate(0.0, 14.0),             // 1066 - 1160
      Seg::stationary(40.0),                                     // 1160 - 1200
  };
  return t;
}

TrajectorySpec short_drive() {
  // 190 s; 73-137 s at 20 m/s (the 95-125 s outage of drive_short).
  TrajectorySpec t = drive_start();
  t.segments = {
      Seg::stationary(30.0),                                     //   0 -  30 static start
      Seg::accelerate(15.0, 10.0), Seg::cruise(15.0),            //  30 -  55
      Seg::turn(90.0 * kDeg, 10.0),                              //  55 -  65
      Seg::accelerate(20.0, 8.0), Seg::cruise(20.0),             //  65 -  93
      Seg::turn(-45.0 * kDeg, 12.0), Seg::cruise(20.0),          //  93 - 125
      Seg::turn(45.0 * kDeg, 12.0),                              // 125 - 137
      Seg::accelerate(0.0, 13.0), Seg::stationary(10.0),         // 137 - 160 stop
      Seg::accelerate(10.0, 8.0), Seg::turn(90.0 * kDeg, 8.0),   // 160 - 176
      Seg::accelerate(0.0, 8.0), Seg::stationary(6.0),           // 176 - 190
  };
  return t;
}

// The reference drive's first 540 s (up to the turn that ends at 506 s, then 34 s of the 20 m/s
// cruise): the 9-minute log of the replay throughput benchmark (tests/bench/replay_throughput.sh).
TrajectorySpec nine_minute_drive() {
  TrajectorySpec t = reference_drive();
  constexpr std::size_t kSegmentsTo506s = 22;
  t.segments.resize(kSegmentsTo506s);
  t.segments.push_back(Seg::cruise(34.0));
  return t;
}

// The 20-minute reference drive `laps` times over, each lap from a standstill to a standstill:
// long logs for measuring time and memory against input size. 24 laps (drive_8h, about a
// gigabyte of VN-300 binary): tests/bench/bench_memory.sh; 3 laps (drive_1h, the hour of 200 Hz
// log issue 16's smoother goal is stated for): tests/bench/smooth_throughput.sh.
TrajectorySpec repeated_drive(int laps) {
  TrajectorySpec t = reference_drive();
  const std::vector<MotionSegment> lap = t.segments;
  for (int i = 1; i < laps; ++i) t.segments.insert(t.segments.end(), lap.begin(), lap.end());
  return t;
}

std::vector<std::string_view> scenario_names() {
  std::vector<std::string_view> names = {"static_start", "drive_outage", "rtk_drive", "drive_short",
                                         "delayed_gnss", "outliers",     "dual_antenna", "drive_9min",
                                         "drive_1h",     "drive_8h",     "calibration_drive"};
  for (std::string_view n : reality_scenario_names()) names.push_back(n);
  return names;
}

std::optional<Scenario> find_scenario(std::string_view name) {
  if (name == "static_start") {
    TrajectorySpec t = drive_start();
    t.segments = {Seg::stationary(60.0)};
    return base_scenario("static_start", t);
  }
  if (name == "drive_outage") {
    Scenario s = base_scenario("drive_outage", reference_drive());
    s.gnss.outages = {{kDriveOutageStart_s, kDriveOutageStart_s + kDriveOutageDuration_s}};
    return s;
  }
  if (name == "rtk_drive") {
    Scenario s = base_scenario("rtk_drive", reference_drive());
    const Eigen::Vector3d lever = s.gnss.lever_arm_m;
    s.gnss = gnss_rtk_fixed(10.0);
    s.gnss.lever_arm_m = lever;
    return s;
  }
  if (name == "drive_short") {
    Scenario s = base_scenario("drive_short", short_drive());
    s.gnss.outages = {{95.0, 125.0}};
    return s;
  }
  if (name == "delayed_gnss") {
    Scenario s = base_scenario("delayed_gnss", reference_drive());
    s.gnss.latency_s = 0.3;
    return s;
  }
  if (name == "outliers") {
    Scenario s = base_scenario("outliers", reference_drive());
    s.gnss.glitch_fraction = 0.02;
    s.gnss.glitch_offset_m = 50.0;
    s.gnss.jumps = {{kJumpTime_s, Eigen::Vector3d(30.0, 0.0, 0.0)}};
    return s;
  }
  if (name == "dual_antenna") {
    Scenario s = base_scenario("dual_antenna", short_drive());
    s.gnss.heading = true;
    // Secondary antenna 1.5 m behind the primary: the baseline points backwards along body x.
    s.gnss.secondary_lever_arm_m = s.gnss.lever_arm_m + Eigen::Vector3d(-1.5, 0.0, 0.0);
    return s;
  }
  if (name == "drive_9min") return base_scenario("drive_9min", nine_minute_drive());
  if (name == "calibration_drive") {
    Scenario s = base_scenario("calibration_drive", calibration_trajectory());
    const Eigen::Vector3d lever = s.gnss.lever_arm_m;
    s.gnss = gnss_rtk_fixed(10.0);
    s.gnss.lever_arm_m = lever;
    add_installation_errors(s);
    return s;
  }
  if (name == "drive_8h") return base_scenario("drive_8h", repeated_drive(24));
  if (name == "drive_1h") {
    // drive_outage's 120 s GNSS outage in every lap: what the smoother is for.
    Scenario s = base_scenario("drive_1h", repeated_drive(3));
    constexpr double kLap_s = 1200.0;
    for (int lap = 0; lap < 3; ++lap) {
      const double start_s = lap * kLap_s + kDriveOutageStart_s;
      s.gnss.outages.push_back({start_s, start_s + kDriveOutageDuration_s});
    }
    return s;
  }
  return find_reality_scenario(name);
}

Scenario make_scenario(std::string_view name) {
  if (std::optional<Scenario> s = find_scenario(name)) return *std::move(s);
  std::string known;
  for (std::string_view n : scenario_names()) known += (known.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("unknown scenario '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace navfuse::sim
