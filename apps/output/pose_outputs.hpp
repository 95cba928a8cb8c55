// The pose outputs of one run (--fe-out, --mip-out, --csv): every writer sees every IMU epoch
// and every pose epoch. The caller decides when a pose is due (OutputRate).
#pragma once

#include <memory>
#include <vector>

#include "apps/output/pose_writer.hpp"

namespace navfuse::apps {

class PoseOutputs {
 public:
  void add(std::unique_ptr<PoseWriter> writer) { writers_.push_back(std::move(writer)); }
  bool empty() const { return writers_.empty(); }

  void on_imu(const NavSolution& s) {
    for (auto& w : writers_) w->on_imu(s);
  }
  // `gnss_fused_total` is the running count of fused GNSS positions: GNSSInfo goes out at the
  // first pose after it changes. `num_sats` is that of the newest fix.
  void on_pose(const NavSolution& s, std::uint64_t gnss_fused_total, std::uint8_t num_sats) {
    const PoseEpoch epoch{s, gnss_fused_total != gnss_at_last_pose_, num_sats};
    gnss_at_last_pose_ = gnss_fused_total;
    for (auto& w : writers_) w->on_pose(epoch);
  }
  void commit() {
    for (auto& w : writers_) w->commit();
  }

 private:
  std::vector<std::unique_ptr<PoseWriter>> writers_;
  std::uint64_t gnss_at_last_pose_ = 0;
};

}  // namespace navfuse::apps
