#include "apps/simcmd/sim_command.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "apps/common/command_error.hpp"
#include "apps/common/command_help.hpp"
#include "apps/common/frontend_registry.hpp"
#include "apps/common/interrupt_signals.hpp"
#include "apps/output/output_paths.hpp"
#include "apps/output/output_file.hpp"
#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"
#include "apps/sim/truth_csv.hpp"
#include "apps/simcmd/device_solution_model.hpp"

namespace navfuse::apps {
namespace {

bool is_odometry(MeasurementKind k) {
  return k == MeasurementKind::kWheelSpeed || k == MeasurementKind::kVehicleSpeed || k == MeasurementKind::kWheelTicks;
}

const frontends::FrontendInfo& frontend_or_throw(std::string_view format) {
  const auto* f = find_frontend(format);
  if (f == nullptr) {
    throw CommandError("unknown or unavailable format '" + std::string(format) + "' (available: " + known_formats() + ")");
  }
  return *f;
}

// The truth CSV through the simulator's writer, moved into the output file in blocks.
class TruthSink {
 public:
  explicit TruthSink(const std::string& path) : file_(path), writer_(text_) {}
  void write(const sim::TruthSample& s) {
    writer_.write(s);
    ++rows_;
    if (rows_ % 1024 == 0) drain();
  }
  void commit() {
    drain();
    file_.commit();
  }
  std::uint64_t rows() const { return rows_; }

