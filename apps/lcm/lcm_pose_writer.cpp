#include "apps/lcm/lcm_pose_writer.hpp"

#include "apps/lcm/lcm_open.hpp"

namespace navfuse::apps {

LcmPoseWriter::LcmPoseWriter(const std::string& url) : lcm_(url), publisher_(lcm_) {
  require_lcm_open(lcm_, url);
}

void LcmPoseWriter::write(const OutputEpoch& epoch) { publisher_.publish_epoch(epoch); }

}  // namespace navfuse::apps
