#include "apps/replay/calibration_collector.hpp"

#include <cmath>
#include <type_traits>

#include "core/time/gps_time.hpp"
#include "filter/measurements/gnss_heading.hpp"
#include "filter/measurements/wheel_speed.hpp"

namespace navfuse::apps {
namespace {

// A bias-instability std over its correlation time as the density of the random walk it drifts
// like over spans much shorter than that time (first-order Gauss-Markov: q = 2 sigma^2 / tau).
double drift_density(double std, double corr_time_s) {
  return corr_time_s > 0.0 ? std::sqrt(2.0 * std * std / corr_time_s) : 0.0;
}

}  // namespace

CalibrationCollector::CalibrationCollector(const filter::FilterOptions& o) : options_(o) {
  calib::CalibrationSetup& s = log_.setup;
  s.gnss_lever_arm_m = o.gnss_lever_arm_m;
  s.mounting_rpy_rad = o.mounting_rpy_rad;
  s.imu_time_offset_s = o.imu_time_offset_s;
  s.wheel_lever_arm_m = o.wheel_lever_arm_m;
  s.heading_baseline_v_m = filter::heading_baseline_b(o.gnss_lever_arm_m, o.gnss_secondary_lever_arm_m);
  s.nhc_lever_arm_m = o.nhc_point_m();
  s.nhc_lever_arm_std_m = o.nhc_lever_arm_std_m;
  s.land_vehicle = o.land_vehicle;
  s.nhc_lateral_std_mps = o.nhc_lateral_std_mps;
  s.nhc_vertical_std_mps = o.nhc_vertical_std_mps;
  s.nhc_min_speed_mps = o.nhc_min_speed_mps;
  s.gyro_arw_rad_rts = o.imu.gyro_arw_rad_rts;
  s.accel_vrw_mps_rts = o.imu.accel_vrw_mps_rts;
  s.gyro_bias_std_rps = drift_density(o.imu.gyro_bias_std_rps, o.imu.gyro_bias_corr_time_s);
  s.accel_bias_std_mps2 = drift_density(o.imu.accel_bias_std_mps2, o.imu.accel_bias_corr_time_s);
  s.gnss_velocity_std_scale = o.gnss_velocity_std_scale;
}

void CalibrationCollector::add(const Measurement& m) {
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        const std::int64_t shift_ns = time::nanoseconds(options_.time_offset_s(kind_of(m)));
        if constexpr (std::is_same_v<T, ImuSample>) {
          // The device applied its own mounting: the calibration's mounting is then a residual
          // about the vehicle axes (and is not written back as imu.mounting_rpy_deg).
          if (x.frame == SensorFrame::kVehicle && log_.imu.empty()) {
            log_.setup.imu_in_vehicle_frame = true;
            log_.setup.mounting_rpy_rad.setZero();
          }
          // Time order is what the calibration indexes by: a sample that goes back (the filter
          // rejects it as time_backwards) or repeats a stamp is left out here too.
          if (log_.imu.empty() || x.header.time_ns > log_.imu.back().header.time_ns) log_.imu.push_back(x);
        } else if constexpr (std::is_same_v<T, GnssPosition>) {
          GnssPosition p = x;
          p.header.time_ns += shift_ns;
          const double k = options_.gnss_position_std_scale_for(p.fix);
          p.cov_ned_m2 *= k * k;
          log_.positions.push_back(p);
        } else if constexpr (std::is_same_v<T, GnssVelocity>) {
          GnssVelocity v = x;
          v.header.time_ns += shift_ns;
          log_.velocities.push_back(v);
        } else if constexpr (std::is_same_v<T, GnssHeading>) {
          GnssHeading h = x;
          h.header.time_ns += shift_ns;
          log_.headings.push_back(h);
        } else if constexpr (std::is_same_v<T, ExternalPosition>) {
          log_.external_positions.push_back(x);
          log_.external_positions.back().header.time_ns += shift_ns;
        } else if constexpr (std::is_same_v<T, ExternalVelocity>) {
          log_.external_velocities.push_back(x);
          log_.external_velocities.back().header.time_ns += shift_ns;
        } else if constexpr (std::is_same_v<T, ExternalHeading>) {
          log_.external_headings.push_back(x);
          log_.external_headings.back().header.time_ns += shift_ns;
        } else if constexpr (std::is_same_v<T, VehicleSpeed> || std::is_same_v<T, WheelSpeeds>) {
          std::optional<filter::SpeedReading> r;
          if constexpr (std::is_same_v<T, VehicleSpeed>) {
            r = filter::speed_from_vehicle(x, options_.wheel_speed_std_mps);
          } else {
            r = filter::speed_from_wheels(x, options_.wheel_speed_std_mps);
          }
          if (r) log_.speeds.push_back({.time_ns = x.header.time_ns + shift_ns, .speed_mps = r->speed_mps, .std_mps = r->std_mps});
        }
      },
      m);
}

void CalibrationCollector::add(const filter::SmoothedSample& s) {
  const filter::NavState& x = s.x;
  log_.trajectory.push_back({.time_ns = x.time_ns - time::nanoseconds(options_.imu_time_offset_s),
                             .lat_rad = x.lat_rad,
                             .lon_rad = x.lon_rad,
                             .height_m = x.height_m,
                             .vel_ned_mps = x.vel_ned_mps,
                             .q_nv = x.q_nb,
                             .gyro_bias_v_rps = x.gyro_bias_rps,
                             .accel_bias_v_mps2 = x.accel_bias_mps2});
}

}  // namespace navfuse::apps
