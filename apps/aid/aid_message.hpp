// External aiding messages for the NAVFUSE_AID_* LCM channels (DESIGN.md, contract): building
// them from command-line words or CSV rows, and turning received ones into core measurements.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/measurements/measurements.hpp"
#include "navfuse/aid_heading_t.hpp"
#include "navfuse/aid_position_t.hpp"
#include "navfuse/aid_speed_t.hpp"
#include "navfuse/aid_velocity_t.hpp"

namespace navfuse::apps {

inline constexpr const char* kAidPositionChannel = "NAVFUSE_AID_POSITION";
inline constexpr const char* kAidVelocityChannel = "NAVFUSE_AID_VELOCITY";
inline constexpr const char* kAidHeadingChannel = "NAVFUSE_AID_HEADING";
inline constexpr const char* kAidSpeedChannel = "NAVFUSE_AID_SPEED";

using AidMessage = std::variant<navfuse::aid_position_t, navfuse::aid_velocity_t,
                                navfuse::aid_heading_t, navfuse::aid_speed_t>;

// The channel an aiding message is published on.
const char* aid_channel(const AidMessage& m);

// Options shared by the command line and CSV forms.
struct AidSpec {
  std::string kind;                 // position | velocity | heading | speed
  std::vector<double> values;       // position: lat_deg lon_deg h_m (or ECEF x y z);
                                    // velocity: 3 components; heading: deg; speed: m/s
  std::vector<double> std;          // 1-sigma, same units; one value applies to every axis
  std::string frame;                // llh|ecef (position), ned|ecef|vehicle (velocity)
  std::vector<double> lever_arm_m;  // empty or 3 values
  std::int64_t time_gps_ns = 0;
};

// Validates and builds the message; throws CommandError naming the problem (wrong number of
// values, unknown kind or frame, non-finite value, std <= 0).
AidMessage make_aid_message(const AidSpec& spec);

// Parses a CSV of aiding rows: header `kind,time_gps_s,frame,v1,v2,v3,std1,std2,std3`
// (unused columns empty). Throws CommandError with the line number on a bad row.
std::vector<AidSpec> read_aid_csv(const std::string& path);

// Received LCM messages -> core measurements (TimeSource::kGps). A message whose values are
// not finite still converts; the filter's input checks reject and count it.
ExternalPosition to_measurement(const navfuse::aid_position_t& m);
ExternalVelocity to_measurement(const navfuse::aid_velocity_t& m);
ExternalHeading to_measurement(const navfuse::aid_heading_t& m);
VehicleSpeed to_measurement(const navfuse::aid_speed_t& m);

}  // namespace navfuse::apps
