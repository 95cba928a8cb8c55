// Owning wrapper for a POSIX file descriptor, plus the small helpers the transports share:
// a monotonic deadline for "never block longer than the timeout" and errno formatting.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

namespace navfuse::io {

class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(UniqueFd&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  UniqueFd& operator=(UniqueFd&& other) noexcept {
    if (this != &other) reset(std::exchange(other.fd_, -1));
    return *this;
  }
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  ~UniqueFd() { reset(); }

  int get() const { return fd_; }
  explicit operator bool() const { return fd_ >= 0; }
  void reset(int fd = -1) {
    // close(2) errors are not actionable here: POSIX leaves the descriptor state unspecified
    // after EINTR and Linux always frees it, so retrying could close someone else's descriptor.
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_ = -1;
};

// A point in time `timeout_ms` from now on the monotonic clock (immune to wall-clock steps).
class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  explicit Deadline(int timeout_ms) : end_(Clock::now() + std::chrono::milliseconds(std::max(timeout_ms, 0))) {}
  // Milliseconds left, rounded up so a poll(2) never returns just before the deadline and spins.
  int remaining_ms() const {
    const auto left = end_ - Clock::now();
    if (left <= Clock::duration::zero()) return 0;
    return static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(left).count());
  }
  bool expired() const { return Clock::now() >= end_; }
  Clock::time_point when() const { return end_; }

 private:
  Clock::time_point end_;
};

// Milliseconds from now until `t` (0 if already past), for poll(2) timeouts.
inline int ms_until(Deadline::Clock::time_point t) {
  const auto left = t - Deadline::Clock::now();
  if (left <= Deadline::Clock::duration::zero()) return 0;
  return static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(left).count());
}

// "connect: Connection refused" from a call name and an errno value.
inline std::string errno_text(std::string_view call, int err) {
  return std::string(call) + ": " + std::strerror(err);
}

}  // namespace navfuse::io
