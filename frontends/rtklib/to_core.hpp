// One RTKLIB solution line (pos_layout.hpp says how to read it) -> core GnssPosition and, when
// the file has velocity columns, GnssVelocity.
//
// Quality flag Q (RTKLIB manual, Appendix B): 1 fix, 2 float, 3 SBAS, 4 DGPS, 5 single, 6 PPP;
// demo5 adds 7 dead reckoning. They map to GnssFixType kRtkFixed, kRtkFloat, kSbas, kDgnss,
// kFix3D, kPpp, kDeadReckoning (0: kNone).
// Noise: sdn/sde/sdu are standard deviations; sdne/sdeu/sdun are "the square root of the absolute
// value of the NE/EU/UN covariance, the sign being the sign of the covariance" (RTKLIB manual,
// Appendix B), so cov = sign(s) * s^2. The NEU covariance becomes NED by flipping the sign of the
// rows and columns of up; the ECEF form's (sdx..sdzx) is rotated into NED at the solution (P_ned =
// C_ne P_ecef C_en). Velocity and its std devs the same way. All std devs zero (RTKLIB writes 0
// when it has none) leave the covariance invalid: the filter then uses its own noise.
// Times: GPST as given; UTC converted with the leap-second table (core/time); JST = UTC + 9 h.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/rtklib/pos_layout.hpp"

namespace navfuse::frontends::rtklib {

struct PosRecord {
  std::int64_t time_ns = 0;  // GPS time
  int quality = 0;           // RTKLIB Q
  GnssFixType fix = GnssFixType::kNone;
  int num_sats = 0;
  double lat_rad = 0.0, lon_rad = 0.0, height_m = 0.0;  // ellipsoidal height
  bool has_height = true;                                // false: geoid height and no geoid grid
  bool has_covariance = false;
  Eigen::Matrix3d cov_ned_m2 = Eigen::Matrix3d::Identity();
  bool has_velocity = false;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  bool has_velocity_covariance = false;
  Eigen::Matrix3d vel_cov_ned_m2ps2 = Eigen::Matrix3d::Identity();
};

// nullopt for a damaged line: too few fields, a non-number, an impossible date, Q outside 0..7,
// a negative std dev, a latitude beyond 90 deg, or a form this reader does not read (ENU
// baseline, Tokyo datum).
std::optional<PosRecord> parse_record(std::string_view line, const PosLayout& layout);

GnssFixType fix_from_quality(int q);

// Emits the record's GnssPosition (and GnssVelocity).
void to_core(const PosRecord& r, DecodeSink& sink);

FrameRecord to_frame_record(const PosRecord& r, std::uint64_t offset);

}  // namespace navfuse::frontends::rtklib
