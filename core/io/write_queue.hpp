// Bounded output queue for a non-blocking stream descriptor (serial port, TCP socket).
//
// write() must never block, but a non-blocking write(2)/send(2) may take only part of a message
// (POSIX write(2): "the write may transfer fewer bytes than requested"). Sending the head and
// forgetting the tail would leave a cut frame in the stream, so the unsent tail is kept here and
// flushed when the descriptor is writable again. A message that does not fit in the remaining
// capacity is refused whole; the caller decides what that means (drop the message, or drop the
// client that is not keeping up).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace navfuse::io {

class WriteQueue {
 public:
  enum class Result {
    kOk,        // sent or queued whole
    kOverflow,  // refused whole: would exceed the capacity
    kError,     // the descriptor failed (errno in error())
  };

  explicit WriteQueue(std::size_t capacity) : capacity_(capacity) {}

  // Flushes what is queued, then sends or queues `data` whole. `is_socket` selects send(2) with
  // MSG_NOSIGNAL (no SIGPIPE from a vanished peer) over write(2). Adds to `bytes_written`.
  Result write(int fd, bool is_socket, std::span<const std::uint8_t> data,
               std::uint64_t& bytes_written);
  // Sends as much of the queue as the descriptor takes now.
  Result flush(int fd, bool is_socket, std::uint64_t& bytes_written);

  bool empty() const { return head_ == pending_.size(); }
  std::size_t queued_bytes() const { return pending_.size() - head_; }
  void clear() {
    pending_.clear();
    head_ = 0;
  }
  int error() const { return error_; }

 private:
  // Sends from `data`; returns bytes taken (possibly 0), or -1 on a real error.
  std::ptrdiff_t send_some(int fd, bool is_socket, std::span<const std::uint8_t> data);

  std::size_t capacity_;
  std::vector<std::uint8_t> pending_;
  std::size_t head_ = 0;  // first unsent byte of pending_
  int error_ = 0;
};

}  // namespace navfuse::io
