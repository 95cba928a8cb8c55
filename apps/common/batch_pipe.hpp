// Batches of T from one producer thread to one consumer thread, in order, with bounded memory:
// how a replay spreads over the machine's cores (log decoding -> filter -> output encoding)
// without a lock per item and without allocating per item.
//
// A fixed set of batch buffers circulates: the producer fills one and hands it over, the
// consumer takes it, uses it and gives it back with its next take(). When every buffer is in
// the consumer's queue the producer waits, so a slow consumer slows the producer down instead
// of growing memory; nothing is dropped (this is for logs, not for live links).
//
// Errors cross in both directions and keep their place: a producer's close(error) is rethrown
// by the consumer's take() after the batches handed over before it; a consumer's fail(error)
// is rethrown by the producer's next hand_over() or close().
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <utility>
#include <vector>

namespace navfuse::apps {

template <class T>
class BatchPipe {
 public:
  using Batch = std::vector<T>;

  // `batches` buffers of `batch_size` reserved items each (>= 2 buffers: one each side).
  BatchPipe(std::size_t batch_size, std::size_t batches) : batch_size_(batch_size) {
    filling_.reserve(batch_size);
    for (std::size_t i = 1; i < batches; ++i) {
      free_.emplace_back();
      free_.back().reserve(batch_size);
    }
  }

  // ---- producer ----
  // The batch being filled: append to it, then call hand_over_if_full() (or hand_over()).
  Batch& filling() { return filling_; }
  void hand_over_if_full() {
    if (filling_.size() >= batch_size_) hand_over();
  }
  // Hands the filling batch over (waits for a free buffer); rethrows the consumer's failure.
  void hand_over() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !free_.empty() || consumer_error_; });
    if (consumer_error_) std::rethrow_exception(consumer_error_);
    full_.push_back(std::move(filling_));
    filling_ = std::move(free_.back());
    free_.pop_back();
    filling_.clear();
    lock.unlock();
    changed_.notify_all();
  }
  // No more batches: hands over what is filled, then the end (with the producer's error, if
  // any). Rethrows the consumer's failure when there is one and no error of its own is passed.
  void close(std::exception_ptr error = nullptr) {
    std::unique_lock lock(mutex_);
    if (!filling_.empty() && !consumer_error_) {
      full_.push_back(std::move(filling_));
      filling_ = Batch();
    }
    closed_ = true;
    producer_error_ = error;
    const std::exception_ptr consumer_error = consumer_error_;
    lock.unlock();
    changed_.notify_all();
    if (consumer_error && !error) std::rethrow_exception(consumer_error);
  }

  // ---- consumer ----
  // Gives `batch` back (its contents are done with) and takes the next one; false once the
  // producer closed and every batch was taken. Rethrows the producer's error in its place.
  bool take(Batch& batch) {
    std::unique_lock lock(mutex_);
    if (batch.capacity() > 0) {
      batch.clear();
      free_.push_back(std::move(batch));
      batch = Batch();
      changed_.notify_all();
    }
    changed_.wait(lock, [this] { return !full_.empty() || closed_; });
    if (full_.empty()) {
      if (producer_error_) std::rethrow_exception(producer_error_);
      return false;
    }
    batch = std::move(full_.front());
    full_.pop_front();
    return true;
  }
  // What the consumer failed with (nullptr: nothing), for a producer that waited for it to end.
  std::exception_ptr consumer_failure() {
    std::lock_guard lock(mutex_);
    return consumer_error_;
  }
  // The consumer gives up: the producer's next hand_over() or close() rethrows `error`.
  void fail(std::exception_ptr error) {
    {
      std::lock_guard lock(mutex_);
      consumer_error_ = error;
    }
    changed_.notify_all();
  }

 private:
  const std::size_t batch_size_;
  Batch filling_;  // producer side only

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Batch> full_;  // oldest first
  std::vector<Batch> free_;
  bool closed_ = false;
  std::exception_ptr producer_error_;
  std::exception_ptr consumer_error_;
};

}  // namespace navfuse::apps
