#include "frontends/rtklib/pos_layout.hpp"

#include <array>

#include "frontends/common/text_fields.hpp"

namespace navfuse::frontends::rtklib {
namespace {

// Column name without its unit: "sdn(m)" -> "sdn", "x-ecef(m)" -> "x-ecef".
std::string_view bare_name(std::string_view name) {
  const auto paren = name.find('(');
  return paren == std::string_view::npos ? name : name.substr(0, paren);
}

// The named columns of the LLH and ECEF forms, in the triplet order the layout stores them.
struct Names {
  std::array<std::string_view, 3> sd, sdc, vel, sdv, sdvc;
};
constexpr Names kLlhNames{{"sdn", "sde", "sdu"}, {"sdne", "sdeu", "sdun"}, {"vn", "ve", "vu"},
                          {"sdvn", "sdve", "sdvu"}, {"sdvne", "sdveu", "sdvun"}};
constexpr Names kEcefNames{{"sdx", "sdy", "sdz"}, {"sdxy", "sdyz", "sdzx"}, {"vx", "vy", "vz"},
                           {"sdvx", "sdvy", "sdvz"}, {"sdvxy", "sdvyz", "sdvzx"}};

void assign(std::string_view name, int index, const Names& names, PosColumns& c) {
  if (name == "Q") c.q = index;
  if (name == "ns") c.ns = index;
  // demo5 writes the ECEF velocity as "vx-ecef(m/s)".
  if (name.ends_with("-ecef")) name.remove_suffix(5);
  const auto find3 = [&](const std::array<std::string_view, 3>& set, int (&out)[3]) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (name == set[k]) out[k] = index;
    }
  };
  find3(names.sd, c.sd);
  find3(names.sdc, c.sdc);
  find3(names.vel, c.vel);
  find3(names.sdv, c.sdv);
  find3(names.sdvc, c.sdvc);
}

}  // namespace

PosLayout default_layout(Coordinates coords) {
  PosLayout l;
  l.coords = coords;
  const Names& n = coords == Coordinates::kEcef ? kEcefNames : kLlhNames;
  const std::array<std::string_view, 19> order = {
      "Q",       "ns",      n.sd[0],   n.sd[1],   n.sd[2],   n.sdc[0],  n.sdc[1],  n.sdc[2],  "age",   "ratio",
      n.vel[0],  n.vel[1],  n.vel[2],  n.sdv[0],  n.sdv[1],  n.sdv[2],  n.sdvc[0], n.sdvc[1], n.sdvc[2]};
  for (std::size_t k = 0; k < order.size(); ++k) assign(order[k], static_cast<int>(k), n, l.columns);
  return l;
}

bool read_header_line(std::string_view line, PosLayout& layout) {
  if (line.empty() || line.front() != '%') return false;
  line.remove_prefix(1);
  if (const auto at = line.find("lat/lon/height="); at != std::string_view::npos) {
    layout.geoid_height = line.find("/geodetic", at) != std::string_view::npos;
    layout.wgs84 = line.find("=WGS84", at) != std::string_view::npos;  // not the Tokyo datum
    return false;
  }
  std::string_view f[64];
  const std::size_t n = std::min(text::split_fields(line, f), std::size(f));
  if (n < 3) return false;
  PosLayout l;
  if (f[0] == "GPST") {
    l.time = TimeSystem::kGpst;
  } else if (f[0] == "UTC") {
    l.time = TimeSystem::kUtc;
  } else if (f[0] == "JST") {
    l.time = TimeSystem::kJst;
  } else {
    return false;
  }
  const std::string_view c0 = f[1];
  if (c0.starts_with("latitude(d'\")")) {
    l.coords = Coordinates::kLlhDms;
  } else if (c0.starts_with("latitude")) {
    l.coords = Coordinates::kLlhDeg;
  } else if (c0.starts_with("x-ecef")) {
    l.coords = Coordinates::kEcef;
  } else {
    l.coords = Coordinates::kUnsupported;
  }
  const Names& names = l.coords == Coordinates::kEcef ? kEcefNames : kLlhNames;
  for (std::size_t i = 4; i < n; ++i) assign(bare_name(f[i]), static_cast<int>(i - 4), names, l.columns);
  l.geoid_height = layout.geoid_height;
  l.wgs84 = layout.wgs84;
  l.from_header = true;
  layout = l;
  return true;
}

}  // namespace navfuse::frontends::rtklib