 private:
  void drain() {
    file_.write(text_.str());
    text_.str(std::string());
  }
  OutputFile file_;
  std::ostringstream text_;
  sim::TruthCsvWriter writer_;
  std::uint64_t rows_ = 0;
};

// --imu-time-offset, --imu-mounting over the scenario's IMU; --no-gnss-velocity over its receiver;
// --nonslip-point over its vehicle.
void apply_installation(const SimOptions& options, sim::Scenario& scenario) {
  if (!options.gnss_velocity) scenario.gnss.velocity = false;
  if (options.imu_time_offset_s) scenario.imu.time_offset_s = *options.imu_time_offset_s;
  if (options.imu_mounting_rpy_deg) {
    const std::vector<double>& rpy = *options.imu_mounting_rpy_deg;
    if (rpy.size() != 3) throw CommandError("--imu-mounting takes roll,pitch,yaw (3 values in degrees)");
    scenario.imu.mounting_rpy_deg = {rpy[0], rpy[1], rpy[2]};
  }
  if (options.nonslip_point_m) {
    const std::vector<double>& p = *options.nonslip_point_m;
    if (p.size() != 3 || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw CommandError("--nonslip-point takes x,y,z (3 finite values in metres)");
    }
    scenario.trajectory.nonslip_point_m = {p[0], p[1], p[2]};
  }
}

}  // namespace

SimReport run_sim(const SimOptions& options) {
  sim::Scenario scenario;
  try {
    scenario = sim::make_scenario(options.scenario);
  } catch (const std::invalid_argument& e) {
    throw CommandError(e.what());
  }
  if (options.seed) scenario.seed = *options.seed;
  apply_installation(options, scenario);
  if (options.wheel_tick_m > 0.0) {
    scenario.wheel.vehicle_ticks = scenario.wheel.vehicle_speed;
    scenario.wheel.vehicle_speed = false;
    scenario.wheel.m_per_tick = options.wheel_tick_m;
  }
  const frontends::FrontendInfo& frontend = frontend_or_throw(options.format);
  scenario.imu.convention = frontend.imu_increments;
  const frontends::FrontendInfo* wheel_frontend = nullptr;
  if (!options.wheel_out_path.empty()) {
    wheel_frontend = odometry_input_frontend();
    if (wheel_frontend == nullptr) throw CommandError("--wheel-out: no front-end carries wheel / vehicle speed inputs");
  }

  DeviceErrorClass device = device_error_class(frontend, scenario.imu.rate_hz);
  if (options.device_rate_hz) device.rate_hz = *options.device_rate_hz;
  std::optional<DeviceSolutionModel> device_model;
  if (device.rate_hz > 0.0) device_model.emplace(device, scenario.start_time_ns, scenario.seed);

  std::unique_ptr<sim::Simulator> simulator;
  try {
    simulator = std::make_unique<sim::Simulator>(scenario);
  } catch (const std::invalid_argument& e) {
    throw CommandError("scenario '" + options.scenario + "': " + e.what());
  }

  check_output_paths({}, {{"--out", options.out_path},
                          {"--truth", options.truth_path},
                          {"--wheel-out", options.wheel_out_path}});
  OutputFile out(options.out_path);
  std::optional<OutputFile> wheel_out;
  if (wheel_frontend) wheel_out.emplace(options.wheel_out_path);
  std::optional<TruthSink> truth;
  if (!options.truth_path.empty()) truth.emplace(options.truth_path);

  auto encoder = frontend.make_encoder();
  auto wheel_encoder = wheel_frontend ? wheel_frontend->make_encoder() : nullptr;
  std::vector<std::uint8_t> bytes;
  bytes.reserve(4096);
  SimReport report;
  if (wheel_frontend) report.wheel_format = wheel_frontend->format;
  const auto emit = [&](const Measurement& m, frontends::MeasurementEncoder& enc, OutputFile& file,
                        std::map<std::string, std::uint64_t>& written) {
    bytes.clear();
    const std::string kind(to_string(kind_of(m)));
    if (!enc.encode(m, bytes)) {
      ++report.dropped[kind];
      return;
    }
    file.write(bytes);
    ++written[kind];
  };

  Measurement m;
  NavSolution solution;
  while (simulator->next(m)) {
    if (options.interrupt && (report.interrupted_by = options.interrupt->load(std::memory_order_relaxed)) != 0) break;
    const MeasurementKind kind = kind_of(m);
    if (wheel_encoder && is_odometry(kind)) {
      emit(m, *wheel_encoder, *wheel_out, report.wheel_written);
      continue;
    }
    emit(m, *encoder, out, report.written);
    if (kind != MeasurementKind::kImu) continue;
    if (truth) truth->write(simulator->truth());
    if (device_model && device_model->step(simulator->truth(), solution)) emit(solution, *encoder, out, report.written);
  }

  out.commit();
  report.out_bytes = out.bytes_written();
  if (wheel_out) {
    wheel_out->commit();
    report.wheel_bytes = wheel_out->bytes_written();
  }
  if (truth) {
    truth->commit();
    report.truth_rows = truth->rows();
  }
  return report;
}

namespace {

void print_report(const SimOptions& o, const SimReport& r, std::ostream& os) {
  const auto counts = [&](const std::map<std::string, std::uint64_t>& c) {
    for (const auto& [kind, n] : c) os << " " << kind << "=" << n;
  };
  os << o.out_path << " [" << o.format << "]: " << r.out_bytes << " bytes;";
  counts(r.written);
  os << "\n";
  if (!o.wheel_out_path.empty()) {
    os << o.wheel_out_path << " [" << r.wheel_format << "]: " << r.wheel_bytes << " bytes;";
    counts(r.wheel_written);
    os << "\n";
  }
  if (!o.truth_path.empty()) os << o.truth_path << ": " << r.truth_rows << " truth rows\n";
  if (r.interrupted_by != 0) {
    os << "interrupted by signal " << r.interrupted_by << ": stopped early, the logs hold what was simulated\n";
  }
  if (!r.dropped.empty()) {
    os << "not carried by " << o.format << " (dropped):";
    counts(r.dropped);
    os << "\n";
  }
}

}  // namespace

void add_sim_command(CLI::App& root, int& exit_code) {
  struct Args {
    SimOptions options;
    std::uint64_t seed = 0;
    double device_rate_hz = -1.0;
    double imu_time_offset_s = 0.0;
    std::vector<double> imu_mounting_rpy_deg;
    std::vector<double> nonslip_point_m;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  SimOptions& o = args->options;
  CLI::App* sub = root.add_subcommand("sim", "Simulate a scenario and write it as a device log");
  std::string scenarios;
  for (std::string_view n : sim::scenario_names()) scenarios += (scenarios.empty() ? "" : ", ") + std::string(n);
  sub->add_option("--scenario", o.scenario, "Scenario name: " + scenarios)->required();
  sub->add_option("--format", o.format, "Device protocol of the log")
      ->required()
      ->check(CLI::IsMember(writable_formats()));
  sub->add_option("--out", o.out_path, "Device log to write")->required();
  sub->add_option("--truth", o.truth_path, "Also write the truth as CSV");
  CLI::Option* seed = sub->add_option("--seed", args->seed, "Random seed (default: the scenario's)");
  sub->add_option("--wheel-out", o.wheel_out_path, "Write wheel/vehicle speed to this FusionEngine log instead");
  sub->add_option("--wheel-ticks", o.wheel_tick_m,
                  "Odometer as a vehicle tick counter of this many metres per tick instead of a speed")
      ->check(CLI::Range(1e-6, 10.0));
  sub->add_option("--device-rate", args->device_rate_hz, "Device INS solution rate in Hz (0: none)")
      ->check(CLI::NonNegativeNumber);
  CLI::Option* time_offset = sub->add_option("--imu-time-offset", args->imu_time_offset_s,
                  "IMU clock offset in s: samples stamped this much before their true time (default: the scenario's)")
      ->check(CLI::Range(-1.0, 1.0));
  CLI::Option* mounting = sub->add_option("--imu-mounting", args->imu_mounting_rpy_deg,
                  "IMU mounting sensor -> vehicle roll,pitch,yaw in deg (default: the scenario's)")
      ->delimiter(',')
      ->expected(3);
  CLI::Option* nonslip = sub->add_option("--nonslip-point", args->nonslip_point_m,
                  "Point of the vehicle that does not slip sideways (a car's rear-axle centre), "
                  "x,y,z in m from the IMU, vehicle frame (default: the IMU)")
      ->delimiter(',')
      ->expected(3);
  sub->add_flag("!--no-gnss-velocity", o.gnss_velocity,
                "The receiver reports positions only (as an RTKLIB .pos without velocity columns)");
  add_quiet_flag(sub, args->quiet, "report of what was written");
  add_examples(sub, {{"a short drive as a CV7 (MIP) log, with its truth",
                      "navfuse sim --scenario drive_short --format mip --out drive.mip --truth truth.csv"},
                     {"a drive with GNSS outages as VN-300 binary, the wheel speeds in a FusionEngine log",
                      "navfuse sim --scenario drive_outage --format vn --out drive.vnb --wheel-out wheel.p1log"}});
  sub->callback([args, seed, time_offset, mounting, nonslip, &exit_code] {
    if (seed->count() > 0) args->options.seed = args->seed;
    if (args->device_rate_hz >= 0.0) args->options.device_rate_hz = args->device_rate_hz;
    const InterruptSignals signals;
    args->options.interrupt = &InterruptSignals::received();
    if (time_offset->count() > 0) args->options.imu_time_offset_s = args->imu_time_offset_s;
    if (mounting->count() > 0) args->options.imu_mounting_rpy_deg = args->imu_mounting_rpy_deg;
    if (nonslip->count() > 0) args->options.nonslip_point_m = args->nonslip_point_m;
    const SimReport report = run_sim(args->options);
    if (!args->quiet || report.interrupted_by != 0) print_report(args->options, report, std::cout);
    exit_code = report.interrupted_by != 0 ? interrupted_exit_code(report.interrupted_by) : 0;
  });
}

}  // namespace navfuse::apps
