// PoseOutputs on a thread of their own, for `navfuse replay`: the filter thread hands each IMU
// epoch over and goes on, while encoding (FusionEngine / MIP / CSV) and file writes run on
// another core. With a pose per IMU sample the encoders cost about as much as the filter, so
// this is what lets a replay use the machine's cores.
//
// Nothing is dropped (unlike the live nav process, a replay must write every epoch): epochs go
// in batches through a BatchPipe (apps/common/batch_pipe.hpp), which makes the producer wait when
// the writer falls that far behind. Order is kept, so outputs are byte-identical to writing
// inline. Buffers are allocated once; no allocation per epoch.
//
// The epochs themselves (~1.8 kB each) stay in a ring of slots and the pipe carries pointers to
// them: the filter thread assembles an epoch in next_slot() (FusionObserver::epoch_slot) and
// post() only queues it, instead of copying every epoch into the pipe.
#pragma once

#include <cstddef>
#include <thread>
#include <vector>

#include "apps/common/batch_pipe.hpp"
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

  // Where the next epoch to post() may be assembled in place (valid until that post()).
  OutputEpoch& next_slot();
  // One output epoch, for PoseOutputs::write: next_slot() itself (queued as it is) or any other
  // epoch (copied into it). Rethrows (as CommandError) a write error the thread met.
  void post(const OutputEpoch& epoch);
  // Writes everything posted, stops the thread and rethrows a write error if there was one.
  // The writers are then ready for PoseOutputs::commit() on this thread.
  void finish();

 private:
  void run();  // the writer thread
  void close_and_join();

  PoseOutputs& outputs_;
  std::vector<OutputEpoch> slots_;  // the ring, grown to full size during its first lap
  std::size_t next_slot_ = 0;
  BatchPipe<OutputEpoch*> pipe_;
  bool closed_ = false;
  std::thread thread_;
};

}  // namespace navfuse::apps
