#include "frontends/nmea/writer.hpp"

#include <charconv>
#include <cmath>

#include "core/bytes/checks.hpp"

namespace navfuse::frontends::nmea {
namespace {
constexpr char kHexDigits[] = "0123456789ABCDEF";  // examples print upper case (digest §1.2)
constexpr int kMaxDecimals = 12;
}  // namespace

void SentenceWriter::begin(std::string_view name, char start) {
  size_ = 0;
  overflow_ = false;
  buffer_[size_++] = start;
  append(name);
}

void SentenceWriter::append(std::string_view text) {
  if (size_ + text.size() > buffer_.size()) {
    overflow_ = true;
    return;
  }
  for (char c : text) buffer_[size_++] = c;
}

void SentenceWriter::add(std::string_view text) {
  append(",");
  append(text);
}

void SentenceWriter::append_fixed(double value, int decimals) {
  if (!std::isfinite(value) || decimals < 0 || decimals > kMaxDecimals) {
    overflow_ = true;
    return;
  }
  // Print a value that rounds to zero as "0.000", not "-0.000".
  const double scale = std::pow(10.0, decimals);
  if (std::fabs(value) * scale < 0.5) value = 0.0;
  std::array<char, 64> tmp{};
  const auto [ptr, ec] = std::to_chars(tmp.data(), tmp.data() + tmp.size(), value,
                                       std::chars_format::fixed, decimals);
  if (ec != std::errc{}) {
    overflow_ = true;
    return;
  }
  append(std::string_view(tmp.data(), static_cast<std::size_t>(ptr - tmp.data())));
}

void SentenceWriter::add_fixed(double value, int decimals) {
  append(",");
  append_fixed(value, decimals);
}

void SentenceWriter::append_uint(std::uint64_t value, int min_width) {
  std::array<char, 24> tmp{};
  const auto [ptr, ec] = std::to_chars(tmp.data(), tmp.data() + tmp.size(), value);
  (void)ec;  // 24 characters always hold a 64-bit value
  const auto digits = static_cast<int>(ptr - tmp.data());
  for (int i = digits; i < min_width && i < static_cast<int>(tmp.size()); ++i) append("0");
  append(std::string_view(tmp.data(), static_cast<std::size_t>(digits)));
}

void SentenceWriter::add_uint(std::uint64_t value, int min_width) {
  append(",");
  append_uint(value, min_width);
}

void SentenceWriter::add_int(std::int64_t value) {
  std::array<char, 24> tmp{};
  const auto [ptr, ec] = std::to_chars(tmp.data(), tmp.data() + tmp.size(), value);
  (void)ec;
  add(std::string_view(tmp.data(), static_cast<std::size_t>(ptr - tmp.data())));
}

void SentenceWriter::add_hex(std::uint32_t value, int min_width, char prefix) {
  std::array<char, 16> tmp{};
  const auto [ptr, ec] = std::to_chars(tmp.data(), tmp.data() + tmp.size(), value, 16);
  (void)ec;
  append(",");
  append(std::string_view(&prefix, 1));
  for (auto i = static_cast<int>(ptr - tmp.data()); i < min_width && i < 8; ++i) append("0");
  append(std::string_view(tmp.data(), static_cast<std::size_t>(ptr - tmp.data())));
}

bool SentenceWriter::finish(std::vector<std::uint8_t>& out, std::size_t max_bytes) {
  if (overflow_ || size_ < 2) return false;
  // XOR of everything strictly between the start character and '*' (L164).
  const std::uint8_t x = bytes::nmea_xor(std::string_view(buffer_.data() + 1, size_ - 1));
  const char tail[] = {'*', kHexDigits[x >> 4], kHexDigits[x & 0xF], '\r', '\n'};
  append(std::string_view(tail, sizeof tail));
  if (overflow_ || size_ > max_bytes) return false;
  out.insert(out.end(), buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(size_));
  return true;
}

}  // namespace navfuse::frontends::nmea
