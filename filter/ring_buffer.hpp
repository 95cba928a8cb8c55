// Fixed-capacity FIFO whose storage is allocated once, at construction: the state history for
// late measurements lives in these so the per-sample path never touches the heap.
#pragma once

#include <cstddef>
#include <vector>

namespace navfuse::filter {

template <class T>
class RingBuffer {
 public:
  explicit RingBuffer(std::size_t capacity = 1) : items_(capacity == 0 ? 1 : capacity) {}

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return items_.size(); }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; head_ = 0; }

  // Appends, dropping the oldest item when full.
  void push_back(const T& item) {
    if (size_ == items_.size()) pop_front();
    items_[(head_ + size_) % items_.size()] = item;
    ++size_;
  }
  void pop_front() {
    head_ = (head_ + 1) % items_.size();
    --size_;
  }
  void pop_back() { --size_; }

  // 0 is the oldest item.
  T& operator[](std::size_t i) { return items_[(head_ + i) % items_.size()]; }
  const T& operator[](std::size_t i) const { return items_[(head_ + i) % items_.size()]; }
  T& front() { return (*this)[0]; }
  T& back() { return (*this)[size_ - 1]; }
  const T& front() const { return (*this)[0]; }
  const T& back() const { return (*this)[size_ - 1]; }

 private:
  std::vector<T> items_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace navfuse::filter
