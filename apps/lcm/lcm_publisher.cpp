#include "apps/lcm/lcm_publisher.hpp"

#include "apps/lcm/lcm_channels.hpp"
#include "apps/lcm/lcm_messages.hpp"

namespace navfuse::apps {

LcmPublisher::LcmPublisher(lcm::LCM& lcm) : lcm_(lcm) {
  buffer_.reserve(1024);  // pose_t, imu_t and gnss_t all fit; status_t grows it once if needed
}

template <class Message>
bool LcmPublisher::send(const char* channel, const Message& msg) {
  const int size = msg.getEncodedSize();
  if (size < 0) {
    ++failures_;
    return false;
  }
  if (buffer_.size() < static_cast<std::size_t>(size)) buffer_.resize(static_cast<std::size_t>(size));
  if (msg.encode(buffer_.data(), 0, size) != size ||
      lcm_publish(lcm_.getUnderlyingLCM(), channel, buffer_.data(), static_cast<unsigned>(size)) != 0) {
    ++failures_;
    return false;
  }
  ++published_;
  return true;
}

bool LcmPublisher::publish_pose(const NavSolution& s) {
  fill_pose(s, pose_);
  return send(kPoseChannel, pose_);
}

bool LcmPublisher::publish_epoch(const OutputEpoch& epoch) {
  if (!publishes(epoch)) return false;
  const bool pose = publish_pose(epoch.solution);
  if (fill_imu(epoch.solution, imu_)) send(kImuChannel, imu_);
  return pose;
}

bool LcmPublisher::publish_gnss(const GnssPosition& p, const GnssVelocity* v) {
  fill_gnss(p, v, gnss_);
  return send(kGnssChannel, gnss_);
}

bool LcmPublisher::publish_status(const navfuse::status_t& status) {
  return send(kStatusChannel, status);
}

}  // namespace navfuse::apps
