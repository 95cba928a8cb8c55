// `navfuse run --corrections ...?gga=1` against a network-RTK (VRS) caster the test runs, which
// sends no corrections until the rover has told it where it is in a valid NMEA GGA sentence.
// The rover is a simulated VN-300 on a pseudo-terminal (simulator + VN encoder, played at 10x
// real time), which is also the receiver the corrections are written to. Checked: the corrections
// reach the port unchanged once navfuse has a position, the caster was told that position every
// second, and each GGA is the nav solution of its time (the run's own CSV row, to the sentence's
// 1e-6 arc-minute resolution) and the simulated truth of that time (to the filter's accuracy).
#include <gtest/gtest.h>
#include <signal.h>

#include <cmath>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/time/gps_time.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/sim_log.hpp"
#include "tests/integration/test_paths.hpp"
#include "tests/integration/tiny_caster.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 10000;
constexpr const char* kScenario = "rtk_drive";
constexpr double kSeconds = 40.0;  // of the simulated drive: 30 s standing, then moving off
constexpr double kSpeedUp = 10.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kEarthRadius_m = 6378137.0;  // WGS-84 semi-major axis: enough for a tolerance
constexpr std::int64_t kDayNs = 86'400'000'000'000LL;
// RTK fixed GNSS (centimetre noise): the solution's error on this drive's first 40 s, measured
// up to 5 cm horizontally and 8 cm in height; the bounds leave room, and still fail the vehicle's
// reference point (0.9 m away).
constexpr double kHorizontalTolerance_m = 0.15;
constexpr double kHeightTolerance_m = 0.25;
// NMEA minutes carry 6 decimals: half a unit is the rounding, the CSV's 1e-10 deg next to nothing.
constexpr double kNmeaHalfUnit_deg = 0.5e-6 / 60.0 + 1e-10;

struct GgaFields {
  std::int64_t time_of_day_ns = 0;  // UTC
  double lat_deg = 0.0, lon_deg = 0.0;
  double height_m = 0.0;  // ellipsoidal: altitude above the geoid plus the geoid separation
  int quality = 0;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string f; std::getline(in, f, sep);) out.push_back(f);
  return out;
}

// "ddmm.mmmmmm" / "dddmm.mmmmmm" with its hemisphere, in degrees.
double nmea_degrees(const std::string& field, const std::string& hemisphere, int degree_digits) {
  const double deg = std::stod(field.substr(0, static_cast<std::size_t>(degree_digits))) +
                     std::stod(field.substr(static_cast<std::size_t>(degree_digits))) / 60.0;
  return hemisphere == "S" || hemisphere == "W" ? -deg : deg;
}

std::optional<GgaFields> parse_gga(const std::string& sentence) {
  const std::vector<std::string> f = split(sentence, ',');
  if (f.size() < 12 || f[1].size() < 6 || f[2].empty() || f[4].empty() || f[9].empty()) return std::nullopt;
  GgaFields g;
  const double tod_s = std::stod(f[1].substr(0, 2)) * 3600 + std::stod(f[1].substr(2, 2)) * 60 + std::stod(f[1].substr(4));
  g.time_of_day_ns = std::llround(tod_s * 1e9);
  g.lat_deg = nmea_degrees(f[2], f[3], 2);
  g.lon_deg = nmea_degrees(f[4], f[5], 3);
  g.quality = std::stoi(f[6]);
  g.height_m = std::stod(f[9]) + (f[11].empty() ? 0.0 : std::stod(f[11]));
  return g;
}

struct CsvPose {
  std::int64_t time_ns = 0;  // GPS
  double lat_deg = 0.0, lon_deg = 0.0;
};

// The run's --csv rows with a position (columns: time, time source, mode, lat, lon, ...).
std::vector<CsvPose> csv_poses(const std::string& path) {
  std::vector<CsvPose> poses;
  std::istringstream in(read_text_file(path));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::vector<std::string> f = split(line, ',');
    if (f.size() < 5 || f[3] == "nan") continue;
    const auto dot = f[0].find('.');
    poses.push_back({std::stoll(f[0].substr(0, dot)) * 1'000'000'000LL + std::stoll(f[0].substr(dot + 1)),
                     std::stod(f[3]), std::stod(f[4])});
  }
  return poses;
}

