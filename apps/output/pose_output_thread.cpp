#include "apps/output/pose_output_thread.hpp"

#include <pthread.h>

namespace navfuse::apps {
namespace {
// 256 epochs per hand-over keep lock traffic negligible (one lock per ~1 ms of a 200 Hz log at
// replay speed); 8 batches in flight bound memory at ~1 MB and let the writer absorb bursts.
constexpr std::size_t kBatchEpochs = 256;
constexpr std::size_t kBatches = 8;
}  // namespace

PoseOutputThread::PoseOutputThread(PoseOutputs& outputs) : outputs_(outputs) {
  filling_.reserve(kBatchEpochs);
  for (std::size_t i = 1; i < kBatches; ++i) {
    free_.emplace_back();
    free_.back().reserve(kBatchEpochs);
  }
  thread_ = std::thread([this] { run(); });
}

PoseOutputThread::~PoseOutputThread() { stop_thread(); }

void PoseOutputThread::post(const OutputEpoch& epoch) {
  filling_.push_back(epoch);
  if (filling_.size() >= kBatchEpochs) hand_over();
}

void PoseOutputThread::hand_over() {
  std::unique_lock lock(mutex_);
  // Waits only when all buffers are queued: the writer is behind by kBatches batches.
  changed_.wait(lock, [this] { return !free_.empty() || error_; });
  if (error_) {
    lock.unlock();
    rethrow_if_failed();
  }
  full_.push_back(std::move(filling_));
  filling_ = std::move(free_.back());
  free_.pop_back();
  lock.unlock();
  changed_.notify_all();
}

void PoseOutputThread::run() {
  pthread_setname_np(pthread_self(), "navfuse-output");  // tells the threads apart in top/perf
  Batch batch;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      if (batch.capacity() > 0) {  // the batch just written goes back (not the first, empty one)
        batch.clear();
        free_.push_back(std::move(batch));
        changed_.notify_all();
      }
      changed_.wait(lock, [this] { return !full_.empty() || closing_; });
      if (full_.empty()) return;  // closing with nothing left
      batch = std::move(full_.front());
      full_.pop_front();
    }
    try {
      for (const OutputEpoch& e : batch) outputs_.write(e);
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      changed_.notify_all();
      return;
    }
  }
}

void PoseOutputThread::finish() {
  if (!filling_.empty() && thread_.joinable()) hand_over();
  stop_thread();
  rethrow_if_failed();
}

void PoseOutputThread::stop_thread() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void PoseOutputThread::rethrow_if_failed() {
  std::exception_ptr e;
  {
    std::lock_guard lock(mutex_);
    e = error_;
  }
  if (e) std::rethrow_exception(e);
}

}  // namespace navfuse::apps
