// Throughput of the UM220-INS front-end (issue #6 goal: >= 200 MB/s) on a mixed stream written
// by the project's own encoder: GYOACC at 10 Hz, NAVTIME/NAVACC/NAVPOS/NAVVEL/GST/GGA/NAVATT at
// 1 Hz, plus the spec's GSA/GSV/RMC/VTG/SNRSTAT/NOTICE examples each second, with 1 % of the
// bytes overwritten at random (fixed seed) so that resynchronisation is on the measured path; the
// stream is repeated to 200 MB before it is corrupted (corrupted_stream.hpp).
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "core/time/gps_time.hpp"
#include "frontends/nmea/framer.hpp"
#include "frontends/unicore/decoder.hpp"
#include "frontends/unicore/encoder.hpp"
#include "tests/bench/corrupted_stream.hpp"

namespace {

using namespace navfuse;

constexpr int kSeconds = 600;
constexpr int kImuPerSecond = 10;
constexpr double kCorruptFraction = 0.01;
constexpr std::size_t kChunkBytes = 4096;  // a typical serial/file read

const char* const kOneHertzExamples[] = {
    "$GPGSA,A,3,02,03,06,09,12,17,19,23,28,25,,,1.34,0.85,1.04,1*1E\r\n",
    "$GPGSV,3,01,11,02,34,277,41,03,16,043,35,05,04,215,35,06,69,333,48,0*57\r\n",
    "$GPGSV,3,02,11,09,25,110,41,12,31,305,43,17,55,116,46,19,76,088,46,0*56\r\n",
    "$GPGSV,3,03,11,23,23,077,40,25,04,328,32,28,05,171,36,0*67\r\n",
    "$GPRMC,060845.00,A,4004.74005,N,11614.19613,E,0.000,,180817,,,A,V*0B\r\n",
    "$GPVTG,,T,,M,0.000,N,0.000,K,A*23\r\n",
    "$SNRSTAT,3,0,0,2*5C\r\n",
    "$NOTICE,1,10000,10000,10000,20,0,FFFF,FFFF,FFFF,1000*29\r\n",
};

std::vector<std::uint8_t> make_stream() {
  frontends::unicore::UnicoreEncoder enc;
  std::vector<std::uint8_t> out;
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> noise(0.0, 0.01);
  const std::int64_t t0 = *time::gps_ns_from_utc({2024, 5, 17, 8, 0, 0.0});
  std::uint32_t ticks = 0;
  for (int s = 0; s < kSeconds; ++s) {
    for (int k = 0; k < kImuPerSecond; ++k) {
      const std::int64_t t = t0 + (s * kImuPerSecond + k) * 100'000'000LL;
      WheelTicks w;
      w.header = {t, TimeSource::kGps, 0, WheelTicks::kValidFrontLeft};
      ticks += 25;
      w.ticks[0] = ticks;
      w.channels = 1;
      enc.encode(w, out);
      ImuSample imu;
      imu.header = {t, TimeSource::kGps, 0, ImuSample::kValidGyro | ImuSample::kValidAccel};
      imu.gyro = {noise(rng), noise(rng), noise(rng)};
      imu.accel = {noise(rng), noise(rng), -9.81 + noise(rng)};
      imu.dt_s = 0.1;
      enc.encode(imu, out);
    }
    const std::int64_t t = t0 + s * 1'000'000'000LL;
    GnssPosition p;
    p.header = {t, TimeSource::kGps, 0, GnssPosition::kValidPosition | GnssPosition::kValidCovariance};
    p.lat_rad = 0.7 + 1e-7 * s;
    p.lon_rad = 2.0;
    p.height_m = 50.0;
    p.cov_ned_m2 = Eigen::Matrix3d::Identity();
    p.fix = GnssFixType::kFix3D;
    enc.encode(p, out);
    GnssVelocity v;
    v.header = {t, TimeSource::kGps, 0, GnssVelocity::kValidVelocity};
    v.vel_ned_mps = {10.0, 1.0, 0.0};
    v.fix = GnssFixType::kFix3D;
    enc.encode(v, out);
    NavSolution n;
    n.header = {t, TimeSource::kGps, 0, NavSolution::kValidPosition | NavSolution::kValidPositionStd |
                                            NavSolution::kValidAttitude | NavSolution::kValidHeading};
    n.mode = NavMode::kNavigation;
    n.lat_rad = p.lat_rad;
    n.lon_rad = p.lon_rad;
    n.height_m = p.height_m;
    n.pos_std_ned_m = {0.5, 0.5, 1.0};
    n.rpy_rad = {0.01, -0.02, 1.0};
    enc.encode(n, out);
    for (const char* e : kOneHertzExamples) out.insert(out.end(), e, e + std::char_traits<char>::length(e));
  }
  bench::repeat_to(out, bench::kCorruptedStreamBytes);
  std::mt19937_64 corrupt(1);
  const auto n_corrupt = static_cast<std::size_t>(static_cast<double>(out.size()) * kCorruptFraction);
  for (std::size_t i = 0; i < n_corrupt; ++i) out[corrupt() % out.size()] = static_cast<std::uint8_t>(corrupt());
  return out;
}

const std::vector<std::uint8_t>& stream() {
  static const std::vector<std::uint8_t> s = make_stream();
  return s;
}

class CountingSink : public frontends::DecodeSink {
 public:
  void on_measurement(const Measurement&) override { ++count; }
  std::size_t count = 0;
};

void BM_UnicoreDecode(benchmark::State& state) {
  const auto& s = stream();
  std::size_t measurements = 0;
  for (auto _ : state) {
    frontends::unicore::UnicoreDecoder dec;
    CountingSink sink;
    for (std::size_t at = 0; at < s.size(); at += kChunkBytes) {
      dec.feed(std::span<const std::uint8_t>(s).subspan(at, std::min(kChunkBytes, s.size() - at)), sink);
    }
    dec.finish(sink);
    measurements = sink.count;
    benchmark::DoNotOptimize(dec.counters().frames);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * s.size()));
  state.counters["measurements"] = static_cast<double>(measurements);
}
BENCHMARK(BM_UnicoreDecode)->Unit(benchmark::kMillisecond);

void BM_UnicoreFramingOnly(benchmark::State& state) {
  const auto& s = stream();
  for (auto _ : state) {
    frontends::nmea::SentenceFramer framer;
    std::size_t frames = 0;
    for (std::size_t at = 0; at < s.size(); at += kChunkBytes) {
      framer.feed(std::span<const std::uint8_t>(s).subspan(at, std::min(kChunkBytes, s.size() - at)),
                  [&](const frontends::nmea::Frame&) { ++frames; });
    }
    benchmark::DoNotOptimize(frames);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * s.size()));
}
BENCHMARK(BM_UnicoreFramingOnly)->Unit(benchmark::kMillisecond);

}  // namespace