// The true position of the GNSS antenna at every IMU sample of the first `seconds` of
// `scenario` (pose epochs are IMU samples). The antenna's: the test's config gives navfuse no
// lever arm, so its solution is the antenna's position (0.9 m from the vehicle's reference point
// on this scenario). The lever arm is turned into north/east/down on a sphere, millimetres off
// for a metre.
std::map<std::int64_t, geo::Llh> antenna_truth_by_time(std::string_view scenario, double seconds) {
  sim::Simulator simulator(sim::make_scenario(scenario));
  const Eigen::Vector3d lever_m = simulator.scenario().gnss.lever_arm_m;
  const std::int64_t end_ns = simulator.start_time_ns() + static_cast<std::int64_t>(seconds * 1e9);
  std::map<std::int64_t, geo::Llh> truth;
  Measurement m;
  while (simulator.next(m) && simulator.delivery_time_ns() <= end_ns) {
    if (kind_of(m) != MeasurementKind::kImu) continue;
    const sim::TruthSample& t = simulator.truth();
    const Eigen::Vector3d ned_m = t.q_nb * lever_m;
    geo::Llh a = t.llh;
    a.lat_rad += ned_m.x() / kEarthRadius_m;
    a.lon_rad += ned_m.y() / (kEarthRadius_m * std::cos(t.llh.lat_rad));
    a.height_m -= ned_m.z();
    truth[t.time_ns] = a;
  }
  return truth;
}

double horizontal_m(double lat1_deg, double lon1_deg, double lat2_deg, double lon2_deg) {
  const double north = (lat1_deg - lat2_deg) * kPi / 180.0 * kEarthRadius_m;
  const double east = (lon1_deg - lon2_deg) * kPi / 180.0 * kEarthRadius_m * std::cos(lat1_deg * kPi / 180.0);
  return std::hypot(north, east);
}

class RunCorrectionsGgaTest : public ScratchDirTest, public ::testing::WithParamInterface<Protocol> {};

