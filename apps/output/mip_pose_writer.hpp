// --mip-out: the solution as the MIP filter data set 0x82 a 3DM-CV7 streams (DESIGN.md, contract),
// one packet group per pose, encoded by the MIP front-end (frontends/mip/encoder_solution.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "apps/output/output_file.hpp"
#include "apps/output/pose_writer.hpp"

namespace navfuse::apps {

class MipPoseWriter final : public PoseWriter {
 public:
  explicit MipPoseWriter(const std::string& path) : file_(path) { bytes_.reserve(1024); }
  void on_pose(const PoseEpoch& epoch) override;
  void commit() override { file_.commit(); }

 private:
  OutputFile file_;
  std::vector<std::uint8_t> bytes_;  // reused packet buffer
};

}  // namespace navfuse::apps
