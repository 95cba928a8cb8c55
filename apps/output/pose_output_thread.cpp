#include "apps/output/pose_output_thread.hpp"

#include <pthread.h>

#include "core/cpu/prefetch.hpp"

namespace navfuse::apps {
namespace {
// 256 epochs per hand-over keep lock traffic negligible (one lock per ~1 ms of a 200 Hz log at
// replay speed); 8 batches in flight bound memory at ~1 MB and let the writer absorb bursts.
constexpr std::size_t kBatchEpochs = 256;
constexpr std::size_t kBatches = 8;
// A slot is written again kSlots epochs after its last use, i.e. kBatches full batches later. By
// then the writer has given that batch back: the filling batch and the ones the writer has not
// given back (handed over, or being written) share the pipe's kBatches buffers, so a batch
// kBatches back no longer holds one. Only close() hands over a batch that is not full, and it
// is the last.
constexpr std::size_t kSlots = kBatchEpochs * kBatches;
}  // namespace

PoseOutputThread::PoseOutputThread(PoseOutputs& outputs)
    : outputs_(outputs), pipe_(kBatchEpochs, kBatches), thread_([this] { run(); }) {
  slots_.reserve(kSlots);
}

PoseOutputThread::~PoseOutputThread() {
  try {
    close_and_join();
  } catch (...) {
    // Not committing anyway: a write error changes nothing here.
  }
}

OutputEpoch& PoseOutputThread::next_slot() {
  if (next_slot_ == slots_.size()) slots_.emplace_back();  // first lap: within the reservation
  // The slot two ahead was last read by the writer thread, on the other core: ask for the part
  // the filter thread writes (the captured solution inputs) before it gets there.
  const std::size_t ahead = (next_slot_ + 2) % kSlots;
  if (ahead < slots_.size()) {
    cpu::prefetch<cpu::Intent::kWrite>(&slots_[ahead].solution_inputs, sizeof(filter::SolutionInputs));
  }
  return slots_[next_slot_];
}

void PoseOutputThread::post(const OutputEpoch& epoch) {
  OutputEpoch& slot = next_slot();
  if (&epoch != &slot) slot = epoch;
  next_slot_ = (next_slot_ + 1) % kSlots;
  pipe_.filling().push_back(&slot);
  pipe_.hand_over_if_full();  // rethrows the writer's error
}

void PoseOutputThread::run() {
  pthread_setname_np(pthread_self(), "navfuse-output");  // tells the threads apart in top/perf
  BatchPipe<OutputEpoch*>::Batch batch;
  try {
    while (pipe_.take(batch)) {
      for (OutputEpoch* e : batch) {
        e->fill_deferred_solution();  // the filter thread only captured it
        outputs_.write(*e);
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
