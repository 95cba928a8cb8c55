#include "apps/output/output_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <memory>

#include "apps/common/command_error.hpp"
#include "apps/common/interrupt_signals.hpp"

namespace navfuse::apps {
namespace {

// Large enough that a pose stream at several MB/s costs few write(2) calls.
constexpr std::size_t kFileBufferBytes = 1 << 20;
// A regular file's writeback is started every this many bytes, by the thread that writes them
// (see OutputFile::write).
constexpr std::uint64_t kWritebackStartBytes = 4 << 20;
// Streams (pipes, terminals, devices) see data in pieces this size, not a megabyte at a time.
constexpr std::size_t kStreamBufferBytes = 1 << 16;
// One write(2) to a stream after poll(2) reported room: a pipe with room takes PIPE_BUF (4096 on
// Linux, pipe(7)) bytes without blocking, so a stalled reader cannot block a write this size.
constexpr std::size_t kStreamWriteBytes = 4096;
// After Ctrl-C / SIGTERM, a reader that takes no byte for this long is taken as stalled (a
// reader that is merely slow gets the rest of the complete frames).
constexpr int kStalledReaderMs = 1000;

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// Paths the system provides, written in place whatever they point at: /dev/stdout of a shell
// redirected to a file is a link to that file, and replacing it would cut the shell's output.
bool system_path(const std::string& path) {
  return path == "-" || starts_with(path, "/dev/") || starts_with(path, "/proc/");
}

[[noreturn]] void cannot_open(const std::string& path, const std::string& why) {
  throw CommandError("cannot write '" + path + "': " + why);
}

// The descriptor for an in-place output. Standard output is duplicated, so that this file's
// writes share its offset and closing this file leaves it open.
int open_in_place(const std::string& path) {
  if (path == "-" || path == "/dev/stdout") return ::dup(STDOUT_FILENO);
  if (path == "/dev/stderr") return ::dup(STDERR_FILENO);
  // No O_CREAT: an absent device is an error, not a new regular file in /dev. O_TRUNC matters
  // only for a regular file reached through /proc or /dev/fd, which is then rewritten like `>`.
  return ::open(path.c_str(), O_WRONLY | O_TRUNC | O_NOCTTY | O_CLOEXEC);
}

}  // namespace

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  const bool in_place = system_path(path_) || (exists && !S_ISREG(st.st_mode));
  if (in_place) {
    fd_ = open_in_place(path_);
    if (fd_ < 0) cannot_open(path_, std::strerror(errno));
    final_path_ = path_;
    buffer_.resize(kStreamBufferBytes);
    return;
  }
  struct stat link {};
  final_path_ = path_;
  if (::lstat(path_.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    // A link to a regular file: replace the target, keep the link. A dangling link is refused
    // rather than replaced by a file.
    std::unique_ptr<char, decltype(&std::free)> target(::realpath(path_.c_str(), nullptr), &std::free);
    if (!exists || target == nullptr) cannot_open(path_, "it is a symbolic link to a missing file");
    final_path_ = target.get();
  }
  partial_path_ = final_path_ + ".partial";
  file_ = std::fopen(partial_path_.c_str(), "wb");
  if (file_ == nullptr) cannot_open(path_, std::strerror(errno));
  buffer_.resize(kFileBufferBytes);
  std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !in_place()) std::remove(partial_path_.c_str());
}

void OutputFile::write(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return;
  if (committed_) fail("write after commit", EBADF);
  if (in_place()) {
    while (!bytes.empty()) {
      if (buffered_ == buffer_.size()) flush_stream();
      const std::size_t n = std::min(bytes.size(), buffer_.size() - buffered_);
      std::memcpy(buffer_.data() + buffered_, bytes.data(), n);
      buffered_ += n;
      bytes_ += n;
      bytes = bytes.subspan(n);
    }
    return;
  }
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail("write error", errno);
  bytes_ += bytes.size();
  if (bytes_ - writeback_started_at_ >= kWritebackStartBytes) {
    // rename(2) onto an existing file makes ext4 start writeback of every dirty page of the new
    // file inside the call (auto_da_alloc, ext4(5)), so that a crash leaves the old or the new
    // content: ~20 ms for a 50 MB pose stream, on the committing thread after the run. Starting
    // it here as the bytes come (SYNC_FILE_RANGE_WRITE only queues the I/O, sync_file_range(2))
    // does the same work on the writer's thread while the run goes on, and leaves the rename
    // only the last pages. Advisory: an error here changes nothing the commit would report.
    ::sync_file_range(fileno(file_), 0, 0, SYNC_FILE_RANGE_WRITE);
    writeback_started_at_ = bytes_;
  }
}

void OutputFile::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void OutputFile::flush_stream() {
  std::size_t done = 0;
  while (done < buffered_) {
    pollfd fds[2] = {{.fd = fd_, .events = POLLOUT, .revents = 0},
                     {.fd = InterruptSignals::wake_fd(), .events = POLLIN, .revents = 0}};
    const nfds_t count = fds[1].fd >= 0 ? 2 : 1;
    if (::poll(fds, count, -1) < 0) {
      if (errno == EINTR) continue;
      fail("write error", errno);
    }
    // Room (or an error that write() will name) goes first: after a signal, whatever the reader
    // still takes is written; only a reader that takes nothing for kStalledReaderMs ends the
    // output.
    if (fds[0].revents == 0) {
      const int ready = ::poll(fds, 1, kStalledReaderMs);
      if (ready < 0) continue;  // another signal: look again
      if (ready == 0) {
        const int signal_number = InterruptSignals::received().load(std::memory_order_relaxed);
        throw CommandError("stopped writing '" + path_ + "' on signal " + std::to_string(signal_number) +
                               ": its reader took no more data",
                           interrupted_exit_code(signal_number));
      }
    }
    const ssize_t n = ::write(fd_, buffer_.data() + done, std::min(kStreamWriteBytes, buffered_ - done));
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      fail("write error", errno);
    }
    done += static_cast<std::size_t>(n);
  }
  buffered_ = 0;
}

void OutputFile::commit() {
  if (committed_) return;
  if (in_place()) {
    flush_stream();
    const int close_error = ::close(fd_) == 0 ? 0 : errno;
    fd_ = -1;
    committed_ = true;
    if (close_error != 0) fail("write error", close_error);
    return;
  }
  const int flush_error = std::fflush(file_) == 0 ? 0 : errno;
  const int close_error = std::fclose(file_) == 0 ? 0 : errno;
  file_ = nullptr;
  if (flush_error != 0 || close_error != 0) fail("write error", flush_error != 0 ? flush_error : close_error);
  if (!in_place() && std::rename(partial_path_.c_str(), final_path_.c_str()) != 0) {
    fail("cannot rename the finished file", errno);
  }
  committed_ = true;
}

void OutputFile::fail(const char* what, int error) {
  throw CommandError("cannot write '" + path_ + "': " + what + " (" + std::strerror(error) + ")");
}

}  // namespace navfuse::apps
