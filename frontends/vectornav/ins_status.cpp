#include "frontends/vectornav/ins_status.hpp"

namespace navfuse::frontends::vectornav {
namespace {
constexpr std::uint16_t kModeMask = 0x0003;
constexpr std::uint16_t kGnssFixBit = 1u << 2;
constexpr std::uint16_t kImuErrBit = 1u << 4;
constexpr std::uint16_t kMagPresErrBit = 1u << 5;
constexpr std::uint16_t kGnssErrBit = 1u << 6;
constexpr unsigned kCompassShift = 8;
constexpr std::uint16_t kCompassMask = 0x0003;
// Bits 0-2, 4-6 and 8-9 are documented (Table 2.77); the rest are reserved or undocumented.
constexpr std::uint16_t kDocumentedBits = 0x0377;
}  // namespace

InsStatus decode_ins_status(std::uint16_t raw) {
  InsStatus s;
  s.mode = static_cast<InsMode>(raw & kModeMask);
  s.gnss_fix = (raw & kGnssFixBit) != 0;
  s.imu_error = (raw & kImuErrBit) != 0;
  s.mag_pres_error = (raw & kMagPresErrBit) != 0;
  s.gnss_error = (raw & kGnssErrBit) != 0;
  s.compass = static_cast<CompassFix>((raw >> kCompassShift) & kCompassMask);
  s.undocumented_bits = static_cast<std::uint16_t>(raw & ~kDocumentedBits);
  return s;
}

std::uint16_t encode_ins_status(const InsStatus& s) {
  std::uint16_t raw = static_cast<std::uint16_t>(static_cast<std::uint16_t>(s.mode) & kModeMask);
  if (s.gnss_fix) raw |= kGnssFixBit;
  if (s.imu_error) raw |= kImuErrBit;
  if (s.mag_pres_error) raw |= kMagPresErrBit;
  if (s.gnss_error) raw |= kGnssErrBit;
  raw = static_cast<std::uint16_t>(raw | ((static_cast<std::uint16_t>(s.compass) & kCompassMask) << kCompassShift));
  return raw;
}

InsValidity validity_of(InsMode mode) {
  switch (mode) {
    case InsMode::kNotTracking: return {false, false};
    case InsMode::kAligning: return {true, false};   // "Position and velocity valid, attitude not"
    case InsMode::kTracking: return {true, true};
    case InsMode::kGnssLost: return {false, true};   // "pos/vel invalid, attitude still valid"
  }
  return {};
}

NavMode nav_mode_of(const InsStatus& s, bool attitude_nonzero) {
  switch (s.mode) {
    case InsMode::kNotTracking: return attitude_nonzero ? NavMode::kAhrs : NavMode::kInvalid;
    case InsMode::kAligning: return NavMode::kInitializing;
    // Tracking continues through short GNSS outages; without a fix the INS is coasting.
    case InsMode::kTracking: return s.gnss_fix ? NavMode::kNavigation : NavMode::kDeadReckoning;
    case InsMode::kGnssLost: return NavMode::kAhrs;
  }
  return NavMode::kInvalid;
}

InsStatus ins_status_of(const NavSolution& sol) {
  InsStatus s;
  switch (sol.mode) {
    case NavMode::kInvalid:
    case NavMode::kVerticalGyro: s.mode = InsMode::kNotTracking; break;
    case NavMode::kInitializing: s.mode = InsMode::kAligning; break;
    case NavMode::kAhrs: s.mode = InsMode::kGnssLost; break;
    case NavMode::kNavigation:
    case NavMode::kDeadReckoning:
    case NavMode::kSmoothed: s.mode = InsMode::kTracking; break;
  }
  const bool fix = sol.gnss_fix >= GnssFixType::kFix2D && sol.gnss_fix != GnssFixType::kDeadReckoning;
  s.gnss_fix = fix && sol.mode != NavMode::kDeadReckoning;
  s.imu_error = (sol.status_flags & NavSolution::kStatusImuFault) != 0;
  s.compass = (sol.status_flags & NavSolution::kStatusDualAntennaHeading) ? CompassFix::kFixAiding : CompassFix::kNoFix;
  return s;
}

std::uint32_t status_flags_of(const InsStatus& s) {
  std::uint32_t f = 0;
  if (s.mode == InsMode::kGnssLost) f |= NavSolution::kStatusGnssOutage;
  if (s.imu_error) f |= NavSolution::kStatusImuFault;
  if (s.compass == CompassFix::kFixAiding) f |= NavSolution::kStatusDualAntennaHeading;
  return f;
}

}  // namespace navfuse::frontends::vectornav
