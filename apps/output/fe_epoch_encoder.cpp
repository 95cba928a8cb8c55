#include "apps/output/fe_epoch_encoder.hpp"

#include "apps/output/compensated_imu.hpp"

namespace navfuse::apps {

void FeEpochEncoder::append(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  using frontends::fusionengine::MessageType;
  const NavSolution& s = epoch.solution;
  const std::int64_t t = s.header.time_ns;
  if (rates_.due(MessageType::kImuOutput, t, true, true) && compensated_imu_from(s, imu_)) {
    frontends::fusionengine::ImuOutputMessage m;
    if (frontends::fusionengine::imu_output_from(imu_, m)) writer_.append(m, out);
  }
  if (rates_.due(MessageType::kPose, t, epoch.pose_due, true)) writer_.append(frontends::fusionengine::pose_from(s), out);
  if (rates_.due(MessageType::kPoseAux, t, epoch.pose_due, true)) writer_.append(frontends::fusionengine::pose_aux_from(s), out);
  const bool gnss_changed = epoch.gnss_fused_total != gnss_at_last_info_;
  if (rates_.due(MessageType::kGnssInfo, t, epoch.gnss_updated, gnss_changed)) {
    gnss_at_last_info_ = epoch.gnss_fused_total;
    writer_.append(frontends::fusionengine::gnss_info_from(s, epoch.num_sats), out);
  }
}

}  // namespace navfuse::apps
