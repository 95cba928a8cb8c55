#include "apps/lcm/lcm_pose_writer.hpp"

#include "apps/lcm/lcm_open.hpp"
#include "apps/output/fe_pose_writer.hpp"

namespace navfuse::apps {

LcmPoseWriter::LcmPoseWriter(const std::string& url) : lcm_(url), publisher_(lcm_) {
  require_lcm_open(lcm_, url);
}

void LcmPoseWriter::on_pose(const PoseEpoch& epoch) {
  publisher_.publish_pose(epoch.solution);
  // The solution's IMU is already in the vehicle frame: published with an identity mounting.
  if (compensated_imu_from(epoch.solution, imu_)) publisher_.publish_imu(imu_);
}

}  // namespace navfuse::apps
