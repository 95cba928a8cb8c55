// Which form an RTKLIB solution (.pos) file uses, from its '%' header lines.
//
// RTKLIB (RTKLIB 2.4.2 manual, Appendix B "Solution file format"; the demo5 fork adds the
// velocity columns) writes a comment header whose last line names the columns, e.g.
//   %  GPST          latitude(deg) longitude(deg)  height(m)   Q  ns   sdn(m) ... ratio vn(m/s) ...
// The first name is the time system: GPST, UTC or JST (UTC + 9 h); the time itself is either a
// calendar date and time (2 fields) or GPS week and seconds (2 fields), told apart per line by the
// '/' of the date. The coordinates are latitude/longitude/height in degrees (1 field each) or in
// degrees-minutes-seconds (latitude(d'") ...: 3 fields each), or x/y/z-ecef(m). Another header
// line says whether the height is above the ellipsoid or the geoid:
//   % (lat/lon/height=WGS84/ellipsoidal,Q=1:fix,...)     or  .../geodetic
// Every named column after the coordinates is looked up by name, so files with or without age,
// ratio or the velocity columns read alike. A file without a header is read as RTKLIB's default
// form (GPST, degrees, ellipsoidal height, Q ns sdn sde sdu sdne sdeu sdun age ratio [velocity]),
// with ECEF recognised per line by an x coordinate beyond 360.
#pragma once

#include <cstdint>
#include <string_view>

namespace navfuse::frontends::rtklib {

enum class TimeSystem : std::uint8_t { kGpst, kUtc, kJst };
enum class Coordinates : std::uint8_t { kLlhDeg, kLlhDms, kEcef, kUnsupported };  // ENU baseline: unsupported

// Index of a named column among the fields after the time and coordinates; -1 when absent.
struct PosColumns {
  int q = -1, ns = -1;
  int sd[3] = {-1, -1, -1};   // sdn sde sdu  | sdx sdy sdz
  int sdc[3] = {-1, -1, -1};  // sdne sdeu sdun | sdxy sdyz sdzx
  int vel[3] = {-1, -1, -1};  // vn ve vu | vx vy vz
  int sdv[3] = {-1, -1, -1};  // sdvn sdve sdvu | sdvx sdvy sdvz
  int sdvc[3] = {-1, -1, -1}; // sdvne sdveu sdvun | sdvxy sdvyz sdvzx
};

struct PosLayout {
  TimeSystem time = TimeSystem::kGpst;
  Coordinates coords = Coordinates::kLlhDeg;
  bool geoid_height = false;  // heights above the geoid ("WGS84/geodetic")
  bool wgs84 = true;          // false: the Tokyo datum, not read
  bool from_header = false;   // a column header line was read
  PosColumns columns;
};

// RTKLIB's column order without a header (outsolheads with the default options).
PosLayout default_layout(Coordinates coords);

// Reads one '%' line into `layout` (the column header, or the height/datum note); other comment
// lines leave it unchanged. Returns true when the line was the column header.
bool read_header_line(std::string_view line, PosLayout& layout);

}  // namespace navfuse::frontends::rtklib
