#include "frontends/imutxt/frontend.hpp"

#include "frontends/imutxt/decoder.hpp"

namespace navfuse::frontends {
namespace {

// Per-sample limits of the probe: 1 rad in one sample is 57 deg (5700 deg/s at 100 Hz), 50 m/s
// is 5000 m/s^2: beyond any IMU, so a line past them is not an IMU sample.
constexpr double kMaxAngleIncrementRad = 1.0;
constexpr double kMaxVelocityIncrementMps = 50.0;
constexpr double kMaxIntervalS = 1.0;

std::size_t probe(std::span<const std::uint8_t> head) {
  LineFramer framer(imutxt::kMaxLineBytes);
  std::size_t plausible = 0;
  std::optional<double> previous_tow_s;
  framer.feed(head, [&](std::string_view line) {
    const imutxt::ParsedLine p = imutxt::parse_line(line);
    if (p.kind != imutxt::LineKind::kData) return;
    const double dt = previous_tow_s ? p.imu.tow_s - *previous_tow_s : 0.0;
    previous_tow_s = p.imu.tow_s;
    if (p.imu.dtheta_rad.cwiseAbs().maxCoeff() > kMaxAngleIncrementRad ||
        p.imu.dvel_mps.cwiseAbs().maxCoeff() > kMaxVelocityIncrementMps || dt < 0.0 || dt > kMaxIntervalS) {
      return;
    }
    ++plausible;
  });
  return plausible;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<imutxt::ImuTextDecoder>(); }
std::unique_ptr<StreamDecoder> make_decoder_in_week(std::int32_t week) {
  return std::make_unique<imutxt::ImuTextDecoder>(week);
}

}  // namespace

const FrontendInfo& imutxt::frontend() {
  static const FrontendInfo info = file_reader_info(
      "imutxt", "KF-GINS-style IMU text: GPS seconds of week, angle (rad) and velocity (m/s) increments", &probe,
      &make_decoder, &make_decoder_in_week);
  return info;
}

}  // namespace navfuse::frontends
