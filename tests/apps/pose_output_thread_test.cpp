// PoseOutputThread keeps epochs in a ring of slots that the producer fills in place: every epoch
// must reach the writers once, in order, with its own values, also when the ring wraps several
// times and the writer is slower than the producer (the producer then waits for free batches).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include "apps/output/pose_output_thread.hpp"
#include "apps/output/pose_outputs.hpp"

namespace navfuse::apps {
namespace {

struct Seen {
  std::int64_t arrival_ns;
  std::uint64_t gnss_fused_total;
};

class RecordingWriter final : public PoseWriter {
 public:
  explicit RecordingWriter(std::vector<Seen>& seen) : seen_(seen) {}
  void write(const OutputEpoch& epoch) override {
    seen_.push_back({epoch.arrival_ns, epoch.gnss_fused_total});
    // A slow writer now and then, so that the producer runs a full ring ahead and waits.
    if (seen_.size() % 1000 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  void commit() override {}

 private:
  std::vector<Seen>& seen_;
};

TEST(PoseOutputThread, EveryEpochOnceInOrderAcrossRingWraps) {
  std::vector<Seen> seen;
  PoseOutputs outputs;
  outputs.add(std::make_unique<RecordingWriter>(seen));
  constexpr std::int64_t kEpochs = 3 * 2048 + 17;  // the ring holds 2048 (8 batches of 256)
  {
    PoseOutputThread thread(outputs);
    for (std::int64_t k = 0; k < kEpochs; ++k) {
      if (k % 3 == 0) {
        OutputEpoch other;  // posted by copy into the slot
        other.arrival_ns = k;
        other.gnss_fused_total = static_cast<std::uint64_t>(3 * k + 1);
        thread.post(other);
      } else {
        OutputEpoch& slot = thread.next_slot();  // assembled in place
        slot.arrival_ns = k;
        slot.gnss_fused_total = static_cast<std::uint64_t>(3 * k + 1);
        thread.post(slot);
      }
    }
    thread.finish();
  }
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(kEpochs));
  for (std::int64_t k = 0; k < kEpochs; ++k) {
    const Seen& s = seen[static_cast<std::size_t>(k)];
    ASSERT_EQ(s.arrival_ns, k) << "epoch " << k;
    ASSERT_EQ(s.gnss_fused_total, static_cast<std::uint64_t>(3 * k + 1)) << "epoch " << k;
  }
}

}  // namespace
}  // namespace navfuse::apps
