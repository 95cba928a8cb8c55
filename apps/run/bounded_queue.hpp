// A fixed-capacity FIFO between threads of the nav process (input readers -> filter, filter ->
// output writers, filter -> LCM). Slots are allocated once, at construction, and reused: pushing
// copies into an existing slot, so a queue of measurements does not allocate per sample.
//
// Full queue policy is the caller's: try_push() refuses (the caller counts a drop: a slow
// consumer must never block the filter), push_wait() waits a bounded time (a file input may wait
// for the filter, a live device may not).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <vector>

namespace navfuse::apps {

template <class T>
class BoundedQueue {
 public:
  explicit BoundedQueue(std::size_t capacity) : slots_(capacity > 0 ? capacity : 1) {}

  // Copies `item` in; false (nothing changed) when the queue is full or closed.
  bool try_push(const T& item) {
    {
      std::lock_guard lock(mutex_);
      if (closed_ || size_ == slots_.size()) return false;
      put(item);
    }
    not_empty_.notify_one();
    return true;
  }

  // As try_push(), waiting up to `timeout` for room.
  template <class Rep, class Period>
  bool push_wait(const T& item, std::chrono::duration<Rep, Period> timeout) {
    {
      std::unique_lock lock(mutex_);
      if (!not_full_.wait_for(lock, timeout, [&] { return closed_ || size_ < slots_.size(); })) return false;
      if (closed_) return false;
      put(item);
    }
    not_empty_.notify_one();
    return true;
  }

  // Moves the oldest item into `out`; false when empty.
  bool try_pop(T& out) {
    {
      std::lock_guard lock(mutex_);
      if (size_ == 0) return false;
      take(out);
    }
    not_full_.notify_one();
    return true;
  }

  // As try_pop(), waiting up to `timeout` for an item (returns early, false, once closed and empty).
  template <class Rep, class Period>
  bool pop_wait(T& out, std::chrono::duration<Rep, Period> timeout) {
    {
      std::unique_lock lock(mutex_);
      if (!not_empty_.wait_for(lock, timeout, [&] { return closed_ || size_ > 0; })) return false;
      if (size_ == 0) return false;
      take(out);
    }
    not_full_.notify_one();
    return true;
  }

  // No more pushes; waiting consumers and producers wake up. Items already queued stay poppable.
  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    not_empty_.notify_all();
    not_full_.notify_all();
  }

  bool empty() const {
    std::lock_guard lock(mutex_);
    return size_ == 0;
  }
  std::size_t capacity() const { return slots_.size(); }

 private:
  void put(const T& item) {
    slots_[(head_ + size_) % slots_.size()] = item;
    ++size_;
  }
  void take(T& out) {
    // Swap rather than move: the slot keeps `out`'s old storage, so element types that own
    // buffers recycle them instead of allocating again.
    using std::swap;
    swap(out, slots_[head_]);
    head_ = (head_ + 1) % slots_.size();
    --size_;
  }

  mutable std::mutex mutex_;
  std::condition_variable not_empty_;
  std::condition_variable not_full_;
  std::vector<T> slots_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  bool closed_ = false;
};

}  // namespace navfuse::apps
