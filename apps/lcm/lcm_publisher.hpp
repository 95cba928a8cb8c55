// Publishes the engine's streams on LCM (DESIGN.md channels NAVFUSE_POSE, NAVFUSE_STATUS,
// NAVFUSE_IMU, NAVFUSE_GNSS) through a caller-owned lcm::LCM. Synchronous and single-threaded
// on purpose: `navfuse replay --lcm` can publish from its own loop, and the nav process calls it
// from the one thread that owns its LCM handle.
//
// Messages are encoded into buffers owned here and handed to lcm_publish() directly, because
// lcm::LCM::publish(channel, msg) allocates a buffer per message (lcm-cpp-impl.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <lcm/lcm-cpp.hpp>

#include "core/measurements/measurements.hpp"
#include "navfuse/gnss_t.hpp"
#include "navfuse/imu_t.hpp"
#include "navfuse/pose_t.hpp"
#include "navfuse/status_t.hpp"

namespace navfuse::apps {

class LcmPublisher {
 public:
  // `c_vs`: the configured sensor -> vehicle mounting, for NAVFUSE_IMU (vehicle frame).
  explicit LcmPublisher(lcm::LCM& lcm, const Eigen::Matrix3d& c_vs = Eigen::Matrix3d::Identity());

  // Each returns false when nothing was published: LCM refused the message (counted in
  // failures()), or, for publish_imu, increments without an interval cannot be given as rates.
  bool publish_pose(const NavSolution& s);
  bool publish_imu(const ImuSample& s);
  bool publish_gnss(const GnssPosition& p, const GnssVelocity* v);
  bool publish_status(const navfuse::status_t& status);

  std::uint64_t published() const { return published_; }
  std::uint64_t failures() const { return failures_; }

 private:
  template <class Message>
  bool send(const char* channel, const Message& msg);

  lcm::LCM& lcm_;
  Eigen::Matrix3d c_vs_;
  navfuse::pose_t pose_{};
  navfuse::imu_t imu_{};
  navfuse::gnss_t gnss_{};
  std::vector<std::uint8_t> buffer_;  // grows to the largest message once, then reused
  std::uint64_t published_ = 0;
  std::uint64_t failures_ = 0;
};

}  // namespace navfuse::apps
