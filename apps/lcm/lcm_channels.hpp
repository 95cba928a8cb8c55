// The LCM channels the engine publishes on (DESIGN.md "LCM", contract). The aiding channels it
// subscribes to are named next to their message types in apps/aid/aid_message.hpp.
#pragma once

namespace navfuse::apps {

inline constexpr const char* kPoseChannel = "NAVFUSE_POSE";
inline constexpr const char* kStatusChannel = "NAVFUSE_STATUS";
inline constexpr const char* kImuChannel = "NAVFUSE_IMU";
inline constexpr const char* kGnssChannel = "NAVFUSE_GNSS";

}  // namespace navfuse::apps
