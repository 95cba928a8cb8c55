#include "frontends/mip/encoder_calibration.hpp"

#include "frontends/mip/protocol.hpp"
#include "frontends/mip/time_fields.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {
namespace {

constexpr std::uint8_t kPrimaryReceiver = 1;  // CV7 receiver numbering (digest §6.9)

void scalar_field(PacketWriter& pw, std::uint8_t desc, double value, bool valid) {
  auto& w = pw.field(desc);
  w.f32(static_cast<float>(value));
  w.u16(valid ? filter::kValid : 0);
}

void antenna_field(PacketWriter& pw, std::uint8_t desc, const Eigen::Vector3d& v, bool valid) {
  auto& w = pw.field(desc);
  w.u8(kPrimaryReceiver);
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(v[i]));
  w.u16(valid ? filter::kValid : 0);
}

}  // namespace

void encode_calibration(const NavSolution& s, const Eigen::Vector3d& configured_lever_arm_m,
                        std::vector<std::uint8_t>& out) {
  const bool solved = (s.header.valid & NavSolution::kValidBiases) != 0;
  const auto& odometer = s.calibration.odometer_scale_error;
  const auto& antenna = s.calibration.gnss_lever_arm_m;
  const bool odometer_valid = solved && odometer.estimated && odometer.value > -1.0;
  const bool antenna_valid = solved && antenna.estimated;
  const double ratio = odometer_valid ? 1.0 / (1.0 + odometer.value) : 1.0;
  PacketWriter pw(out, set::kFilter);
  write_time_fields(s.header, pw);
  scalar_field(pw, filter::kOdometerScaleError, odometer_valid ? ratio - 1.0 : 0.0, odometer_valid);
  scalar_field(pw, filter::kOdometerScaleErrorUnc, odometer_valid ? odometer.std * ratio * ratio : 0.0, odometer_valid);
  antenna_field(pw, filter::kAntennaOffsetCorrection,
                antenna_valid ? Eigen::Vector3d(antenna.value - configured_lever_arm_m) : Eigen::Vector3d::Zero(),
                antenna_valid);
  antenna_field(pw, filter::kAntennaOffsetCorrectionUnc, antenna_valid ? antenna.std : Eigen::Vector3d::Zero(),
                antenna_valid);
  pw.finish();
}

}  // namespace navfuse::frontends::mip
