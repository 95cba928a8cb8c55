#include "core/geodesy/geoid.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

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
  // The file is mapped, not read: a lookup reads its four big-endian nodes where they are. Reading
  // the 4 MB into a vector and byte-swapping it cost ~4 ms at the start of every replay (zeroed
  // pages, the copy, the swap), for the few pages a drive ever looks at.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return fail("cannot open (install Debian's proj-data for the EGM96 grid)");
  struct stat st {};
  const bool sized = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  const std::size_t file_size = sized ? static_cast<std::size_t>(st.st_size) : 0;
  void* map = file_size >= kGtxHeaderBytes ? ::mmap(nullptr, file_size, PROT_READ, MAP_PRIVATE, fd, 0) : MAP_FAILED;
  ::close(fd);  // the mapping stays valid without it (mmap(2))
  if (map == MAP_FAILED) return fail(file_size < kGtxHeaderBytes ? "not a GTX grid (bad header)" : "cannot read");
  GeoidGrid g;
  g.file_ = std::shared_ptr<const std::uint8_t>(static_cast<const std::uint8_t*>(map),
                                                [file_size](const std::uint8_t* p) {
                                                  ::munmap(const_cast<std::uint8_t*>(p), file_size);
                                                });
  bytes::BeReader r(std::span(g.file_.get(), kGtxHeaderBytes));
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
  if (file_size != kGtxHeaderBytes + 4 * n) return fail("GTX size does not match its header");
  g.nodes_ = g.file_.get() + kGtxHeaderBytes;
  const bool repeats_first_column = std::abs(g.dlon_deg_ * (g.cols_ - 1) - 360.0) < 1e-9;
  g.global_ = std::abs(g.dlon_deg_ * g.cols_ - 360.0) < 1e-9 || repeats_first_column;
  g.wrap_cols_ = repeats_first_column ? g.cols_ - 1 : g.cols_;
  return g;
}

float GeoidGrid::node(int row, int col) const {
  bytes::BeReader r(std::span(nodes_ + 4 * (static_cast<std::size_t>(row) * cols_ + col), 4));
  return r.f32();
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
  // Longitudes wrap: bring lon into [lon0, lon0 + 360). fmod returns an argument already in
  // range unchanged, so it is only called for one that is not (it costs as much as the rest).
  lon -= lon0_deg_;
  if (!(lon >= 0.0 && lon < 360.0)) lon = std::fmod(lon, 360.0);
  if (lon < 0) lon += 360.0;
  const double col_f = lon / dlon_deg_;
  const int r0 = std::min(static_cast<int>(row_f), rows_ - 2);
  int c0 = static_cast<int>(col_f);
  const double tr = row_f - r0;
  double tc = col_f - c0;
  if (c0 >= cols_ - 1 && !global_) return std::nullopt;
  c0 %= wrap_cols_;
  const int c1 = (c0 + 1) % wrap_cols_;
  const float v00 = node(r0, c0), v01 = node(r0, c1), v10 = node(r0 + 1, c0), v11 = node(r0 + 1, c1);
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
