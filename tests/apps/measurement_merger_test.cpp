// Merging logs by measurement time: two FusionEngine logs written by the front-end's encoder
// (IMU in one, vehicle speed in the other) come out as one time-ordered stream, whatever the
// chunk size; a cut-off last frame is an error naming the file unless allowed.
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "apps/common/command_error.hpp"
#include "apps/fusion/measurement_merger.hpp"
#include "frontends/fusionengine/frontend.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

using testing::read_bytes;
using testing::scratch_dir;

constexpr std::int64_t kT0 = 1'400'000'000'000'000'000LL;
constexpr std::int64_t kMs = 1'000'000;

void write_log(const std::filesystem::path& path, const std::vector<Measurement>& ms) {
  auto enc = frontends::fusionengine::frontend().make_encoder();
  std::vector<std::uint8_t> bytes;
  for (const auto& m : ms) ASSERT_TRUE(enc->encode(m, bytes));
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
}

ImuSample imu_at(std::int64_t t) {
  ImuSample s;
  s.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
  s.accel = {0.0, 0.0, -9.8};
  return s;
}

VehicleSpeed speed_at(std::int64_t t, double v) {
  VehicleSpeed s;
  s.header = {t, TimeSource::kGps, 0, VehicleSpeed::kValidSpeed};
  s.speed_mps = v;
  s.is_signed = true;
  s.gear = Gear::kForward;
  return s;
}

struct Logs {
  std::filesystem::path imu, speed;
};

Logs make_logs(const std::filesystem::path& dir) {
  std::vector<Measurement> imu, speed;
  for (int k = 0; k < 10; ++k) imu.emplace_back(imu_at(kT0 + k * 10 * kMs));
  speed.emplace_back(speed_at(kT0 + 3 * kMs, 0.5));
  for (int k = 0; k < 10; ++k) speed.emplace_back(speed_at(kT0 + (10 * k + 5) * kMs, 1.0 + k));
  Logs logs{dir / "imu.p1log", dir / "speed.p1log"};
  write_log(logs.imu, imu);
  write_log(logs.speed, speed);
  return logs;
}

std::vector<InputSpec> specs(const Logs& logs) {
  const auto* fe = &frontends::fusionengine::frontend();
  return {{logs.imu.string(), fe, false, std::nullopt, {}, nullptr}, {logs.speed.string(), fe, false, std::nullopt, {}, nullptr}};
}

TEST(MeasurementMerger, MergesByTimeForAnyChunkSize) {
  const Logs logs = make_logs(scratch_dir());
  for (std::size_t chunk : {std::size_t{7}, std::size_t{64}, std::size_t{1 << 16}}) {
    MeasurementMerger merger(specs(logs), {.chunk_bytes = chunk});
    std::vector<Measurement> out;
    while (const Measurement* m = merger.next()) out.push_back(*m);
    ASSERT_EQ(out.size(), 21u) << "chunk " << chunk;
    for (std::size_t i = 1; i < out.size(); ++i) {
      EXPECT_LE(header_of(out[i - 1]).time_ns, header_of(out[i]).time_ns) << i;
    }
    // 3 ms speed, 0 ms IMU first; then IMU at 10k ms and speed at 10k+5 ms alternate.
    EXPECT_EQ(kind_of(out[0]), MeasurementKind::kImu);
    EXPECT_EQ(kind_of(out[1]), MeasurementKind::kVehicleSpeed);
    EXPECT_EQ(header_of(out[1]).time_ns, kT0 + 3 * kMs);
    for (const auto& x : out) {
      EXPECT_EQ(header_of(x).stream_id, kind_of(x) == MeasurementKind::kImu ? 0 : 1);
      EXPECT_EQ(header_of(x).time_source, TimeSource::kGps);
    }
    EXPECT_EQ(merger.decoded()[static_cast<std::size_t>(MeasurementKind::kImu)], 10u);
    EXPECT_EQ(merger.decoded()[static_cast<std::size_t>(MeasurementKind::kVehicleSpeed)], 11u);
    const auto inputs = merger.input_summaries();
    ASSERT_EQ(inputs.size(), 2u);
    EXPECT_EQ(inputs[0].counters.frames, 10u);
    EXPECT_EQ(inputs[1].counters.frames, 11u);
    EXPECT_EQ(merger.bytes_read(), merger.total_bytes());
  }
}

TEST(MeasurementMerger, TruncatedInputIsAnErrorNamingTheFile) {
  const Logs logs = make_logs(scratch_dir());
  auto bytes = read_bytes(logs.speed);
  bytes.resize(bytes.size() - 3);
  std::ofstream(logs.speed, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  try {
    MeasurementMerger merger(specs(logs), {});
    while (merger.next() != nullptr) {
    }
    FAIL() << "expected an error";
  } catch (const CommandError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(logs.speed.string()), std::string::npos) << what;
    EXPECT_NE(what.find("truncated"), std::string::npos) << what;
  }
  MeasurementMerger lenient(specs(logs), {.allow_truncated = true});
  int n = 0;
  while (lenient.next() != nullptr) ++n;
  EXPECT_EQ(n, 20);  // the cut-off speed sample is lost
  ASSERT_EQ(lenient.truncated_inputs().size(), 1u);
}

}  // namespace
}  // namespace navfuse::apps
