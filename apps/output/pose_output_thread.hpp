// PoseOutputs on a thread of their own, for `navfuse replay`: the filter thread hands each IMU
// epoch over and goes on, while encoding (FusionEngine / MIP / CSV) and file writes run on
// another core. With a pose per IMU sample the encoders cost about as much as the filter, so
// this is what lets a replay use the machine's cores.
//
// Nothing is dropped (unlike the live nav process, a replay must write every epoch): epochs go
// in batches through a BatchPipe (apps/common/batch_pipe.hpp), which makes the producer wait when
// the writer falls that far behind. Order is kept, so outputs are byte-identical to writing
// inline. Buffers are allocated once; no allocation per epoch.
#pragma once

#include <thread>

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

  // One output epoch, for PoseOutputs::write. Rethrows (as CommandError) a write error the
  // thread met.
  void post(const OutputEpoch& epoch);
  // Writes everything posted, stops the thread and rethrows a write error if there was one.
  // The writers are then ready for PoseOutputs::commit() on this thread.
  void finish();

 private:
  void run();  // the writer thread
  void close_and_join();

  PoseOutputs& outputs_;
  BatchPipe<OutputEpoch> pipe_;
  bool closed_ = false;
  std::thread thread_;
};

}  // namespace navfuse::apps
