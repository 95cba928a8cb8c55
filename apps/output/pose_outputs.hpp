// The outputs of one replay (--fe-out, --mip-out, --csv, --lcm): every writer sees every output
// epoch and decides itself what it writes at it.
#pragma once

#include <memory>
#include <vector>

#include "apps/output/pose_writer.hpp"

namespace navfuse::apps {

class PoseOutputs {
 public:
  void add(std::unique_ptr<PoseWriter> writer) { writers_.push_back(std::move(writer)); }
  bool empty() const { return writers_.empty(); }

  void write(const OutputEpoch& epoch) {
    for (auto& w : writers_) w->write(epoch);
  }
  void commit() {
    for (auto& w : writers_) w->commit();
  }

 private:
  std::vector<std::unique_ptr<PoseWriter>> writers_;
};

}  // namespace navfuse::apps
