#include "apps/aid/aid_message.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "apps/common/command_error.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

constexpr double kDeg = rot::kDegToRad;

void require_count(const AidSpec& s, std::size_t n) {
  if (s.values.size() != n) {
    throw CommandError("aid " + s.kind + " takes " + std::to_string(n) + " value(s), got " +
                       std::to_string(s.values.size()));
  }
  for (double v : s.values) {
    if (!std::isfinite(v)) throw CommandError("aid " + s.kind + ": value is not a finite number");
  }
}

// Expands the std list to n axes (one value applies to all) and checks each is > 0, as MIP
// 0x13 requires of a valid axis (MIP digest §5.4).
std::vector<double> stds(const AidSpec& s, std::size_t n) {
  std::vector<double> out = s.std;
  if (out.empty()) throw CommandError("aid " + s.kind + ": --std is required (1-sigma uncertainty)");
  if (out.size() == 1) out.assign(n, out[0]);
  if (out.size() != n) throw CommandError("aid " + s.kind + ": --std takes 1 or " + std::to_string(n) + " values");
  for (double v : out) {
    if (!(v > 0) || !std::isfinite(v)) throw CommandError("aid " + s.kind + ": uncertainty must be > 0");
  }
  return out;
}

void lever(const AidSpec& s, float out[3]) {
  if (s.lever_arm_m.empty()) return;
  if (s.lever_arm_m.size() != 3) throw CommandError("aid: --lever-arm takes 3 values");
  for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(s.lever_arm_m[i]);
}

// Every LCM aiding message is stamped in GPS time (core/lcm/aid_*.lcm).
MeasurementHeader gps_header(std::int64_t time_gps_ns, std::uint32_t valid) {
  MeasurementHeader h;
  h.time_ns = time_gps_ns;
  h.time_source = TimeSource::kGps;
  h.valid = valid;
  return h;
}

Eigen::Vector3d vec3(const float v[3]) { return {v[0], v[1], v[2]}; }

}  // namespace

const char* aid_channel(const AidMessage& m) {
  switch (m.index()) {
    case 0: return kAidPositionChannel;
    case 1: return kAidVelocityChannel;
    case 2: return kAidHeadingChannel;
    default: return kAidSpeedChannel;
  }
}

AidMessage make_aid_message(const AidSpec& s) {
  if (s.kind == "position") {
    require_count(s, 3);
    navfuse::aid_position_t m{};
    m.time_gps_ns = s.time_gps_ns;
    if (s.frame.empty() || s.frame == "llh") {
      m.frame = navfuse::aid_position_t::FRAME_LLH;
      if (std::abs(s.values[0]) > 90 || std::abs(s.values[1]) > 360) throw CommandError("aid position: latitude/longitude out of range");
    } else if (s.frame == "ecef") {
      m.frame = navfuse::aid_position_t::FRAME_ECEF;
    } else {
      throw CommandError("aid position: unknown frame '" + s.frame + "' (llh or ecef)");
    }
    const auto sd = stds(s, 3);
    for (int i = 0; i < 3; ++i) {
      m.value[i] = s.values[i];
      m.std_m[i] = static_cast<float>(sd[i]);
    }
    m.valid_mask = 0x7;
    lever(s, m.lever_arm_m);
    return m;
  }
  if (s.kind == "velocity") {
    require_count(s, 3);
    navfuse::aid_velocity_t m{};
    m.time_gps_ns = s.time_gps_ns;
    if (s.frame.empty() || s.frame == "ned") m.frame = navfuse::aid_velocity_t::FRAME_NED;
    else if (s.frame == "ecef") m.frame = navfuse::aid_velocity_t::FRAME_ECEF;
    else if (s.frame == "vehicle") m.frame = navfuse::aid_velocity_t::FRAME_VEHICLE;
    else throw CommandError("aid velocity: unknown frame '" + s.frame + "' (ned, ecef or vehicle)");
    const auto sd = stds(s, 3);
    for (int i = 0; i < 3; ++i) {
      m.value_mps[i] = static_cast<float>(s.values[i]);
      m.std_mps[i] = static_cast<float>(sd[i]);
    }
    m.valid_mask = 0x7;
    lever(s, m.lever_arm_m);
    return m;
  }
  if (s.kind == "heading") {
    require_count(s, 1);
    navfuse::aid_heading_t m{};
    m.time_gps_ns = s.time_gps_ns;
    m.heading_deg = static_cast<float>(s.values[0]);
    m.std_deg = static_cast<float>(stds(s, 1)[0]);
    m.valid = 1;
    return m;
  }
  if (s.kind == "speed") {
    require_count(s, 1);
    navfuse::aid_speed_t m{};
    m.time_gps_ns = s.time_gps_ns;
    m.speed_mps = static_cast<float>(s.values[0]);
    m.std_mps = static_cast<float>(stds(s, 1)[0]);
    m.valid = 1;
    if (!s.lever_arm_m.empty()) throw CommandError("aid speed: the measurement point is the config's wheel.lever_arm_m");
    return m;
  }
  throw CommandError("unknown aiding kind '" + s.kind + "' (position, velocity, heading or speed)");
}

