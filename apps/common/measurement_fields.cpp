#include "apps/common/measurement_fields.hpp"

#include <string>

#include "core/rotation/rotation.hpp"

namespace navfuse::apps {
namespace {

using frontends::FieldValue;
using frontends::FrameRecord;
constexpr double kRadToDeg = rot::kRadToDeg;

struct Fields {
  FrameRecord& r;
  void add(std::string name, double v) { r.fields.emplace_back(std::move(name), FieldValue{v}); }
  void add_int(std::string name, std::int64_t v) { r.fields.emplace_back(std::move(name), FieldValue{v}); }
  void add_str(std::string name, std::string_view v) {
    r.fields.emplace_back(std::move(name), FieldValue{std::string(v)});
  }
  void vec(const std::string& prefix, const Eigen::Vector3d& v, const std::string& unit, double scale = 1.0,
           const char* axes = "xyz") {
    for (int i = 0; i < 3; ++i) add(prefix + "_" + axes[i] + "_" + unit, v[i] * scale);
  }
  void header(const MeasurementHeader& h) {
    add_int("time_ns", h.time_ns);
    add_str("time_source", to_string(h.time_source));
    add_int("stream_id", h.stream_id);
    add_int("valid", h.valid);
  }
};

std::string_view gear_name(Gear g) {
  switch (g) {
    case Gear::kForward: return "forward";
    case Gear::kReverse: return "reverse";
    case Gear::kPark: return "park";
    case Gear::kNeutral: return "neutral";
    case Gear::kUnknown: break;
  }
  return "unknown";
}

}  // namespace

void measurement_to_record(const Measurement& m, FrameRecord& record) {
  record.name = std::string(to_string(kind_of(m)));
  record.fields.clear();
  Fields f{record};
  f.header(header_of(m));
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, ImuSample>) {
          const bool inc = v.quantity == ImuQuantity::kIncrements;
          f.add_str("quantity", inc ? "increments" : "rates");
          f.add_str("frame", v.frame == SensorFrame::kSensor ? "sensor" : "vehicle");
          f.vec(inc ? "delta_theta" : "gyro", v.gyro, inc ? "rad" : "radps");
          f.vec(inc ? "delta_v" : "accel", v.accel, inc ? "mps" : "mps2");
          f.add("dt_s", v.dt_s);
          if (inc) f.add_str("increments", v.increments == ImuIncrements::kCompensated ? "compensated" : "raw_integrals");
          f.add_int("low_rate", v.low_rate);
          f.add_int("saturation", v.saturation);
        } else if constexpr (std::is_same_v<T, GnssPosition>) {
          f.add("lat_deg", v.lat_rad * kRadToDeg);
          f.add("lon_deg", v.lon_rad * kRadToDeg);
          f.add("height_m", v.height_m);
          f.vec("std", v.cov_ned_m2.diagonal().cwiseSqrt(), "m", 1.0, "ned");
          f.add_str("fix", to_string(v.fix));
          f.add_int("num_sats", v.num_sats);
          f.add_int("receiver_id", v.receiver_id);
        } else if constexpr (std::is_same_v<T, GnssVelocity>) {
          f.vec("vel", v.vel_ned_mps, "mps", 1.0, "ned");
          f.vec("std", v.cov_ned_m2ps2.diagonal().cwiseSqrt(), "mps", 1.0, "ned");
          f.add_str("fix", to_string(v.fix));
          f.add_int("receiver_id", v.receiver_id);
        } else if constexpr (std::is_same_v<T, GnssHeading>) {
          f.add("heading_deg", v.heading_rad * kRadToDeg);
          f.add("heading_std_deg", v.heading_std_rad * kRadToDeg);
          f.add("pitch_deg", v.pitch_rad * kRadToDeg);
          f.add("pitch_std_deg", v.pitch_std_rad * kRadToDeg);
          f.add("baseline_m", v.baseline_m);
          f.add_str("fix", to_string(v.fix));
        } else if constexpr (std::is_same_v<T, WheelSpeeds>) {
          static constexpr const char* kNames[4] = {"fl", "fr", "rl", "rr"};
          for (int i = 0; i < 4; ++i) f.add(std::string("speed_") + kNames[i] + "_mps", v.speed_mps[i]);
          f.add_str("gear", gear_name(v.gear));
          f.add_int("is_signed", v.is_signed);
        } else if constexpr (std::is_same_v<T, VehicleSpeed>) {
          f.add("speed_mps", v.speed_mps);
          f.add_str("gear", gear_name(v.gear));
          f.add_int("is_signed", v.is_signed);
        } else if constexpr (std::is_same_v<T, WheelTicks>) {
          for (int i = 0; i < v.channels && i < 4; ++i) f.add_int("ticks_" + std::to_string(i), v.ticks[i]);
          f.add_int("channels", v.channels);
          f.add_str("gear", gear_name(v.gear));
          f.add("period_s", v.period_s);
        } else if constexpr (std::is_same_v<T, ExternalPosition>) {
          if (v.frame == PositionFrame::kLlh) {
            f.add_str("frame", "llh");
            f.add("lat_deg", v.value.x() * kRadToDeg);
            f.add("lon_deg", v.value.y() * kRadToDeg);
            f.add("height_m", v.value.z());
            f.vec("std", v.std_m, "m", 1.0, "ned");
          } else {
            f.add_str("frame", "ecef");
            f.vec("ecef", v.value, "m");
            f.vec("std", v.std_m, "m");
          }
          f.vec("lever_arm", v.lever_arm_m, "m");
        } else if constexpr (std::is_same_v<T, ExternalVelocity>) {
          f.add_str("frame", v.frame == VelocityFrame::kNed ? "ned" : v.frame == VelocityFrame::kEcef ? "ecef" : "vehicle");
          f.vec("vel", v.value_mps, "mps");
          f.vec("std", v.std_mps, "mps");
          f.vec("lever_arm", v.lever_arm_m, "m");
        } else if constexpr (std::is_same_v<T, ExternalHeading>) {
          f.add("heading_deg", v.heading_rad * kRadToDeg);
          f.add("std_deg", v.std_rad * kRadToDeg);
        } else if constexpr (std::is_same_v<T, NavSolution>) {
          f.add_str("mode", to_string(v.mode));
          f.add_str("gnss_fix", to_string(v.gnss_fix));
          f.add("lat_deg", v.lat_rad * kRadToDeg);
          f.add("lon_deg", v.lon_rad * kRadToDeg);
          f.add("height_m", v.height_m);
          f.vec("vel", v.vel_ned_mps, "mps", 1.0, "ned");
          f.add("roll_deg", v.rpy_rad.x() * kRadToDeg);
          f.add("pitch_deg", v.rpy_rad.y() * kRadToDeg);
          f.add("yaw_deg", v.rpy_rad.z() * kRadToDeg);
          f.vec("pos_std", v.pos_std_ned_m, "m", 1.0, "ned");
          f.vec("vel_std", v.vel_std_ned_mps, "mps", 1.0, "ned");
          f.vec("att_std", v.att_std_rpy_rad, "deg", kRadToDeg, "rpy");
          f.add_int("device_status", v.device_status);
          f.add_int("status_flags", v.status_flags);
        } else if constexpr (std::is_same_v<T, Magnetometer>) {
          f.vec("field", v.field_gauss, "gauss");
        } else if constexpr (std::is_same_v<T, Pressure>) {
          f.add("pressure_pa", v.pressure_pa);
        }
      },
      m);
}

}  // namespace navfuse::apps
