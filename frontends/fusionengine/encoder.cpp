#include "frontends/fusionengine/encoder.hpp"

#include <type_traits>

namespace navfuse::frontends::fusionengine {
namespace {

template <class In, class Out, class Layout>
void append_as(FusionEngineWriter& w, bool as_input, const Layout& layout, std::vector<std::uint8_t>& out) {
  if (as_input) {
    In msg;
    static_cast<Layout&>(msg) = layout;
    w.append(msg, out);
  } else {
    Out msg;
    static_cast<Layout&>(msg) = layout;
    w.append(msg, out);
  }
}

}  // namespace

bool FusionEngineEncoder::encode(const Measurement& m, std::vector<std::uint8_t>& out) {
  const bool inputs = options_.sensor_inputs;
  return std::visit(
      [&](const auto& x) -> bool {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, ImuSample>) {
          if (x.frame == SensorFrame::kVehicle && !inputs) {
            ImuOutputMessage msg;
            if (!imu_output_from(x, msg)) return false;
            writer_.append(msg, out);
            return true;
          }
          ScaledImuLayout layout;
          if (!scaled_imu_from(x, layout)) return false;
          append_as<ImuInputMessage, RawImuOutputMessage>(writer_, inputs, layout, out);
          return true;
        } else if constexpr (std::is_same_v<T, NavSolution>) {
          writer_.append(pose_from(x), out);
          writer_.append(pose_aux_from(x), out);
          if (x.gnss_fix != GnssFixType::kNone && x.header.time_source == TimeSource::kGps) {
            writer_.append(gnss_info_from(x), out);
          }
          return true;
        } else if constexpr (std::is_same_v<T, GnssHeading>) {
          writer_.append(gnss_attitude_from(x), out);
          return true;
        } else if constexpr (std::is_same_v<T, WheelSpeeds>) {
          append_as<WheelSpeedInputMessage, RawWheelSpeedOutputMessage>(writer_, inputs, wheel_speed_from(x), out);
          return true;
        } else if constexpr (std::is_same_v<T, VehicleSpeed>) {
          append_as<VehicleSpeedInputMessage, RawVehicleSpeedOutputMessage>(writer_, inputs, vehicle_speed_from(x), out);
          return true;
        } else if constexpr (std::is_same_v<T, WheelTicks>) {
          if (x.channels == 1) {
            append_as<VehicleTickInputMessage, RawVehicleTickOutputMessage>(writer_, inputs, vehicle_ticks_from(x), out);
          } else {
            append_as<WheelTickInputMessage, RawWheelTickOutputMessage>(writer_, inputs, wheel_ticks_from(x), out);
          }
          return true;
        } else if constexpr (std::is_same_v<T, GnssPosition> || std::is_same_v<T, GnssVelocity>) {
          writer_.append(gps_fix_from(x), out);
          return true;
        } else {
          return false;  // external aiding, magnetometer, pressure: FusionEngine has no message
        }
      },
      m);
}

}  // namespace navfuse::frontends::fusionengine
