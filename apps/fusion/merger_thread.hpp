// The log merger on a thread of its own: `replay` and `bench` decode their inputs on one core
// while the filter runs on another (decoding is about a fifth of a replay's filter-thread time).
// Measurements come out in exactly the merger's order, so results do not change; memory is
// bounded by a few batches (apps/common/batch_pipe.hpp).
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>

#include "apps/common/batch_pipe.hpp"
#include "apps/fusion/measurement_merger.hpp"

namespace navfuse::apps {

class MergerThread {
 public:
  // Starts reading at once. `merger` must not be used by anyone else until join().
  explicit MergerThread(MeasurementMerger& merger);
  // Stops the reading thread early if it is still running.
  ~MergerThread();
  MergerThread(const MergerThread&) = delete;
  MergerThread& operator=(const MergerThread&) = delete;

  // The next measurement in merged order, valid until the next call; nullptr once every input
  // is used up. Rethrows what the merger threw (read error, truncated input) in its place.
  const Measurement* next();
  // Bytes the merger had read when the current batch was handed over (for progress display).
  std::uint64_t bytes_read() const { return bytes_read_.load(std::memory_order_relaxed); }
  // Waits for the reading thread: after it, the merger's summaries are final.
  void join();
  // Stops the reading thread early (nothing more comes out of next()) and waits for it.
  void stop();

 private:
  void run();

  MeasurementMerger& merger_;
  BatchPipe<Measurement> pipe_;
  BatchPipe<Measurement>::Batch batch_;  // consumer side: the batch being read
  std::size_t position_ = 0;
  std::atomic<std::uint64_t> bytes_read_{0};
  std::thread thread_;
};

}  // namespace navfuse::apps
