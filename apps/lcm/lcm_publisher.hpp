// Publishes the engine's streams on LCM (DESIGN.md channels NAVFUSE_POSE, NAVFUSE_STATUS,
// NAVFUSE_IMU, NAVFUSE_GNSS) through a caller-owned lcm::LCM. Synchronous and single-threaded
// on purpose: `navfuse replay --lcm` publishes from its output thread, and the nav process
// (`navfuse run --lcm`) from the one thread that owns its LCM handle. Both publish output epochs
// through publish_epoch(), so each channel means the same in both (core/lcm/*.lcm).
//
// Messages are encoded into buffers owned here and handed to lcm_publish() directly, because
// lcm::LCM::publish(channel, msg) allocates a buffer per message (lcm-cpp-impl.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "apps/fusion/output_epoch.hpp"
#include "core/measurements/measurements.hpp"
#include "navfuse/gnss_t.hpp"
#include "navfuse/imu_t.hpp"
#include "navfuse/pose_t.hpp"
#include "navfuse/status_t.hpp"

namespace navfuse::apps {

class LcmPublisher {
 public:
  explicit LcmPublisher(lcm::LCM& lcm);

  // Whether publish_epoch() sends anything for `epoch`: only pose epochs (output.rate_hz).
  static bool publishes(const OutputEpoch& epoch) { return epoch.pose_due; }
  // At a pose epoch: NAVFUSE_POSE, then NAVFUSE_IMU (the filter's bias-compensated IMU of the
  // same epoch, once the attitude is known). True when the pose went out.
  bool publish_epoch(const OutputEpoch& epoch);
  // Each returns false when LCM refused the message (counted in failures()).
  bool publish_pose(const NavSolution& s);
  bool publish_gnss(const GnssPosition& p, const GnssVelocity* v);
  bool publish_status(const navfuse::status_t& status);

  std::uint64_t published() const { return published_; }
  std::uint64_t failures() const { return failures_; }

 private:
  template <class Message>
  bool send(const char* channel, const Message& msg);

  lcm::LCM& lcm_;
  navfuse::pose_t pose_{};
  navfuse::imu_t imu_{};
  navfuse::gnss_t gnss_{};
  std::vector<std::uint8_t> buffer_;  // grows to the largest message once, then reused
  std::uint64_t published_ = 0;
  std::uint64_t failures_ = 0;
};

}  // namespace navfuse::apps
