// --fe-out: the solution as a Point One device streams it (DESIGN.md, contract): Pose 10000 and
// PoseAux 10003 at the pose rate, GNSSInfo 10001 at pose times after a GNSS fix was fused, and
// IMUOutput 11000 after every IMU sample. Encoding (FLU body, ENU yaw, units) is the FusionEngine
// front-end's (frontends/fusionengine/from_core.hpp); this file only decides what goes out when.
#pragma once

#include <string>

#include "apps/output/output_file.hpp"
#include "apps/output/pose_writer.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::apps {

class FePoseWriter final : public PoseWriter {
 public:
  explicit FePoseWriter(const std::string& path) : file_(path) {}
  void on_imu(const NavSolution& s) override;
  void on_pose(const PoseEpoch& epoch) override;
  void commit() override { file_.commit(); }

 private:
  OutputFile file_;
  frontends::fusionengine::FusionEngineWriter writer_;  // one writer: one sequence counter for the whole stream
  ImuSample imu_;                  // reused: no allocation per sample
};

// The bias-compensated IMU measurement a device reports in IMUOutput, rebuilt from the solution:
// angular rate as is, specific force f_b = a_b - C_bn g_n (the solution carries the
// gravity-free acceleration a_b and g_n). False when the attitude is not yet known.
bool compensated_imu_from(const NavSolution& s, ImuSample& out);

}  // namespace navfuse::apps
