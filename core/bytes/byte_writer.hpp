// Little- and big-endian writers appending to a caller-owned byte vector, plus in-place patching
// (for length and checksum fields written after the payload); SpanWriter writes the same way
// into bytes that already exist (a frame whose size is known, grown once), without a vector
// insert per field, and ByteCounter counts what would be written.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace navfuse::bytes {
namespace detail {

// `value` in the given byte order, into sizeof(T) bytes at `raw`.
template <bool kLittle, typename T>
void to_bytes(T value, std::uint8_t* raw) {
  static_assert(std::is_arithmetic_v<T>, "write() takes integers and floating point");
  std::memcpy(raw, &value, sizeof(T));
  constexpr bool native_little = std::endian::native == std::endian::little;
  if constexpr (sizeof(T) > 1 && kLittle != native_little) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  }
}

}  // namespace detail

template <bool kLittle>
class Writer {
 public:
  explicit Writer(std::vector<std::uint8_t>& out) : out_(out) {}

  template <typename T>
  void write(T value) {
    std::uint8_t raw[sizeof(T)];
    detail::to_bytes<kLittle>(value, raw);
    out_.insert(out_.end(), raw, raw + sizeof(T));
  }
  void u8(std::uint8_t v) { write(v); }
  void i8(std::int8_t v) { write(v); }
  void u16(std::uint16_t v) { write(v); }
  void i16(std::int16_t v) { write(v); }
  void u32(std::uint32_t v) { write(v); }
  void i32(std::int32_t v) { write(v); }
  void u64(std::uint64_t v) { write(v); }
  void i64(std::int64_t v) { write(v); }
  void f32(float v) { write(v); }
  void f64(double v) { write(v); }
  void bytes(std::span<const std::uint8_t> b) { out_.insert(out_.end(), b.begin(), b.end()); }
  void zeros(std::size_t n) { out_.insert(out_.end(), n, 0); }

  // Overwrites sizeof(T) bytes at absolute offset `at` of the vector (must already exist).
  template <typename T>
  void patch(std::size_t at, T value) {
    detail::to_bytes<kLittle>(value, out_.data() + at);
  }

  std::size_t size() const { return out_.size(); }

 private:
  std::vector<std::uint8_t>& out_;
};

using LeWriter = Writer<true>;
using BeWriter = Writer<false>;

// Writer's appending calls, into a span from its start: what Writer would append, at the same
// offsets. Writing past the span's end throws std::length_error (a size computed wrongly), and
// written() says how far it got.
template <bool kLittle>
class SpanWriter {
 public:
  explicit SpanWriter(std::span<std::uint8_t> out) : out_(out) {}

  template <typename T>
  void write(T value) {
    detail::to_bytes<kLittle>(value, take(sizeof(T)));
  }
  void u8(std::uint8_t v) { write(v); }
  void u16(std::uint16_t v) { write(v); }
  void u32(std::uint32_t v) { write(v); }
  void u64(std::uint64_t v) { write(v); }
  void bytes(std::span<const std::uint8_t> b) {
    if (!b.empty()) std::memcpy(take(b.size()), b.data(), b.size());
  }
  void zeros(std::size_t n) {
    if (n > 0) std::memset(take(n), 0, n);
  }

  std::size_t written() const { return at_; }

 private:
  std::uint8_t* take(std::size_t n) {
    if (n > out_.size() - at_) throw std::length_error("SpanWriter: write past the end of the span");
    std::uint8_t* p = out_.data() + at_;
    at_ += n;
    return p;
  }

  std::span<std::uint8_t> out_;
  std::size_t at_ = 0;
};

using LeSpanWriter = SpanWriter<true>;

// Writer's appending calls, only counted: the size of what they would write.
class ByteCounter {
 public:
  template <typename T>
  void write(T) {
    static_assert(std::is_arithmetic_v<T>, "write() takes integers and floating point");
    n_ += sizeof(T);
  }
  void u8(std::uint8_t v) { write(v); }
  void u16(std::uint16_t v) { write(v); }
  void u32(std::uint32_t v) { write(v); }
  void u64(std::uint64_t v) { write(v); }
  void bytes(std::span<const std::uint8_t> b) { n_ += b.size(); }
  void zeros(std::size_t n) { n_ += n; }

  std::size_t written() const { return n_; }

 private:
  std::size_t n_ = 0;
};

}  // namespace navfuse::bytes
