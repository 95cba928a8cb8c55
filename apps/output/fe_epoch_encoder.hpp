// The FusionEngine stream of navfuse's solution, one output epoch at a time: the encoder every
// FusionEngine output uses (--fe-out files of replay, the --fe-out device link of run). It
// decides what goes out at an epoch from the message rates and nothing about transport; the
// encoding itself (FLU body, ENU yaw, units) is the front-end's (frontends/fusionengine/
// from_core.hpp, writer.hpp).
//
// At the default rates (DESIGN.md --fe-out, contract): IMUOutput 11000 after every IMU epoch
// (the bias-compensated IMU, apps/output/compensated_imu.hpp, once the attitude is known), then
// at each pose epoch Pose 10000 and PoseAux 10003, and GNSSInfo 10001 when a GNSS fix was fused
// since the previous pose. IMUOutput comes first because the pose is computed from that sample.
#pragma once

#include <cstdint>
#include <vector>

#include "apps/fusion/output_epoch.hpp"
#include "apps/output/fe_stream_rates.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::apps {

class FeEpochEncoder {
 public:
  // Appends the messages due at `epoch` to `out` (often none).
  void append(const OutputEpoch& epoch, std::vector<std::uint8_t>& out);

  FeStreamRates& rates() { return rates_; }
  // The stream's writer: anything else sent on the same stream (command replies) goes through
  // it so that the whole stream has one sequence counter (spec L190).
  frontends::fusionengine::FusionEngineWriter& writer() { return writer_; }

 private:
  FeStreamRates rates_;
  frontends::fusionengine::FusionEngineWriter writer_;
  ImuSample imu_;                        // reused: no allocation per epoch
  std::uint64_t gnss_at_last_info_ = 0;  // for GNSSInfo "on change"
};

}  // namespace navfuse::apps
