// PoseOutputs on a thread of their own, for `navfuse replay`: the filter thread hands each IMU
// epoch over and goes on, while encoding (FusionEngine / MIP / CSV) and file writes run on a
// second core. With a pose per IMU sample the encoders cost about as much as the filter, so
// this is what lets a replay use the machine's two cores.
//
// Nothing is dropped (unlike the live nav process, a replay must write every epoch): epochs are
// passed in batches through a bounded set of buffers and the producer waits when the writer
// falls that far behind. Order is kept, so outputs are byte-identical to writing inline.
// Buffers are allocated once; no allocation per epoch.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "apps/fusion/output_epoch.hpp"
#include "apps/output/pose_outputs.hpp"

namespace navfuse::apps {

class PoseOutputThread {
 public:
  // Takes over `outputs`; the thread starts at once.
  explicit PoseOutputThread(PoseOutputs& outputs);
  // Stops the thread without committing: the writers' unfinished files are removed.
  ~PoseOutputThread();
  PoseOutputThread(const PoseOutputThread&) = delete;
  PoseOutputThread& operator=(const PoseOutputThread&) = delete;

  // One output epoch, for PoseOutputs::write. Rethrows (as CommandError) a write error the
  // thread met.
  void post(const OutputEpoch& epoch);
  // Writes everything posted, stops the thread and rethrows a write error if there was one.
  // The writers are then ready for PoseOutputs::commit() on this thread.
  void finish();

 private:
  using Batch = std::vector<OutputEpoch>;

  void hand_over();  // the batch being filled -> the writer thread
  void run();        // the writer thread
  void stop_thread();
  void rethrow_if_failed();

  PoseOutputs& outputs_;
  Batch filling_;  // producer side only

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Batch> full_;   // oldest first
  std::vector<Batch> free_;  // emptied batches, capacity kept
  bool closing_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace navfuse::apps
