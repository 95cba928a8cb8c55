// A binary or text output file that only appears under its final name when complete.
//
// Bytes go to "<path>.partial" through a large stdio buffer; commit() flushes, closes and renames
// it onto `path` (rename(2) is atomic within a file system, so a reader sees either the old file
// or the whole new one). Destroying an uncommitted OutputFile (an error or exception unwound the
// run) deletes the partial file, so nothing half-written is left looking complete.
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
  // Opens "<path>.partial" for writing; throws CommandError naming `path` when it cannot.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(std::span<const std::uint8_t> bytes);
  void write(std::string_view text);
  // Flushes and renames onto the final path; throws CommandError on any write error.
  void commit();

  const std::string& path() const { return path_; }
  std::uint64_t bytes_written() const { return bytes_; }

 private:
  void fail(const char* what);

  std::string path_;
  std::string partial_path_;
  std::FILE* file_ = nullptr;
  std::vector<char> buffer_;
  std::uint64_t bytes_ = 0;
  bool committed_ = false;
};

}  // namespace navfuse::apps