TEST_P(RunCorrectionsGgaTest, VrsCasterGetsTheNavPositionBeforeAndWhileItSends) {
  const SimLog log = make_sim_log(kScenario, "vn", kSeconds);
  const std::vector<std::uint8_t> data = correction_bytes(6000);
  TinyCaster caster(GetParam(), data, /*require_gga=*/true);
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\noutput:\n  rate_hz: 50\n");
  const std::string summary = (dir_ / "summary.json").string();
  const std::string csv = (dir_ / "run.csv").string();
  PtyDevice device((dir_ / "ttyVN").string());
  ChildProcess nav({navfuse_binary(), "run", "--config", config, "--in", "vn:serial:" + device.link() + "?baud=921600",
                    "--corrections", caster_source(GetParam(), caster.port(), kCasterMount, "gga=1"),
                    "--corrections-to", "0", "--csv", csv, "--summary-json", summary},
                   (dir_ / "nav.log").string());
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  device.release_slave();

  // The device streams its drive while whatever navfuse writes to its port is collected.
  std::vector<std::uint8_t> got;
  std::thread receiver([&] { got = receive(device, data.size(), kTimeoutMs + 5000); });
  const bool played = play(device, log, 0, log.pieces.size(), kSpeedUp);
  receiver.join();
  ASSERT_TRUE(played);
  EXPECT_EQ(got.size(), data.size()) << nav.output();
  EXPECT_TRUE(got == data) << "the corrections changed on the way";
  EXPECT_EQ(caster.sent_before_gga(), 0u);
  // Uploads go on after the corrections flow: at least three, a second apart.
  const io::Deadline more(kTimeoutMs);
  while (caster.ggas().size() < 3 && !more.expired()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  nav.send(SIGTERM);
  ASSERT_EQ(nav.wait_exit(kTimeoutMs).value_or(-1), 0) << nav.output();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the caster takes the last lines

  const std::vector<TinyCaster::Gga> ggas = caster.ggas();
  ASSERT_GE(ggas.size(), 3u);
  EXPECT_TRUE(caster.bad_lines().empty()) << caster.bad_lines().front();
  if (GetParam() == Protocol::kNtrip1) {
    EXPECT_TRUE(caster.request().starts_with(std::string("GET /") + kCasterMount + " HTTP/1.0\r\n")) << caster.request();
  }
  for (std::size_t i = 1; i < ggas.size(); ++i) {
    const double gap_s = std::chrono::duration<double>(ggas[i].received - ggas[i - 1].received).count();
    EXPECT_GE(gap_s, 0.9) << i;
    EXPECT_LE(gap_s, 2.5) << i;  // 1 s, plus the forwarder's 0.1 s wake and a loaded machine
  }
  const auto j = nlohmann::json::parse(read_text_file(summary));
  EXPECT_EQ(j["corrections"]["gga_sent"].get<std::size_t>(), ggas.size()) << j.dump();
  EXPECT_EQ(j["corrections"]["bytes_forwarded"].get<std::size_t>(), data.size()) << j.dump();

  // Each GGA is the solution at its time: the CSV row of that epoch (the sentence's time has
  // 10 ms steps, the 50 Hz poses 20 ms), and the simulated truth there.
  const std::vector<CsvPose> poses = csv_poses(csv);
  ASSERT_FALSE(poses.empty());
  const std::map<std::int64_t, geo::Llh> truth = antenna_truth_by_time(kScenario, kSeconds);
  double worst_truth_m = 0.0, worst_height_m = 0.0;
  for (const TinyCaster::Gga& g : ggas) {
    const std::optional<GgaFields> f = parse_gga(g.sentence);
    ASSERT_TRUE(f.has_value()) << g.sentence;
    EXPECT_GE(f->quality, 1) << g.sentence;  // never a position the filter did not have
    const CsvPose* match = nullptr;
    for (const CsvPose& p : poses) {
      const std::int64_t tod = (time::unix_ns_from_gps_ns(p.time_ns) % kDayNs + kDayNs) % kDayNs;
      if (std::llabs(tod - f->time_of_day_ns) <= 10'000'000 &&
          std::abs(p.lat_deg - f->lat_deg) <= kNmeaHalfUnit_deg && std::abs(p.lon_deg - f->lon_deg) <= kNmeaHalfUnit_deg) {
        match = &p;
      }
    }
    ASSERT_NE(match, nullptr) << "no pose of the run at the time and place of " << g.sentence;
    const auto t = truth.lower_bound(match->time_ns);
    ASSERT_NE(t, truth.end()) << g.sentence;
    const double error_m = horizontal_m(f->lat_deg, f->lon_deg, t->second.lat_rad * 180.0 / kPi,
                                        t->second.lon_rad * 180.0 / kPi);
    const double height_error_m = f->height_m - t->second.height_m;
    worst_truth_m = std::max(worst_truth_m, error_m);
    worst_height_m = std::max(worst_height_m, std::abs(height_error_m));
    EXPECT_LT(error_m, kHorizontalTolerance_m) << g.sentence;
    EXPECT_LT(std::abs(height_error_m), kHeightTolerance_m) << g.sentence;
  }
  std::printf("%zu GGA uploads (first in the %s); farthest from the simulated antenna: %.3f m horizontally, "
              "%.3f m in height\n", ggas.size(), ggas.front().in_header ? "Ntrip-GGA header" : "stream", worst_truth_m,
              worst_height_m);
}

INSTANTIATE_TEST_SUITE_P(Casters, RunCorrectionsGgaTest, ::testing::Values(Protocol::kNtrip2, Protocol::kNtrip1),
                         [](const auto& info) { return protocol_name(info.param); });

}  // namespace
}  // namespace navfuse::test
