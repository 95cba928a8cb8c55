#include "apps/common/input_bytes.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {

InputBytes::InputBytes(const InputSpec& spec) : spec_(spec) {
  if (spec.stream) {
    file_ = spec.stream.get();
    owns_file_ = false;
    return;
  }
  head_offset_ = spec.head.size();  // nothing to replay: the file is read again from its start
  file_ = std::fopen(spec.path.c_str(), "rb");
  if (file_ == nullptr) throw CommandError("cannot open input '" + spec.path + "': " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fileno(file_), &st) == 0 && st.st_size > 0) size_bytes_ = static_cast<std::uint64_t>(st.st_size);
}

InputBytes::~InputBytes() {
  if (file_ != nullptr && owns_file_) std::fclose(file_);
}

std::size_t InputBytes::read(std::span<std::uint8_t> out) {
  if (head_offset_ < spec_.head.size()) {
    const std::size_t n = std::min(out.size(), spec_.head.size() - head_offset_);
    std::copy_n(spec_.head.data() + head_offset_, n, out.data());
    head_offset_ += n;
    return n;
  }
  const std::size_t n = std::fread(out.data(), 1, out.size(), file_);
  if (n == 0 && std::ferror(file_)) throw CommandError("read error on input '" + spec_.path + "'");
  return n;
}

}  // namespace navfuse::apps
