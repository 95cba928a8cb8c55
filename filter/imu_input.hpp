// Turns IMU samples (rates or increments, sensor or vehicle frame) into vehicle-frame increments
// over the interval since the previous sample. Rates are integrated with the trapezoidal rule,
// which is what makes the same mechanisation correct from a 5 Hz (UM220 GYOACC) to a 1 kHz IMU.
#pragma once

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/strapdown.hpp"

namespace navfuse::filter {

class ImuInput {
 public:
  // Sensor -> vehicle rotation (the configured mounting, MIP 0x0C,0x31 convention).
  void set_mounting(const Eigen::Matrix3d& c_vs) { c_vs_ = c_vs; }
  const Eigen::Matrix3d& mounting() const { return c_vs_; }
  void reset() { have_previous_ = false; }
  bool has_previous() const { return have_previous_; }
  std::int64_t previous_time_ns() const { return previous_time_ns_; }

  // The increment ending at this sample; nullopt for the first sample of rates (nothing to
  // integrate yet) or of increments without a dt.
  std::optional<ImuIncrement> convert(const ImuSample& s);

 private:
  Eigen::Matrix3d c_vs_ = Eigen::Matrix3d::Identity();
  bool have_previous_ = false;
  std::int64_t previous_time_ns_ = 0;
  Eigen::Vector3d previous_rate_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_force_ = Eigen::Vector3d::Zero();
};

}  // namespace navfuse::filter
