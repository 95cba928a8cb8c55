#include "apps/output/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {

// Large enough that a pose stream at several MB/s costs few write(2) calls.
constexpr std::size_t kFileBufferBytes = 1 << 20;
// Streams (pipes, terminals, devices) see data in pieces this size, not a megabyte at a time.
constexpr std::size_t kStreamBufferBytes = 1 << 16;

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
  std::size_t buffer_bytes = kFileBufferBytes;
  if (in_place) {
    const int fd = open_in_place(path_);
    if (fd < 0) cannot_open(path_, std::strerror(errno));
    file_ = ::fdopen(fd, "wb");
    if (file_ == nullptr) {
      const int error = errno;
      ::close(fd);
      cannot_open(path_, std::strerror(error));
    }
    final_path_ = path_;
    buffer_bytes = kStreamBufferBytes;
  } else {
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
  }
  buffer_.resize(buffer_bytes);
  std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_ && !in_place()) std::remove(partial_path_.c_str());
}

void OutputFile::write(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return;
  if (file_ == nullptr) fail("write after commit", EBADF);
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail("write error", errno);
  bytes_ += bytes.size();
}

void OutputFile::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void OutputFile::commit() {
  if (committed_) return;
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
