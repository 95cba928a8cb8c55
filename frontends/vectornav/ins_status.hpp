// InsStatus bitfield (ICD Table 2.77 / 4.28, L1694-1725; digest §5.7, §7.2) and its mapping to
// the core NavMode and validity bits of a NavSolution.
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"

namespace navfuse::frontends::vectornav {

enum class InsMode : std::uint8_t { kNotTracking = 0, kAligning = 1, kTracking = 2, kGnssLost = 3 };
enum class CompassFix : std::uint8_t { kNoFix = 0, kUndefined = 1, kFix = 2, kFixAiding = 3 };

struct InsStatus {
  InsMode mode = InsMode::kNotTracking;
  bool gnss_fix = false;
  bool imu_error = false;
  bool mag_pres_error = false;
  bool gnss_error = false;  // GNSS communication error or no valid PPS (L1712)
  CompassFix compass = CompassFix::kNoFix;
  // Errata A13/A14 (digest §10; ICD L4900, L4973): the examples set bits 12 and 15, which this
  // ICD does not document, and bit 7 is "reserved for internal use" and toggles. They are kept
  // here for logging only and never drive a decision.
  std::uint16_t undocumented_bits = 0;
};

InsStatus decode_ins_status(std::uint16_t raw);
std::uint16_t encode_ins_status(const InsStatus& status);

// What the mode allows (Table 2.78 and the heading-source note, L1686-1712; errata A29: gate by
// the mode table, not by the group-level "only valid if tracking" sentence).
struct InsValidity {
  bool position_velocity = false;
  bool attitude = false;
};
InsValidity validity_of(InsMode mode);

// NavMode for a decoded status. `attitude_nonzero`: Mode 0 still carries the AHRS attitude when
// AHRS aiding is on, and all-zero attitude when it is off (Reg 67, L4103).
NavMode nav_mode_of(const InsStatus& status, bool attitude_nonzero);
// The InsStatus a VN-300 would report for a navfuse solution (the inverse where the protocol
// can represent it: kVerticalGyro has no VN mode and is reported as NotTracking).
InsStatus ins_status_of(const NavSolution& solution);
// NavSolution::kStatus* flags implied by a status.
std::uint32_t status_flags_of(const InsStatus& status);

}  // namespace navfuse::frontends::vectornav
