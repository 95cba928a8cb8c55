// `navfuse replay --lcm [URL]`: the replayed solution on the nav process's channels, published
// as `navfuse run` publishes them (LcmPublisher::publish_epoch): at each pose output time
// NAVFUSE_POSE and NAVFUSE_IMU (the bias-compensated vehicle-frame IMU of that epoch). Both
// follow the pose rate, not the IMU rate, which matters most here: a replay runs hundreds of
// times faster than real time, and a 200 Hz stream would arrive as a burst of tens of thousands
// of datagrams that LCM's udpm receivers drop (seen here: 3 of 4 lost for a 20 s log). Even so a
// subscriber only keeps up with bursts of about a hundred datagrams (Linux's default socket
// receive buffer); --rate sets how many go out. NAVFUSE_STATUS and NAVFUSE_GNSS are published
// by `navfuse run` only.
#pragma once

#include <cstdint>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "apps/lcm/lcm_publisher.hpp"
#include "apps/output/pose_writer.hpp"

namespace navfuse::apps {

class LcmPoseWriter final : public PoseWriter {
 public:
  // `url` empty: LCM's default (LCM_DEFAULT_URL or udpm). Throws CommandError when LCM cannot
  // be opened.
  explicit LcmPoseWriter(const std::string& url);
  void write(const OutputEpoch& epoch) override;
  void commit() override {}  // every message is already out

  std::uint64_t published() const { return publisher_.published(); }
  std::uint64_t failures() const { return publisher_.failures(); }

 private:
  lcm::LCM lcm_;
  LcmPublisher publisher_;
};

}  // namespace navfuse::apps
