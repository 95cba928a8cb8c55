// Geoid undulation (height of the EGM96 geoid above the WGS-84 ellipsoid) from the 15-arc-minute
// grid Debian's proj-data installs as /usr/share/proj/egm96_15.gtx (NOAA VDatum GTX format:
// big-endian header of 4 doubles lat0, lon0, dlat, dlon (degrees) and 2 int32 rows, cols, then
// rows*cols big-endian float32 values, south row first). Bilinear interpolation between nodes.
//
// When the grid file is absent the undulation is "invalid" (nullopt), never a guess.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace navfuse::geo {

class GeoidGrid {
 public:
  static constexpr const char* kDefaultPath = "/usr/share/proj/egm96_15.gtx";

  // Loads a GTX grid; nullopt (and `error` filled) when missing or malformed.
  static std::optional<GeoidGrid> load(const std::string& path, std::string* error = nullptr);
  // The process-wide EGM96 grid from kDefaultPath, loaded once; nullptr when unavailable.
  static const GeoidGrid* egm96();

  // Geoid height above the ellipsoid in metres at (lat, lon) radians; nullopt outside the grid
  // or on a no-data node.
  std::optional<double> undulation_m(double lat_rad, double lon_rad) const;

 private:
  double lat0_deg_ = 0, lon0_deg_ = 0, dlat_deg_ = 0, dlon_deg_ = 0;
  int rows_ = 0, cols_ = 0;
  // From the header, once: a global grid wraps its columns (with or without a repeated column at
  // 360 deg, whose columns then wrap at cols - 1).
  bool global_ = false;
  int wrap_cols_ = 0;
  float node(int row, int col) const;  // the value at a node (rows from the south)
  std::shared_ptr<const std::uint8_t> file_;  // the whole GTX file, mapped read-only
  const std::uint8_t* nodes_ = nullptr;       // its big-endian float32 nodes, row by row
};

// Convenience: EGM96 undulation, nullopt when the grid is not installed.
std::optional<double> egm96_undulation_m(double lat_rad, double lon_rad);

}  // namespace navfuse::geo
