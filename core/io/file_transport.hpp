// File transport: a recorded log as input, or a file output, behind the Transport interface.
//
//  - Input (Direction::kInput): read-only; read() returns kEndOfStream at end of file. For
//    pipes and FIFOs (and file:- = stdin) read() waits with poll(2) up to the timeout.
//  - Output (Direction::kOutput): created or truncated (mode 0644 before umask); write() writes
//    the whole message, blocking only as long as the kernel takes to accept it (regular files
//    cannot be non-blocking, POSIX open(2) O_NONBLOCK). file:- is stdout.
//  - reopen(): an input starts again from the beginning; an output re-opens for appending, so
//    nothing already written is lost (e.g. after log rotation moved the file away).
#pragma once

#include <string>

#include "core/io/transport.hpp"
#include "core/io/unique_fd.hpp"

namespace navfuse::io {

class FileTransport : public Transport {
 public:
  // Opens now; throws TransportError naming the path if that fails or if direction is kBoth.
  FileTransport(std::string path, Direction direction);

  std::ptrdiff_t read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  std::ptrdiff_t write(std::span<const std::uint8_t> data) override;
  bool is_open() const override { return fd_ >= 0; }
  bool reopen() override;
  std::string describe() const override;

 private:
  int open_path(bool append);  // returns the descriptor or -1 (errno set)

  std::string path_;
  Direction direction_;
  UniqueFd owned_;  // empty for stdin/stdout, which are not ours to close
  int fd_ = -1;
  bool at_eof_ = false;
};

}  // namespace navfuse::io
