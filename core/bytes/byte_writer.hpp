// Little- and big-endian writers appending to a caller-owned byte vector, plus in-place patching
// (for length and checksum fields written after the payload).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace navfuse::bytes {

template <bool kLittle>
class Writer {
 public:
  explicit Writer(std::vector<std::uint8_t>& out) : out_(out) {}

  template <typename T>
  void write(T value) {
    std::uint8_t raw[sizeof(T)];
    to_bytes(value, raw);
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
    to_bytes(value, out_.data() + at);
  }

  std::size_t size() const { return out_.size(); }

 private:
  // `value` in the writer's byte order, into sizeof(T) bytes at `raw`.
  template <typename T>
  static void to_bytes(T value, std::uint8_t* raw) {
    static_assert(std::is_arithmetic_v<T>, "write() takes integers and floating point");
    std::memcpy(raw, &value, sizeof(T));
    constexpr bool native_little = std::endian::native == std::endian::little;
    if constexpr (sizeof(T) > 1 && kLittle != native_little) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    }
  }

  std::vector<std::uint8_t>& out_;
};

using LeWriter = Writer<true>;
using BeWriter = Writer<false>;

}  // namespace navfuse::bytes
