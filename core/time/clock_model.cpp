#include "core/time/clock_model.hpp"

#include <cmath>

namespace navfuse::time {

void ClockModel::reset() {
  pairs_ = 0;
  sw_ = sx_ = sy_ = sxx_ = sxy_ = 0.0;
  offset_s_ = drift_ = 0.0;
}

void ClockModel::add_pair(std::int64_t device_ns, std::int64_t gps_ns) {
  if (pairs_ > 0) {
    const auto predicted = to_gps(device_ns);
    const std::int64_t err = gps_ns - *predicted;
    if (err > options_.reset_threshold_ns || err < -options_.reset_threshold_ns) {
      reset();
      ++resets_;
    }
  }
  if (pairs_ == 0) {
    device_ref_ns_ = device_ns;
    gps_ref_ns_ = gps_ns;
  }
  // Work relative to the first pair so the sums stay well conditioned in double.
  const double x = static_cast<double>(device_ns - device_ref_ns_) * 1e-9;
  const double y = static_cast<double>((gps_ns - gps_ref_ns_) - (device_ns - device_ref_ns_)) * 1e-9;
  const double lambda = options_.forgetting_factor;
  sw_ = lambda * sw_ + 1.0;
  sx_ = lambda * sx_ + x;
  sy_ = lambda * sy_ + y;
  sxx_ = lambda * sxx_ + x * x;
  sxy_ = lambda * sxy_ + x * y;
  ++pairs_;
  // Weighted linear regression y = offset + drift * x; with one distinct x, drift stays 0.
  const double denom = sw_ * sxx_ - sx_ * sx_;
  if (pairs_ >= 2 && std::abs(denom) > 1e-12 * sw_ * sw_) {
    drift_ = (sw_ * sxy_ - sx_ * sy_) / denom;
    offset_s_ = (sy_ - drift_ * sx_) / sw_;
  } else {
    drift_ = 0.0;
    offset_s_ = sy_ / sw_;
  }
}

std::optional<std::int64_t> ClockModel::to_gps(std::int64_t device_ns) const {
  if (pairs_ == 0) return std::nullopt;
  const std::int64_t dx_ns = device_ns - device_ref_ns_;
  const double y = offset_s_ + drift_ * static_cast<double>(dx_ns) * 1e-9;
  return gps_ref_ns_ + dx_ns + static_cast<std::int64_t>(std::llround(y * 1e9));
}

}  // namespace navfuse::time
