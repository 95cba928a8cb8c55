// An append-only sequence of fixed-size records kept in an anonymous temporary file, so that a
// command can hold a whole run's worth of samples (bench's solution tracks, aligned errors,
// error values for percentiles) in constant memory: only a write buffer and each reader's read
// buffer are in RAM. Like the smoother's forward record (filter/smoother/forward_record.hpp) the
// file is std::tmpfile(): deleted when closed, also when the process dies.
//
// The last record stays in memory until a later one is appended, so back() can amend it (a
// solution track merges an epoch's partial messages into its last sample). Readers use pread at
// their own offsets and see every record appended so far, also while appending goes on.
//
// Records are stored as their bytes: T must be trivially copyable, or opt in with
// kSpillableAsBytes<T> when it is a plain aggregate of values that own no memory (Eigen's
// fixed-size vectors are plain arrays of doubles but not trivially copyable by the trait).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {

template <class T>
inline constexpr bool kSpillableAsBytes = std::is_trivially_copyable_v<T>;

template <class T>
class SpillFile {
  static_assert(kSpillableAsBytes<T>, "SpillFile stores records as bytes: T must own no memory");

 public:
  // Records written to the file per write; the memory one SpillFile holds (about 64 kB of
  // doubles by default).
  explicit SpillFile(std::size_t buffer_records = 8192) : buffer_records_(buffer_records < 2 ? 2 : buffer_records) {}

  void push_back(const T& value) {
    if (buffer_.size() >= buffer_records_) flush_all_but_last();
    buffer_.push_back(value);
  }
  // The last record (always in memory); the sequence must not be empty.
  T& back() { return buffer_.back(); }
  const T& back() const { return buffer_.back(); }
  std::size_t size() const { return written_ + buffer_.size(); }
  bool empty() const { return size() == 0; }

  // Reads records in order from `first` (0: the start).
  class Reader {
   public:
    // False at the end.
    bool next(T& out) {
      if (index_ >= file_->size()) return false;
      if (index_ >= file_->written_) {
        out = file_->buffer_[index_++ - file_->written_];
        return true;
      }
      if (block_pos_ >= block_.size()) fill();
      out = block_[block_pos_++];
      ++index_;
      return true;
    }
    std::size_t index() const { return index_; }

   private:
    friend class SpillFile;
    Reader(const SpillFile* file, std::size_t first, std::size_t block_records)
        : file_(file), index_(first), block_records_(block_records) {}
    void fill() {
      const std::size_t n = std::min(block_records_, file_->written_ - index_);
      block_.resize(n);
      file_->read(index_, block_.data(), n);
      block_pos_ = 0;
    }
    const SpillFile* file_;
    std::size_t index_;
    std::size_t block_records_;
    std::vector<T> block_;
    std::size_t block_pos_ = 0;
  };
  // `block_records`: records read from the file at a time (the reader's memory).
  Reader reader(std::size_t first = 0, std::size_t block_records = 1024) const {
    return Reader(this, first, block_records < 1 ? 1 : block_records);
  }

  // Records [first, first + n) that are already in the file, into `out`.
  void read(std::size_t first, T* out, std::size_t n) const {
    const auto bytes = static_cast<std::size_t>(n * sizeof(T));
    const auto offset = static_cast<off_t>(first * sizeof(T));
    std::size_t done = 0;
    while (done < bytes) {
      const ssize_t got = ::pread(fd(), reinterpret_cast<char*>(static_cast<void*>(out)) + done, bytes - done,
                                  offset + static_cast<off_t>(done));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) throw CommandError("cannot read back a temporary file: " + reason(got));
      done += static_cast<std::size_t>(got);
    }
  }

 private:
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  int fd() const { return ::fileno(file_.get()); }
  static std::string reason(ssize_t got) { return got == 0 ? "file shorter than written" : std::strerror(errno); }

  void flush_all_but_last() {
    if (!file_) {
      file_.reset(std::tmpfile());
      if (!file_) throw CommandError(std::string("cannot create a temporary file: ") + std::strerror(errno));
    }
    const std::size_t n = buffer_.size() - 1;
    const auto bytes = static_cast<std::size_t>(n * sizeof(T));
    const auto offset = static_cast<off_t>(written_ * sizeof(T));
    std::size_t done = 0;
    while (done < bytes) {
      const ssize_t put = ::pwrite(fd(), reinterpret_cast<const char*>(static_cast<const void*>(buffer_.data())) + done,
                                   bytes - done, offset + static_cast<off_t>(done));
      if (put < 0 && errno == EINTR) continue;
      if (put <= 0) throw CommandError(std::string("cannot write a temporary file (disk full?): ") + std::strerror(errno));
      done += static_cast<std::size_t>(put);
    }
    written_ += n;
    buffer_.erase(buffer_.begin(), buffer_.end() - 1);
  }

  std::size_t buffer_records_;
  std::vector<T> buffer_;
  std::size_t written_ = 0;  // records in the file
  std::unique_ptr<std::FILE, Close> file_;
};

}  // namespace navfuse::apps
