// File transport (file_transport.hpp).
#include "core/io/file_transport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace navfuse::io {

FileTransport::FileTransport(std::string path, Direction direction)
    : path_(std::move(path)), direction_(direction) {
  if (direction_ == Direction::kBoth) {
    throw TransportError("file:" + path_ + ": a file is either an input or an output, not both");
  }
  if (open_path(false) < 0) {
    throw TransportError("file:" + path_ + ": " + errno_text(direction_ == Direction::kInput
                                                                  ? "cannot open for reading"
                                                                  : "cannot create",
                                                              errno));
  }
}

int FileTransport::open_path(bool append) {
  owned_.reset();
  fd_ = -1;
  at_eof_ = false;
  if (path_ == "-") {
    fd_ = direction_ == Direction::kInput ? STDIN_FILENO : STDOUT_FILENO;
    return fd_;
  }
  const int flags = direction_ == Direction::kInput
                        ? O_RDONLY
                        : O_WRONLY | O_CREAT | (append ? O_APPEND : O_TRUNC);
  owned_.reset(::open(path_.c_str(), flags | O_CLOEXEC, 0644));
  fd_ = owned_.get();
  return fd_;
}

bool FileTransport::reopen() {
  if (open_path(direction_ == Direction::kOutput) < 0) {
    record_error("file:" + path_ + ": " + errno_text("open", errno));
    return false;
  }
  ++stats_.reconnects;
  return true;
}

std::ptrdiff_t FileTransport::read(std::span<std::uint8_t> buffer, int timeout_ms) {
  if (direction_ != Direction::kInput || fd_ < 0 || at_eof_) return kEndOfStream;
  // A regular file always polls readable; a pipe or FIFO waits here for the writer.
  pollfd p{fd_, POLLIN, 0};
  for (;;) {
    const int ready = ::poll(&p, 1, std::max(timeout_ms, 0));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) {
      record_error("file:" + path_ + ": " + errno_text("poll", errno));
      return 0;
    }
    if (ready == 0) return 0;
    break;
  }
  for (;;) {
    const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
    if (n > 0) {
      stats_.bytes_read += static_cast<std::uint64_t>(n);
      return n;
    }
    if (n == 0) {
      at_eof_ = true;
      return kEndOfStream;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN) return 0;
    record_error("file:" + path_ + ": " + errno_text("read", errno));
    return 0;
  }
}

std::ptrdiff_t FileTransport::write(std::span<const std::uint8_t> data) {
  if (direction_ != Direction::kOutput || fd_ < 0) {
    stats_.bytes_dropped += data.size();
    return 0;
  }
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd_, data.data() + done, data.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      stats_.bytes_written += static_cast<std::uint64_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      // ENOSPC, EIO, EPIPE (stdout closed; SIGPIPE is the shell's default, so callers that
      // write to a pipe should ignore SIGPIPE): the rest of this message is lost.
      record_error("file:" + path_ + ": " + errno_text("write", n < 0 ? errno : EIO));
      stats_.bytes_dropped += data.size() - done;
      return 0;
    }
  }
  return static_cast<std::ptrdiff_t>(data.size());
}

std::string FileTransport::describe() const {
  return "file:" + path_ + (direction_ == Direction::kInput ? " (input" : " (output") +
         (fd_ >= 0 ? (at_eof_ ? ", at end)" : ")") : ", closed)");
}

}  // namespace navfuse::io
