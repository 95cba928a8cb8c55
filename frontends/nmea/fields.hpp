// Splitting a sentence body into comma-separated fields and parsing them without locale or
// allocation (std::from_chars), with the field data types of the Unicore protocol (spec §3
// "Formats", L174-L196; digest §1.3), which are a superset of what NMEA 0183 needs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace navfuse::frontends::nmea {

// Longest field list accepted. The longest documented sentence, h51 GSV/GSA, has 21 fields; a
// 128-byte sentence could hold 127 empty ones, which is corruption, not data.
inline constexpr std::size_t kMaxFields = 40;

// The fields of one sentence body ("NAME,f1,f2,..."): [0] is the name, [1..] the data fields.
class Fields {
 public:
  // Splits `body`; false if it holds more than kMaxFields fields.
  bool split(std::string_view body);
  std::size_t size() const { return count_; }
  // Field i, or an empty view past the end (an absent trailing field reads as a null one).
  std::string_view operator[](std::size_t i) const { return i < count_ && i < kMaxFields ? items_[i] : std::string_view{}; }
  std::string_view name() const { return items_[0]; }
  // Number of data fields (excluding the name).
  std::size_t data_count() const { return count_ == 0 ? 0 : count_ - 1; }

 private:
  std::array<std::string_view, kMaxFields> items_{};
  std::size_t count_ = 0;
};

// Numeric parsers. Each returns nullopt for an empty field (a "null field" of NMEA / an omitted
// optional parameter, spec L156) and for any malformed, out-of-range or non-finite text; callers
// that need the difference check `field.empty()` first. Leading blanks are skipped because the
// spec's own MAPFB examples carry one inside the checksummed text (digest §11 item 15, L828).

// DOUBLE (L192-L196): optional '-', digits, optional '.' and digits. No exponent, inf or nan.
std::optional<double> parse_double(std::string_view field);
// INT (L184-L186): optional '-' and decimal digits, -2^31 .. 2^31-1.
std::optional<std::int32_t> parse_int(std::string_view field);
// UINT (L182-L183): decimal, or 'h'/'H' followed by 1-8 hex digits (e.g. "h51", "H11", "hff").
std::optional<std::uint32_t> parse_uint(std::string_view field);
// UINT64 (L188-L190): decimal, or 'h', 'H', '0x', '0X' followed by 1-16 hex digits.
std::optional<std::uint64_t> parse_uint64(std::string_view field);
// A single-character flag field such as 'A'/'V', 'N'/'S'; nullopt unless exactly one character.
std::optional<char> parse_char(std::string_view field);

// A DOUBLE field together with the number of decimals it was printed with, so that a decoded
// sentence re-encodes to the same bytes (the spec's tables and examples disagree on decimal
// counts, digest §11 item 17: the precision is data, not a constant).
struct Real {
  double value = 0.0;
  int decimals = 0;
};
std::optional<Real> parse_real(std::string_view field);

// An unsigned field with its printed width: h51 sentences zero-pad satellite numbers, elevation,
// azimuth, C/N0 and message numbers (digest §4.4.4), h30 ones do not.
struct Count {
  std::uint32_t value = 0;
  int width = 1;
};
std::optional<Count> parse_count(std::string_view field);

// Case-insensitive ASCII comparison (message names are not case-sensitive, L154).
bool iequals(std::string_view a, std::string_view b);

}  // namespace navfuse::frontends::nmea
