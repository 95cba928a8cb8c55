#include "frontends/fusionengine/message_catalog.hpp"

#include <array>
#include <utility>

namespace navfuse::fe {
namespace {

template <std::size_t... I>
constexpr auto make_name_table(std::index_sequence<I...>) {
  return std::array<std::pair<std::uint16_t, std::string_view>, sizeof...(I)>{
      {{to_u16(std::tuple_element_t<I, AllMessages>::kType),
        std::tuple_element_t<I, AllMessages>::kName}...}};
}
constexpr auto kNames = make_name_table(std::make_index_sequence<kCatalogSize>{});

}  // namespace

std::optional<std::string_view> message_name(std::uint16_t message_type) {
  for (const auto& [type, name] : kNames) {
    if (type == message_type) return name;
  }
  return std::nullopt;
}

}  // namespace navfuse::fe
