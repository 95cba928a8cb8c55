#include "apps/lcm/lcm_publisher.hpp"

#include "apps/lcm/lcm_channels.hpp"
#include "apps/lcm/lcm_messages.hpp"

namespace navfuse::apps {

LcmPublisher::LcmPublisher(lcm::LCM& lcm, const Eigen::Matrix3d& c_vs) : lcm_(lcm), c_vs_(c_vs) {
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

bool LcmPublisher::publish_imu(const ImuSample& s) {
  if (!fill_imu(s, c_vs_, imu_)) return false;
  return send(kImuChannel, imu_);
}

bool LcmPublisher::publish_gnss(const GnssPosition& p, const GnssVelocity* v) {
  fill_gnss(p, v, gnss_);
  return send(kGnssChannel, gnss_);
}

bool LcmPublisher::publish_status(const navfuse::status_t& status) {
  return send(kStatusChannel, status);
}

}  // namespace navfuse::apps
