// `navfuse sim --scenario NAME --format vn|mip|fe|unicore --out F [--truth F.csv] [--seed N]
//              [--wheel-out F.p1log] [--device-rate HZ] [--quiet]`
// Runs a named simulator scenario (apps/sim/scenarios.hpp) and writes what the device would
// have logged, through the front-end's own MeasurementEncoder: IMU, GNSS and, where the protocol
// carries it, wheel speed, plus a device INS solution (device_solution_model.hpp); the truth CSV
// with --truth; and the wheel / vehicle speed as a FusionEngine sensor log with --wheel-out (for
// devices such as the VN-300 that have no wheel input).
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace navfuse::apps {

struct SimOptions {
  std::string scenario;
  std::string format;
  std::string out_path;
  std::string truth_path;
  std::string wheel_out_path;
  std::optional<std::uint64_t> seed;      // default: the scenario's
  std::optional<double> device_rate_hz;   // default: the device class's; 0 = no device solution
  // > 0: the scenario's vehicle speed becomes a vehicle tick counter of this many metres per
  // count (WheelTicks, one channel: FusionEngine VehicleTickInput on --wheel-out).
  double wheel_tick_m = 0.0;
  // Polled per measurement (InterruptSignals::received()): non-zero stops the simulation; the
  // logs are committed with the frames written so far and SimReport::interrupted_by says so.
  const std::atomic<int>* interrupt = nullptr;
  // The IMU installation, overriding the scenario's: clock offset (stamps this much before the
  // true time) and mounting sensor -> vehicle roll, pitch, yaw in degrees.
  std::optional<double> imu_time_offset_s;
  std::optional<std::vector<double>> imu_mounting_rpy_deg;
  // Where the vehicle does not slip (the rear-axle centre of a car), vehicle frame from the IMU,
  // metres; default: the scenario's (the IMU itself).
  std::optional<std::vector<double>> nonslip_point_m;
  // false: the receiver reports positions only, as an RTKLIB .pos without velocity columns.
  bool gnss_velocity = true;
};

struct SimReport {
  std::map<std::string, std::uint64_t> written;  // measurements per kind in the device log
  std::map<std::string, std::uint64_t> wheel_written;
  std::string wheel_format;  // protocol of the --wheel-out log
  std::map<std::string, std::uint64_t> dropped;  // kinds the protocol cannot carry
  std::uint64_t truth_rows = 0;
  std::uint64_t out_bytes = 0, wheel_bytes = 0;
  int interrupted_by = 0;  // the signal that stopped the simulation early (0: ran to the end)
};

// Throws CommandError with a one-line reason (unknown scenario or format, unwritable file).
SimReport run_sim(const SimOptions& options);

void add_sim_command(CLI::App& root, int& exit_code);

}  // namespace navfuse::apps
