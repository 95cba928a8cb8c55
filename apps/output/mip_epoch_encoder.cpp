#include "apps/output/mip_epoch_encoder.hpp"

#include "frontends/mip/encoder_solution.hpp"

namespace navfuse::apps {

void MipEpochEncoder::append(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) {
  if (epoch.pose_due) frontends::mip::encode_solution(epoch.solution, out);
}

}  // namespace navfuse::apps
