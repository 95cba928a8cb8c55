// A binary or text output of a command (replay --fe-out/--mip-out/--csv, sim --out, ...). What is
// at the path decides how it is written, so that navfuse never replaces what it did not create:
//
//  - A regular file, or nothing yet: bytes go to "<path>.partial" through a large stdio buffer;
//    commit() flushes, closes and renames it onto the path (rename(2) is atomic within a file
//    system, so a reader sees either the old file or the whole new one). Destroying an
//    uncommitted OutputFile (an error unwound the run) deletes the partial file, so nothing
//    half-written is left looking complete. A symbolic link to a regular file is followed: its
//    target is replaced that way and the link stays.
//  - Anything else, written in place and streaming, never renamed or removed: a device node, a
//    FIFO, a socket, a link to one of those, "-" (standard output), and every path under /dev
//    or /proc (/dev/stdout, /dev/null, /dev/fd/N: the system's, whatever they point at).
//
// Every write error (ENOSPC, EPIPE, EIO, ...) is a CommandError naming the path and the reason,
// from write() or at the latest from commit(). A pipe whose reader went away gives EPIPE only
// when SIGPIPE is ignored, as main() does.
//
// An in-place output waits for room with poll(2) next to InterruptSignals::wake_fd(): after
// Ctrl-C / SIGTERM it still writes while the reader takes data, but a reader that stalls (a FIFO
// nobody drains) no longer holds the process: the write ends in a CommandError with exit status
// 128 + signal instead of blocking forever.
#pragma once

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::apps {

class OutputFile {
 public:
  // Opens the output (see above); throws CommandError naming `path` when it cannot. Opening a
  // FIFO waits for a reader, as open(2) does.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(std::span<const std::uint8_t> bytes);
  void write(std::string_view text);
  // Flushes (and for a regular file renames onto the final path); throws CommandError on any
  // write error.
  void commit();

  const std::string& path() const { return path_; }
  std::uint64_t bytes_written() const { return bytes_; }
  // True when written in place (not a regular file): nothing is renamed or removed.
  bool in_place() const { return partial_path_.empty(); }

 private:
  [[noreturn]] void fail(const char* what, int error);

  std::string path_;          // as given, for messages
  std::string final_path_;    // what commit() renames onto (a link's target)
  std::string partial_path_;  // empty when written in place
  void flush_stream();  // in place: the buffered bytes to fd_

  std::FILE* file_ = nullptr;  // regular file (.partial)
  int fd_ = -1;                // in place
  std::vector<char> buffer_;   // stdio's buffer, or the in-place bytes not yet written
  std::size_t buffered_ = 0;   // in place: bytes of buffer_ in use
  std::uint64_t bytes_ = 0;
  std::uint64_t writeback_started_at_ = 0;  // regular file: bytes_ when writeback was last started
  bool committed_ = false;
};

}  // namespace navfuse::apps
