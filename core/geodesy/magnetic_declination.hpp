// Magnetic declination from GeographicLib's MagneticModel (the default model, e.g. WMM2025, found
// where GeographicLib looks: GEOGRAPHICLIB_MAGNETIC_PATH or its data directory). Debian ships the
// library without the model data (geographiclib-get-magnetic installs it), so absence is normal:
// callers then need a configured declination.
#pragma once

#include <cstdint>
#include <optional>

namespace navfuse::geo {

// Declination (rad, east of true north positive) at a position and GPS time, or nullopt when no
// model data is installed (or the model refuses the input). The model is loaded once per process.
std::optional<double> magnetic_declination_rad(double lat_rad, double lon_rad, double height_m,
                                               std::int64_t gps_ns);

// Decimal year of a GPS time (leap seconds ignored: a minute is 2e-6 years).
double decimal_year_from_gps_ns(std::int64_t gps_ns);

}  // namespace navfuse::geo
