// Bounds-checked readers of little- and big-endian values from a byte span.
//
// A read past the end never touches memory outside the span: it returns 0 and sets the sticky
// `ok()` flag false, so a decoder can read a whole structure and check once at the end.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>

namespace navfuse::bytes {

enum class Endian { kLittle, kBig };

template <Endian E>
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> data) : data_(data) {}

  template <typename T>
  T read() {
    static_assert(std::is_arithmetic_v<T>, "read() takes integers and floating point");
    if (sizeof(T) > data_.size() - pos_) {
      ok_ = false;
      pos_ = data_.size();
      return T{};
    }
    T value;
    std::memcpy(&value, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if constexpr (sizeof(T) > 1) {
      constexpr bool native_little = std::endian::native == std::endian::little;
      if ((E == Endian::kLittle) != native_little) value = byteswap(value);
    }
    return value;
  }

  std::uint8_t u8() { return read<std::uint8_t>(); }
  std::int8_t i8() { return read<std::int8_t>(); }
  std::uint16_t u16() { return read<std::uint16_t>(); }
  std::int16_t i16() { return read<std::int16_t>(); }
  std::uint32_t u32() { return read<std::uint32_t>(); }
  std::int32_t i32() { return read<std::int32_t>(); }
  std::uint64_t u64() { return read<std::uint64_t>(); }
  std::int64_t i64() { return read<std::int64_t>(); }
  float f32() { return read<float>(); }
  double f64() { return read<double>(); }

  // Skips n bytes (fails like a read when fewer remain).
  void skip(std::size_t n) {
    if (n > data_.size() - pos_) {
      ok_ = false;
      pos_ = data_.size();
    } else {
      pos_ += n;
    }
  }
  // The next n bytes as a span (empty and !ok() when fewer remain).
  std::span<const std::uint8_t> take(std::size_t n) {
    if (n > data_.size() - pos_) {
      ok_ = false;
      pos_ = data_.size();
      return {};
    }
    auto s = data_.subspan(pos_, n);
    pos_ += n;
    return s;
  }

  bool ok() const { return ok_; }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  template <typename T>
  static T byteswap(T value) {
    using U = std::make_unsigned_t<std::conditional_t<std::is_floating_point_v<T>,
        std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>, T>>;
    U u;
    std::memcpy(&u, &value, sizeof(T));
    if constexpr (sizeof(T) == 2) u = static_cast<U>(__builtin_bswap16(u));
    if constexpr (sizeof(T) == 4) u = static_cast<U>(__builtin_bswap32(u));
    if constexpr (sizeof(T) == 8) u = static_cast<U>(__builtin_bswap64(u));
    std::memcpy(&value, &u, sizeof(T));
    return value;
  }

  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

using LeReader = Reader<Endian::kLittle>;
using BeReader = Reader<Endian::kBig>;

}  // namespace navfuse::bytes
