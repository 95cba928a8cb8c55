#include "apps/output/output_file.hpp"

#include <cerrno>
#include <cstring>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {
// Large enough that a pose stream at several MB/s costs few write(2) calls.
constexpr std::size_t kBufferBytes = 1 << 20;
}  // namespace

OutputFile::OutputFile(std::string path) : path_(std::move(path)), partial_path_(path_ + ".partial") {
  file_ = std::fopen(partial_path_.c_str(), "wb");
  if (file_ == nullptr) {
    throw CommandError("cannot write '" + path_ + "': " + std::strerror(errno));
  }
  buffer_.resize(kBufferBytes);
  std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_) std::remove(partial_path_.c_str());
}

void OutputFile::write(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail("write error");
  bytes_ += bytes.size();
}

void OutputFile::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void OutputFile::commit() {
  if (committed_) return;
  const bool flushed = std::fflush(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) fail("write error");
  if (std::rename(partial_path_.c_str(), path_.c_str()) != 0) fail("cannot rename the finished file");
  committed_ = true;
}

void OutputFile::fail(const char* what) {
  throw CommandError("cannot write '" + path_ + "': " + what + " (" + std::strerror(errno) + ")");
}

}  // namespace navfuse::apps
