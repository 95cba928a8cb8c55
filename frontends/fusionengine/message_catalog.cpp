#include "frontends/fusionengine/message_catalog.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "frontends/fusionengine/payload_bound.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

template <std::size_t... I>
constexpr auto make_name_table(std::index_sequence<I...>) {
  return std::array<std::pair<std::uint16_t, std::string_view>, sizeof...(I)>{
      {{to_u16(std::tuple_element_t<I, AllMessages>::kType),
        std::tuple_element_t<I, AllMessages>::kName}...}};
}
constexpr auto kNames = make_name_table(std::make_index_sequence<kCatalogSize>{});

// The catalogue's ids lie in [kFirstType, kFirstType + kTypeSpan); the size bounds are a table
// over that span (16 KiB) so the framer's check is one load per frame, 0 marking an id the
// catalogue does not define.
template <std::size_t... I>
constexpr std::pair<std::uint16_t, std::uint16_t> type_range(std::index_sequence<I...>) {
  const std::array<std::uint16_t, sizeof...(I)> ids{to_u16(std::tuple_element_t<I, AllMessages>::kType)...};
  return {*std::min_element(ids.begin(), ids.end()), *std::max_element(ids.begin(), ids.end())};
}
constexpr auto kTypeRange = type_range(std::make_index_sequence<kCatalogSize>{});
constexpr std::uint16_t kFirstType = kTypeRange.first;
constexpr std::size_t kTypeSpan = std::size_t{kTypeRange.second} - kFirstType + 1;
using SizeBounds = std::array<std::uint32_t, kTypeSpan>;

// Built once, at static initialisation (payload_bound() is not constexpr, see there). A layout
// payload_bound() refuses (0) keeps the frame limit rather than failing the program: the
// payload-bound tests flag it.
template <std::size_t... I>
SizeBounds make_size_bounds(std::index_sequence<I...>) {
  SizeBounds bound{};
  auto set = [&](std::uint16_t type, std::uint64_t layout) {
    const std::uint64_t b = layout == 0 ? kMaxPayloadSize : layout + kMaxVersionGrowth;
    bound[type - kFirstType] = static_cast<std::uint32_t>(std::min<std::uint64_t>(b, kMaxPayloadSize));
  };
  (set(to_u16(std::tuple_element_t<I, AllMessages>::kType), payload_bound<std::tuple_element_t<I, AllMessages>>()),
   ...);
  return bound;
}
const SizeBounds kSizeBounds = make_size_bounds(std::make_index_sequence<kCatalogSize>{});

}  // namespace

std::uint32_t max_payload_size(std::uint16_t message_type) {
  const std::size_t i = static_cast<std::size_t>(message_type) - kFirstType;  // wraps below the span
  const std::uint32_t b = i < kTypeSpan ? kSizeBounds[i] : 0;
  return b == 0 ? kMaxUnknownPayloadSize : b;
}

std::optional<std::string_view> message_name(std::uint16_t message_type) {
  for (const auto& [type, name] : kNames) {
    if (type == message_type) return name;
  }
  return std::nullopt;
}

}  // namespace navfuse::frontends::fusionengine
