#include "filter/measurements/baro_height.hpp"

#include <cmath>

namespace navfuse::filter {
namespace {

constexpr double kSeaLevelPressure_pa = 101325.0;
constexpr double kSeaLevelTemperature_k = 288.15;
constexpr double kLapseRate_kpm = 0.0065;
constexpr double kExponent = 0.190263;  // R L / g0, with R = 287.053 J/(kg K), g0 = 9.80665 m/s^2

}  // namespace

double pressure_altitude_m(double pressure_pa) {
  return kSeaLevelTemperature_k / kLapseRate_kpm * (1.0 - std::pow(pressure_pa / kSeaLevelPressure_pa, kExponent));
}

double baro_height_prediction_m(const StateView& s) {
  const PointPrediction p = point_at(s, Eigen::Vector3d::Zero());
  return p.height_m - p.offset_ned_m.z();  // offset is NED: down is minus height
}

Observation baro_height_observation(const StateView& s, double height_m, double std_m) {
  // The position model of a point at the IMU, down row only (a barometer says nothing about
  // north or east).
  Observation obs(3);
  const PointPrediction p = point_at(s, Eigen::Vector3d::Zero());
  obs.residual = point_minus_llh_ned_m(s, p, p.lat_rad, p.lon_rad, height_m);
  point_jacobian(s, Eigen::Vector3d::Zero(), obs);
  obs.r(2, 2) = std_m * std_m;
  obs.keep_rows(0b100);
  return obs;
}

}  // namespace navfuse::filter
