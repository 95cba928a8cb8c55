// Maps a device's monotonic clock (e.g. VectorNav TimeStartup, MIP reference time) onto GPS
// time once the device has reported both for the same instant.
//
// Model: gps = device + offset + drift * (device - device_ref). Offset and drift are fitted by
// exponentially weighted least squares over recent pairs, so a slowly drifting crystal is
// followed while a single bad pair moves the mapping little. Pairs that disagree with the current
// fit by more than `reset_threshold_ns` (device reboot, GPS time jump) restart the fit.
#pragma once

#include <cstdint>
#include <optional>

namespace navfuse::time {

class ClockModel {
 public:
  struct Options {
    double forgetting_factor = 0.99;             // weight of older pairs per new pair
    std::int64_t reset_threshold_ns = 50'000'000;  // 50 ms disagreement restarts the fit
  };
  ClockModel() = default;
  explicit ClockModel(const Options& options) : options_(options) {}

  // Records that the device clock read `device_ns` at GPS time `gps_ns`.
  void add_pair(std::int64_t device_ns, std::int64_t gps_ns);
  bool valid() const { return pairs_ > 0; }
  // GPS time for a device time; nullopt until the first pair.
  std::optional<std::int64_t> to_gps(std::int64_t device_ns) const;
  double drift_ppm() const { return drift_ * 1e6; }
  std::uint64_t resets() const { return resets_; }
  void reset();

 private:
  Options options_{};
  std::uint64_t pairs_ = 0;
  std::uint64_t resets_ = 0;
  std::int64_t device_ref_ns_ = 0;  // first device time of the current fit (keeps sums small)
  std::int64_t gps_ref_ns_ = 0;
  // Weighted sums over x = device - device_ref (s), y = gps - device - (gps_ref - device_ref) (s).
  double sw_ = 0, sx_ = 0, sy_ = 0, sxx_ = 0, sxy_ = 0;
  double offset_s_ = 0.0;  // y at x = 0
  double drift_ = 0.0;     // dy/dx, dimensionless
};

}  // namespace navfuse::time
