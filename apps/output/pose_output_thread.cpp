#include "apps/output/pose_output_thread.hpp"

#include <pthread.h>

namespace navfuse::apps {
namespace {
// 256 epochs per hand-over keep lock traffic negligible (one lock per ~1 ms of a 200 Hz log at
// replay speed); 8 batches in flight bound memory at ~1 MB and let the writer absorb bursts.
constexpr std::size_t kBatchEpochs = 256;
constexpr std::size_t kBatches = 8;
}  // namespace

PoseOutputThread::PoseOutputThread(PoseOutputs& outputs)
    : outputs_(outputs), pipe_(kBatchEpochs, kBatches), thread_([this] { run(); }) {}

PoseOutputThread::~PoseOutputThread() {
  try {
    close_and_join();
  } catch (...) {
    // Not committing anyway: a write error changes nothing here.
  }
}

void PoseOutputThread::post(const OutputEpoch& epoch) {
  pipe_.filling().push_back(epoch);
  pipe_.hand_over_if_full();  // rethrows the writer's error
}

void PoseOutputThread::run() {
  pthread_setname_np(pthread_self(), "navfuse-output");  // tells the threads apart in top/perf
  BatchPipe<OutputEpoch>::Batch batch;
  try {
    while (pipe_.take(batch)) {
      for (OutputEpoch& e : batch) {
        e.fill_deferred_solution();  // the filter thread only captured it
        outputs_.write(e);
      }
    }
  } catch (...) {
    pipe_.fail(std::current_exception());
  }
}

void PoseOutputThread::close_and_join() {
  if (closed_) return;
  closed_ = true;
  std::exception_ptr early;
  try {
    pipe_.close();  // rethrows a failure the writer already met
  } catch (...) {
    early = std::current_exception();
  }
  thread_.join();
  if (early) std::rethrow_exception(early);
}

void PoseOutputThread::finish() {
  close_and_join();
  if (const std::exception_ptr e = pipe_.consumer_failure()) std::rethrow_exception(e);
}

}  // namespace navfuse::apps
