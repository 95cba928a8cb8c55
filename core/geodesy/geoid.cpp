#include "core/geodesy/geoid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/bytes/byte_reader.hpp"

namespace navfuse::geo {
namespace {

constexpr std::size_t kGtxHeaderBytes = 4 * 8 + 2 * 4;
// GTX marks nodes without data with -88.8888 (NOAA VDatum GTX format description).
constexpr float kGtxNoData = -88.8888f;
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

}  // namespace

std::optional<GeoidGrid> GeoidGrid::load(const std::string& path, std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<GeoidGrid> {
    if (error) *error = path + ": " + why;
    return std::nullopt;
  };
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return fail("cannot open (install Debian's proj-data for the EGM96 grid)");
  // The 4 MB of nodes are read in one call straight into the grid and byte-swapped in place: a
  // byte-wise stream copy plus a checked read per node took 84 M instructions (~8 ms), paid at
  // the start of every replay (now ~10 M).
  const std::streamoff file_size = in.tellg();
  std::uint8_t header[kGtxHeaderBytes];
  in.seekg(0);
  if (file_size < 0 || !in.read(reinterpret_cast<char*>(header), sizeof header)) {
    return fail("not a GTX grid (bad header)");
  }
  bytes::BeReader r(header);
  GeoidGrid g;
  g.lat0_deg_ = r.f64();
  g.lon0_deg_ = r.f64();
  g.dlat_deg_ = r.f64();
  g.dlon_deg_ = r.f64();
  g.rows_ = r.i32();
  g.cols_ = r.i32();
  if (!r.ok() || g.rows_ < 2 || g.cols_ < 2 || !(g.dlat_deg_ > 0) || !(g.dlon_deg_ > 0)) {
    return fail("not a GTX grid (bad header)");
  }
  const std::size_t n = static_cast<std::size_t>(g.rows_) * static_cast<std::size_t>(g.cols_);
  if (static_cast<std::size_t>(file_size) != kGtxHeaderBytes + 4 * n) return fail("GTX size does not match its header");
  g.values_.resize(n);
  if (!in.read(reinterpret_cast<char*>(g.values_.data()), static_cast<std::streamsize>(4 * n))) {
    return fail("cannot read");
  }
  static_assert(sizeof(float) == 4);
  if constexpr (std::endian::native == std::endian::little) {
    for (float& v : g.values_) v = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(v)));
  }
  return g;
}

const GeoidGrid* GeoidGrid::egm96() {
  static const std::optional<GeoidGrid> grid = load(kDefaultPath);
  return grid ? &*grid : nullptr;
}

std::optional<double> GeoidGrid::undulation_m(double lat_rad, double lon_rad) const {
  if (!std::isfinite(lat_rad) || !std::isfinite(lon_rad)) return std::nullopt;
  const double lat = lat_rad * kRadToDeg;
  double lon = lon_rad * kRadToDeg;
  const double row_f = (lat - lat0_deg_) / dlat_deg_;
  if (row_f < 0.0 || row_f > rows_ - 1) return std::nullopt;
  // Longitudes wrap: bring lon into [lon0, lon0 + 360).
  lon = std::fmod(lon - lon0_deg_, 360.0);
  if (lon < 0) lon += 360.0;
  const double col_f = lon / dlon_deg_;
  const int r0 = std::min(static_cast<int>(row_f), rows_ - 2);
  int c0 = static_cast<int>(col_f);
  const double tr = row_f - r0;
  double tc = col_f - c0;
  // A global grid may or may not repeat its first column at 360 deg: wrap the column index.
  const bool global = std::abs(dlon_deg_ * cols_ - 360.0) < 1e-9 || std::abs(dlon_deg_ * (cols_ - 1) - 360.0) < 1e-9;
  if (c0 >= cols_ - 1 && !global) return std::nullopt;
  const int wrap_cols = (std::abs(dlon_deg_ * (cols_ - 1) - 360.0) < 1e-9) ? cols_ - 1 : cols_;
  c0 %= wrap_cols;
  const int c1 = (c0 + 1) % wrap_cols;
  auto at = [&](int row, int col) { return values_[static_cast<std::size_t>(row) * cols_ + col]; };
  const float v00 = at(r0, c0), v01 = at(r0, c1), v10 = at(r0 + 1, c0), v11 = at(r0 + 1, c1);
  for (float v : {v00, v01, v10, v11}) {
    if (std::abs(v - kGtxNoData) < 1e-3f) return std::nullopt;
  }
  return (1 - tr) * ((1 - tc) * v00 + tc * v01) + tr * ((1 - tc) * v10 + tc * v11);
}

std::optional<double> egm96_undulation_m(double lat_rad, double lon_rad) {
  const GeoidGrid* g = GeoidGrid::egm96();
  if (!g) return std::nullopt;
  return g->undulation_m(lat_rad, lon_rad);
}

}  // namespace navfuse::geo
