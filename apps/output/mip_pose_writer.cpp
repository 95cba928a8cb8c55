#include "apps/output/mip_pose_writer.hpp"

#include "frontends/mip/encoder_solution.hpp"

namespace navfuse::apps {

void MipPoseWriter::on_pose(const PoseEpoch& epoch) {
  bytes_.clear();
  frontends::mip::encode_solution(epoch.solution, bytes_);
  file_.write(bytes_);
}

}  // namespace navfuse::apps
