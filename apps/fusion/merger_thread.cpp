#include "apps/fusion/merger_thread.hpp"

#include <pthread.h>

#include <stdexcept>

#include "core/cpu/prefetch.hpp"

namespace navfuse::apps {
namespace {
// 512 measurements (~220 kB) per hand-over: ~0.5 ms of a 200 Hz log at replay speed, so the
// lock is taken a few thousand times a second at most; 6 buffers let either side run ahead.
constexpr std::size_t kBatchMeasurements = 512;
constexpr std::size_t kBatches = 6;

struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("log reading cancelled") {}
};
}  // namespace

MergerThread::MergerThread(MeasurementMerger& merger)
    : merger_(merger), pipe_(kBatchMeasurements, kBatches), thread_([this] { run(); }) {}

MergerThread::~MergerThread() { stop(); }

void MergerThread::stop() {
  if (!thread_.joinable()) return;
  pipe_.fail(std::make_exception_ptr(Cancelled()));
  thread_.join();
}

void MergerThread::run() {
  pthread_setname_np(pthread_self(), "navfuse-decode");  // tells the threads apart in top/perf
  try {
    for (;;) {
      const Measurement* m = merger_.next();
      if (m == nullptr) break;
      // Copy-constructed in place: only the measurement's own bytes are written, not the whole
      // variant (a default-constructed one is zeroed first: 704 bytes for an 88-byte IMU sample).
      pipe_.filling().push_back(*m);
      bytes_read_.store(merger_.bytes_read(), std::memory_order_relaxed);
      pipe_.hand_over_if_full();
    }
    pipe_.close();
  } catch (const Cancelled&) {
    pipe_.close(std::current_exception());  // the consumer has gone: nobody reads this
  } catch (...) {
    pipe_.close(std::current_exception());
  }
}

const Measurement* MergerThread::next() {
  while (position_ >= batch_.size()) {
    position_ = 0;
    if (!pipe_.take(batch_)) return nullptr;
  }
  // The batch was written on the reading thread's core: ask for a measurement a few ahead, the
  // lines its kind and its first fields are in (an IMU sample: the first two; the variant keeps
  // its index after the largest alternative, in the last), not all eleven (cpu/prefetch.hpp).
  constexpr std::size_t kAhead = 4;
  if (position_ + kAhead < batch_.size()) {
    const Measurement* ahead = &batch_[position_ + kAhead];
    cpu::prefetch<cpu::Intent::kRead>(ahead, 2 * cpu::kCacheLineBytes);
    cpu::prefetch<cpu::Intent::kRead>(reinterpret_cast<const char*>(ahead + 1) - 1, 1);
  }
  return &batch_[position_++];
}

void MergerThread::join() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace navfuse::apps
