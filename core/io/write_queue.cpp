#include "core/io/write_queue.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

namespace navfuse::io {

std::ptrdiff_t WriteQueue::send_some(int fd, bool is_socket, std::span<const std::uint8_t> data) {
  std::size_t sent = 0;
  while (sent < data.size()) {
    const std::uint8_t* p = data.data() + sent;
    const std::size_t len = data.size() - sent;
    const ssize_t n = is_socket ? ::send(fd, p, len, MSG_NOSIGNAL | MSG_DONTWAIT) : ::write(fd, p, len);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      break;  // the kernel buffer is full: keep the rest
    } else {
      error_ = n < 0 ? errno : EIO;
      return -1;
    }
  }
  return static_cast<std::ptrdiff_t>(sent);
}

WriteQueue::Result WriteQueue::flush(int fd, bool is_socket, std::uint64_t& bytes_written) {
  if (empty()) return Result::kOk;
  const std::ptrdiff_t n = send_some(fd, is_socket, std::span(pending_).subspan(head_));
  if (n < 0) return Result::kError;
  head_ += static_cast<std::size_t>(n);
  bytes_written += static_cast<std::uint64_t>(n);
  if (empty()) clear();  // reuse the storage from the start
  return Result::kOk;
}

WriteQueue::Result WriteQueue::write(int fd, bool is_socket, std::span<const std::uint8_t> data,
                                     std::uint64_t& bytes_written) {
  if (flush(fd, is_socket, bytes_written) == Result::kError) return Result::kError;
  if (queued_bytes() + data.size() > capacity_) return Result::kOverflow;
  std::size_t sent = 0;
  if (empty()) {  // nothing ahead of it: try the kernel first, keeping byte order
    const std::ptrdiff_t n = send_some(fd, is_socket, data);
    if (n < 0) return Result::kError;
    sent = static_cast<std::size_t>(n);
    bytes_written += sent;
  }
  if (head_ > 0 && head_ >= pending_.size() / 2) {  // compact before growing
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(head_));
    head_ = 0;
  }
  pending_.insert(pending_.end(), data.begin() + static_cast<std::ptrdiff_t>(sent), data.end());
  return Result::kOk;
}

}  // namespace navfuse::io
