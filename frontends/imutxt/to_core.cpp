#include "frontends/imutxt/to_core.hpp"

#include "core/time/gps_time.hpp"
#include "frontends/common/text_fields.hpp"

namespace navfuse::frontends::imutxt {
namespace {

bool is_comment_start(std::string_view line) {
  for (char c : line) {
    if (text::is_blank(c)) continue;
    return c == '#' || c == '%' || c == '/' || c == ';';
  }
  return false;
}

}  // namespace

ParsedLine parse_line(std::string_view line) {
  ParsedLine out;
  if (text::is_blank_line(line)) {
    out.kind = LineKind::kBlank;
    return out;
  }
  if (is_comment_start(line)) {
    out.kind = LineKind::kComment;
    return out;
  }
  std::string_view fields[16];
  const std::size_t n = std::min(text::split_fields(line, fields), std::size(fields));
  double v[kColumns] = {};
  bool any_number = false;
  bool all_numbers = n >= kColumns;
  for (std::size_t i = 0; i < n; ++i) {
    const auto x = text::parse_number(fields[i]);
    any_number = any_number || x.has_value();
    if (i < kColumns) {
      if (x) {
        v[i] = *x;
      } else {
        all_numbers = false;
      }
    }
  }
  // A column header ("time gx gy gz ...") has no number in it; a damaged data line has some.
  if (!any_number) {
    out.kind = LineKind::kComment;
    return out;
  }
  if (!all_numbers || v[0] < 0.0 || v[0] >= static_cast<double>(time::kSecondsPerWeek)) return out;
  out.kind = LineKind::kData;
  out.imu.tow_s = v[0];
  out.imu.dtheta_rad = {v[1], v[2], v[3]};
  out.imu.dvel_mps = {v[4], v[5], v[6]};
  return out;
}

ImuSample to_core(const ImuLine& line, std::int64_t time_ns, TimeSource source, double dt_s) {
  ImuSample s;
  s.header.time_ns = time_ns;
  s.header.time_source = source;
  s.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
  s.quantity = ImuQuantity::kIncrements;
  s.frame = SensorFrame::kSensor;
  s.gyro = line.dtheta_rad;
  s.accel = line.dvel_mps;
  s.dt_s = dt_s;
  return s;
}

FrameRecord to_record(const ImuLine& line, std::uint64_t offset) {
  FrameRecord r;
  r.protocol = "imutxt";
  r.name = "imu";
  r.offset = offset;
  r.fields = {{"tow_s", line.tow_s},
              {"dtheta_x_rad", line.dtheta_rad.x()},
              {"dtheta_y_rad", line.dtheta_rad.y()},
              {"dtheta_z_rad", line.dtheta_rad.z()},
              {"dvel_x_mps", line.dvel_mps.x()},
              {"dvel_y_mps", line.dvel_mps.y()},
              {"dvel_z_mps", line.dvel_mps.z()}};
  return r;
}

}  // namespace navfuse::frontends::imutxt