std::vector<AidSpec> read_aid_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CommandError("cannot open aiding CSV '" + path + "'");
  std::vector<AidSpec> rows;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#' || line.rfind("kind,", 0) == 0) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    const std::string where = path + ":" + std::to_string(line_no);
    if (cells.size() < 4) throw CommandError(where + ": expected kind,time_gps_s,frame,values...");
    AidSpec s;
    s.kind = cells[0];
    s.frame = cells[2];
    try {
      const double t = std::stod(cells[1]);
      const double whole = std::floor(t);  // see aid_command.cpp: keep ns exact
      s.time_gps_ns = static_cast<std::int64_t>(whole) * 1'000'000'000 + std::llround((t - whole) * 1e9);
      const std::size_t n = (s.kind == "heading" || s.kind == "speed") ? 1 : 3;
      for (std::size_t i = 0; i < n && 3 + i < cells.size(); ++i) s.values.push_back(std::stod(cells[3 + i]));
      for (std::size_t i = 3 + n; i < cells.size() && i < 3 + 2 * n; ++i) {
        if (!cells[i].empty()) s.std.push_back(std::stod(cells[i]));
      }
    } catch (const std::exception&) {
      throw CommandError(where + ": not a number");
    }
    try {
      make_aid_message(s);  // validate now so the error names the line
    } catch (const CommandError& e) {
      throw CommandError(where + ": " + e.what());
    }
    rows.push_back(std::move(s));
  }
  return rows;
}

ExternalPosition to_measurement(const navfuse::aid_position_t& m) {
  ExternalPosition p;
  p.header = gps_header(m.time_gps_ns, static_cast<std::uint32_t>(m.valid_mask) & 0x7u);
  p.frame = m.frame == navfuse::aid_position_t::FRAME_ECEF ? PositionFrame::kEcef : PositionFrame::kLlh;
  if (p.frame == PositionFrame::kLlh) {
    p.value = {m.value[0] * kDeg, m.value[1] * kDeg, m.value[2]};
  } else {
    p.value = {m.value[0], m.value[1], m.value[2]};
  }
  p.std_m = vec3(m.std_m);
  p.lever_arm_m = vec3(m.lever_arm_m);
  return p;
}

ExternalVelocity to_measurement(const navfuse::aid_velocity_t& m) {
  ExternalVelocity v;
  v.header = gps_header(m.time_gps_ns, static_cast<std::uint32_t>(m.valid_mask) & 0x7u);
  v.frame = m.frame == navfuse::aid_velocity_t::FRAME_ECEF      ? VelocityFrame::kEcef
            : m.frame == navfuse::aid_velocity_t::FRAME_VEHICLE ? VelocityFrame::kVehicle
                                                                : VelocityFrame::kNed;
  v.value_mps = vec3(m.value_mps);
  v.std_mps = vec3(m.std_mps);
  v.lever_arm_m = vec3(m.lever_arm_m);
  return v;
}

ExternalHeading to_measurement(const navfuse::aid_heading_t& m) {
  ExternalHeading h;
  h.header = gps_header(m.time_gps_ns, m.valid ? ExternalHeading::kValidHeading : 0u);
  h.heading_rad = m.heading_deg * kDeg;
  h.std_rad = m.std_deg * kDeg;
  return h;
}

VehicleSpeed to_measurement(const navfuse::aid_speed_t& m) {
  VehicleSpeed s;
  s.header = gps_header(m.time_gps_ns, m.valid ? VehicleSpeed::kValidSpeed : 0u);
  s.speed_mps = m.speed_mps;
  s.speed_std_mps = m.std_mps;
  s.is_signed = true;
  return s;
}

}  // namespace navfuse::apps
