// The bytes of one resolved input, from the first: a regular file is opened again from its
// start; a pipe, FIFO or device (which cannot be read twice) gives first the bytes detection read
// (InputSpec::head), then goes on from where detection stopped. `decode`, `replay` and `bench`
// all read their inputs through this, so `cat log | navfuse replay vn:/dev/stdin` loses nothing.
#pragma once

#include <cstdint>
#include <cstdio>
#include <span>

#include "apps/common/input_spec.hpp"

namespace navfuse::apps {

class InputBytes {
 public:
  // Throws CommandError naming the file when it cannot be opened.
  explicit InputBytes(const InputSpec& spec);
  ~InputBytes();
  InputBytes(const InputBytes&) = delete;
  InputBytes& operator=(const InputBytes&) = delete;

  // Up to out.size() bytes; 0 at the end. Throws CommandError on a read error.
  std::size_t read(std::span<std::uint8_t> out);
  // The file's size when it is a regular file, else 0 (for progress display).
  std::uint64_t size_bytes() const { return size_bytes_; }

 private:
  const InputSpec& spec_;
  std::FILE* file_ = nullptr;
  bool owns_file_ = true;
  std::size_t head_offset_ = 0;  // bytes of spec_.head given out so far (streams only)
  std::uint64_t size_bytes_ = 0;
};

}  // namespace navfuse::apps
