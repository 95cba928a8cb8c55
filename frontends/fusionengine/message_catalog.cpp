#include "frontends/fusionengine/message_catalog.hpp"

#include <array>
#include <type_traits>
#include <utility>

namespace navfuse::frontends::fusionengine {
namespace {

template <std::size_t... I>
constexpr auto make_name_table(std::index_sequence<I...>) {
  return std::array<std::pair<std::uint16_t, std::string_view>, sizeof...(I)>{
      {{to_u16(std::tuple_element_t<I, AllMessages>::kType),
        std::tuple_element_t<I, AllMessages>::kName}...}};
}
constexpr auto kNames = make_name_table(std::make_index_sequence<kCatalogSize>{});

// A layout is fixed unless it carries counted entries / lengths (sync_lengths()) or a tail of
// "the rest of the payload" (InputDataWrapper, STA5635IQData).
template <class M>
constexpr bool kFixedLayout = !requires(M m) { m.sync_lengths(); } &&
                              !std::is_same_v<M, InputDataWrapperMessage> &&
                              !std::is_same_v<M, Sta5635IqDataMessage>;

// Bound per type id: the fixed layout's size plus kMaxVersionGrowth, kVariableLayout for a
// variable-length type of the catalogue, 0 for a type the catalogue does not know; a table so
// the framer's check is one load per frame.
using SizeBounds = std::array<std::uint16_t, 65536>;
constexpr std::uint16_t kVariableLayout = 0xFFFF;
template <std::size_t... I>
constexpr SizeBounds make_size_bounds(std::index_sequence<I...>) {
  SizeBounds bound{};
  ((bound[to_u16(std::tuple_element_t<I, AllMessages>::kType)] =
        kFixedLayout<std::tuple_element_t<I, AllMessages>>
            ? static_cast<std::uint16_t>(std::tuple_element_t<I, AllMessages>::kSize + kMaxVersionGrowth)
            : kVariableLayout),
   ...);
  return bound;
}
constexpr SizeBounds kSizeBounds = make_size_bounds(std::make_index_sequence<kCatalogSize>{});
static_assert(kSizeBounds[to_u16(PoseMessage::kType)] < kVariableLayout, "fixed bounds stay below the marker");

}  // namespace

std::uint32_t max_payload_size(std::uint16_t message_type) {
  const std::uint16_t b = kSizeBounds[message_type];
  if (b == 0) return kMaxUnknownPayloadSize;
  return b == kVariableLayout ? kMaxPayloadSize : b;
}

std::optional<std::string_view> message_name(std::uint16_t message_type) {
  for (const auto& [type, name] : kNames) {
    if (type == message_type) return name;
  }
  return std::nullopt;
}

}  // namespace navfuse::frontends::fusionengine
