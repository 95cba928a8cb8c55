// The real MicroStrain capture (../shared/captures/mip_sdk_mip_data.bin: IMU and magnetometer,
// no GNSS) with magnetometer aiding switched on: the filter levels, takes its heading from the
// magnetometer and holds it (issue 17: "magnetometer alignment on the shared real MicroStrain
// capture reaches a heading"). The reference is the device's own filter heading in the same
// capture (0x82 Euler angles), decoded independently of the replay. The capture's location is
// unknown, so no declination is known: 0 is configured, and the device's own heading comes from
// its own declination setting and magnetometer calibration, which the capture does not carry:
// agreement is therefore asserted loosely and printed. The heading std is 10 deg, what an
// uncalibrated magnetometer (no hard-iron values for this unit) is worth: with 5 deg a third of
// the readings failed the gate while the device was turned by hand. Measured 2026-11-24: mean
// -0.8 deg, RMS 8.3 deg, max 14.2 deg over 695 epochs. Skips without the shared captures.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>
#include <sstream>

#include "apps/replay/replay.hpp"
#include "frontends/mip/decoder.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

const std::filesystem::path kCapture = std::filesystem::path(NAVFUSE_SHARED_DIR) / "captures/mip_sdk_mip_data.bin";

// Device filter yaw (deg) by time (ns), straight from the decoder.
std::map<std::int64_t, double> device_yaw_deg() {
  std::ifstream in(kCapture, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  struct Sink final : frontends::DecodeSink {
    std::map<std::int64_t, double> yaw;
    void on_measurement(const Measurement& m) override {
      if (const auto* s = std::get_if<NavSolution>(&m)) yaw[s->header.time_ns] = s->rpy_rad.z() * 180.0 / M_PI;
    }
  } sink;
  frontends::mip::MipDecoder decoder;
  decoder.feed(bytes, sink);
  decoder.finish(sink);
  return sink.yaw;
}

TEST(MipCaptureMagnetometer, HeadingFromTheMagnetometerAgreesWithTheDevice) {
  if (!std::filesystem::exists(kCapture)) GTEST_SKIP() << "capture not present";
  const auto dir = testing::scratch_dir();
  const std::filesystem::path config = dir / "cv7_mag.yaml";
  std::ofstream(config) << "device: cv7\nmagnetometer:\n  heading_std_deg: 10\n  declination_deg: 0\n"
                        << "output:\n  rate_hz: 0\n";
  ReplayOptions o;
  o.config_path = config.string();
  o.inputs = {"mip:" + kCapture.string()};
  o.csv_out = (dir / "pose.csv").string();
  const ReplayResult r = run_replay(o);
  ASSERT_TRUE(r.summary.run);
  const auto& modes = r.summary.run->modes_reached;
  ASSERT_NE(std::find(modes.begin(), modes.end(), "ahrs"), modes.end());
  const KindSummary& mag = r.summary.kinds[static_cast<std::size_t>(MeasurementKind::kMagnetometer)];
  EXPECT_EQ(mag.decoded, 3578u);  // capture README / MIP capture test: 3578 (0x80,0x06) fields
  EXPECT_GT(mag.used, 3000u);

  const std::map<std::int64_t, double> device = device_yaw_deg();
  ASSERT_EQ(device.size(), 714u);
  // navfuse's heading in AHRS by time: its poses are at the IMU times (every 8 ms), the device's
  // 0x82 at its own (4 ms apart from the nearest IMU time): compared with the nearest pose.
  std::map<std::int64_t, double> navfuse_yaw;
  std::ifstream csv(o.csv_out);
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    std::stringstream row(line);
    std::vector<std::string> f;
    for (std::string c; std::getline(row, c, ',');) f.push_back(c);
    if (f.size() < 12 || f[2] != "ahrs") continue;
    navfuse_yaw[static_cast<std::int64_t>(std::llround(std::stod(f[0]) * 1e9))] = std::stod(f[11]);
  }
  double sum = 0.0, sum_sq = 0.0, worst = 0.0;
  int n = 0;
  for (const auto& [t_ns, yaw_deg] : device) {
    auto it = navfuse_yaw.lower_bound(t_ns - 4'000'000);
    if (it == navfuse_yaw.end() || it->first > t_ns + 4'000'000) continue;
    const double d = std::remainder(it->second - yaw_deg, 360.0);
    sum += d;
    sum_sq += d * d;
    worst = std::max(worst, std::abs(d));
    ++n;
  }
  ASSERT_GT(n, 500);
  const double mean = sum / n, rms = std::sqrt(sum_sq / n);
  std::printf("navfuse magnetic heading vs the device's 0x82 heading over %d epochs: mean %+.1f deg, "
              "RMS %.1f deg, max %.1f deg\n", n, mean, rms, worst);
  // A heading from the magnetometer, not an arbitrary one: within 20 deg of the device's.
  EXPECT_LT(rms, 20.0);
}

}  // namespace
}  // namespace navfuse::apps
