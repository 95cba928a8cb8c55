#include "core/geodesy/magnetic_declination.hpp"

#include <cmath>
#include <memory>

#include <GeographicLib/MagneticModel.hpp>

namespace navfuse::geo {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
// 1980-01-06 (the GPS epoch) as a decimal year: 5 days into 1980, a leap year.
constexpr double kGpsEpochYear = 1980.0 + 5.0 / 366.0;
constexpr double kSecondsPerYear = 365.2425 * 86400.0;

const GeographicLib::MagneticModel* model() {
  static const std::unique_ptr<GeographicLib::MagneticModel> loaded = []() {
    try {
      return std::make_unique<GeographicLib::MagneticModel>(GeographicLib::MagneticModel::DefaultMagneticName());
    } catch (const std::exception&) {
      return std::unique_ptr<GeographicLib::MagneticModel>();  // no data installed
    }
  }();
  return loaded.get();
}

}  // namespace

double decimal_year_from_gps_ns(std::int64_t gps_ns) {
  return kGpsEpochYear + static_cast<double>(gps_ns) * 1e-9 / kSecondsPerYear;
}

std::optional<double> magnetic_declination_rad(double lat_rad, double lon_rad, double height_m,
                                               std::int64_t gps_ns) {
  const GeographicLib::MagneticModel* m = model();
  if (m == nullptr) return std::nullopt;
  try {
    double east = 0.0, north = 0.0, up = 0.0;
    (*m)(decimal_year_from_gps_ns(gps_ns), lat_rad * kRadToDeg, lon_rad * kRadToDeg, height_m, east, north, up);
    // The field's azimuth from true north (GeographicLib MagneticModel::FieldComponents: D).
    const double d = std::atan2(east, north);
    return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace navfuse::geo
