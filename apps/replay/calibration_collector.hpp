// Gathers what the calibration needs (calibration/calibration_log.hpp) during `navfuse smooth
// --calibration-out`: every measurement the filter takes (raw stamps; GNSS and wheel moved onto
// the GNSS base by their configured offsets, as the filter does), and the smoothed trajectory
// (moved back onto the IMU clock). Memory: about 120 bytes per IMU sample (both), ~90 MB per hour
// at 200 Hz.
#pragma once

#include "calibration/calibration_log.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/filter_options.hpp"
#include "filter/smoother/rts_smoother.hpp"

namespace navfuse::apps {

class CalibrationCollector {
 public:
  explicit CalibrationCollector(const filter::FilterOptions& options);

  void add(const Measurement& m);
  void add(const filter::SmoothedSample& s);

  const calib::CalibrationLog& log() const { return log_; }

 private:
  filter::FilterOptions options_;
  calib::CalibrationLog log_;
};

}  // namespace navfuse::apps
