// Tables of the names a config key accepts for an enumeration (`device:`, `platform:`): both
// directions of the lookup, case-insensitive on the way in, written once.
#pragma once

#include <algorithm>
#include <cctype>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace navfuse::config {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

// The table's name for `value`; `fallback` for a value outside the enumeration.
template <class E>
std::string_view name_in(std::span<const EnumName<E>> table, E value, std::string_view fallback) {
  for (const auto& row : table) {
    if (row.value == value) return row.name;
  }
  return fallback;
}

template <class E>
std::optional<E> value_in(std::span<const EnumName<E>> table, std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  for (const auto& row : table) {
    if (row.name == lower) return row.value;
  }
  return std::nullopt;
}

}  // namespace navfuse::config
