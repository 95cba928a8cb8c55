// The fusion loop on a stream of frames with random times (issue 15: time faults and gaps). Each
// input record is one measurement (IMU rates or increments, GNSS position / velocity, wheel speed)
// whose time steps from the last by a fuzzed amount: forward or back, a sample period or a year,
// on GPS or the device's own clock. It goes through FusionRunner::offer() as replay hands it a
// log (time-base gate -> IMU time guard -> filter, with its lost-frame bridging and time_gap
// restarts), so the sanitizers watch that path, and at the end every kind's counts must add up:
// decoded = used + rejected + pending_at_end.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <cstdio>

#include "apps/common/summary.hpp"
#include "apps/fusion/fusion_runner.hpp"
#include "core/config/config.hpp"
#include "filter/filter_options.hpp"

namespace {

using namespace navfuse;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool has(std::size_t n) const { return size_ - pos_ >= n; }
  std::uint8_t u8() { return data_[pos_++]; }
  std::int32_t i32() {
    std::int32_t v;
    std::memcpy(&v, data_ + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  double small(double scale) { return static_cast<double>(static_cast<std::int8_t>(u8())) * scale; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// The step from the previous measurement: mostly a few IMU periods, sometimes far (a lost second,
// a wild timestamp a day or years away), forward or back.
std::int64_t time_step_ns(std::uint8_t scale, std::int32_t raw) {
  switch (scale % 8) {
    case 0: return static_cast<std::int64_t>(raw % 4) * 5'000'000;              // 0..3 periods at 200 Hz
    case 1: return static_cast<std::int64_t>(raw % 1000) * 1'000;               // sub-millisecond jitter
    case 2: return static_cast<std::int64_t>(raw % 20) * 100'000'000;           // lost frames, up to 2 s
    case 3: return static_cast<std::int64_t>(raw) * 1'000'000;                  // +-24 days
    case 4: return static_cast<std::int64_t>(raw) * 1'000'000'000;              // +-68 years
    default: return 5'000'000;                                                  // steady 200 Hz
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const filter::FilterOptions kOptions =
      filter::options_from_config(config::defaults_for(config::DeviceProfile::kVn300));
  apps::FusionObserver observer;
  apps::FusionRunner runner(kOptions, {.output_rate_hz = 50.0, .solutions = apps::FusionRunner::Solutions::kPoses,
                                       .gnss_outages = {}},
                            observer);
  Reader in(data, size);
  std::int64_t t_ns = 1'400'000'000'000'000'000;  // 2024 in GPS time
  while (in.has(13)) {  // the longest record
    const std::uint8_t kind = in.u8();
    // A step that would leave int64 nanoseconds is not taken (the harness's own arithmetic).
    if (std::int64_t next = 0; !__builtin_add_overflow(t_ns, time_step_ns(in.u8(), in.i32()), &next)) t_ns = next;
    MeasurementHeader header{.time_ns = t_ns,
                             .time_source = (kind & 0x80) ? TimeSource::kDeviceMonotonic : TimeSource::kGps,
                             .stream_id = 0,
                             .valid = 0};
    switch (kind % 5) {
      case 0:
      case 1: {  // IMU near rest, rates or increments over a fuzzed interval
        ImuSample s;
        header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
        s.header = header;
        s.quantity = kind % 5 == 0 ? ImuQuantity::kRates : ImuQuantity::kIncrements;
        s.dt_s = 0.005 * (1 + in.u8() % 4);
        const double scale = s.quantity == ImuQuantity::kRates ? 1.0 : s.dt_s;
        s.gyro = Eigen::Vector3d(in.small(1e-3), in.small(1e-3), in.small(1e-2)) * scale;
        s.accel = Eigen::Vector3d(in.small(0.05), in.small(0.05), -9.8 + in.small(0.05)) * scale;
        runner.offer(s);
        break;
      }
      case 2: {
        GnssPosition p;
        header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
        p.header = header;
        p.lat_rad = 0.8 + in.small(1e-7);
        p.lon_rad = 0.2 + in.small(1e-7);
        p.height_m = 100.0 + in.small(0.1);
        p.fix = GnssFixType::kFix3D;
        p.num_sats = 10;
        runner.offer(p);
        break;
      }
      case 3: {
        GnssVelocity v;
        v.header = header;
        v.header.valid = 1;
        v.vel_ned_mps = Eigen::Vector3d(in.small(0.05), in.small(0.05), in.small(0.05));
        v.fix = GnssFixType::kFix3D;
        runner.offer(v);
        break;
      }
      default: {
        WheelSpeeds w;
        w.header = header;
        w.header.valid = ~0u;
        runner.offer(w);
        break;
      }
    }
  }
  runner.finish();
  apps::Summary summary;
  runner.fill_summary(summary, 1.0);
  for (const apps::KindSummary& k : summary.kinds) {
    std::uint64_t rejected = 0;
    for (const auto& [reason, n] : k.rejected) rejected += n;
    if (k.decoded != k.used + rejected + k.pending) {
      std::fprintf(stderr, "counts do not add up: decoded %llu, used %llu, rejected %llu, pending %llu\n",
                   static_cast<unsigned long long>(k.decoded), static_cast<unsigned long long>(k.used),
                   static_cast<unsigned long long>(rejected), static_cast<unsigned long long>(k.pending));
      __builtin_trap();  // the counts must add up
    }
  }
  return 0;
}
