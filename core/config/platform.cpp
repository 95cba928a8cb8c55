// Platform names for the `platform:` key. Which constraints each platform allows is decided in
// filter/filter_options.cpp (options_from_config); here only the spelling lives.
#include "core/config/config.hpp"
#include "core/config/name_table.hpp"

namespace navfuse::config {
namespace {

constexpr EnumName<Platform> kNames[] = {
    {Platform::kGeneric, "generic"},
    {Platform::kLand, "land"},
    {Platform::kPedestrian, "pedestrian"},
    {Platform::kAirborne, "airborne"},
    {Platform::kMarine, "marine"},
};

}  // namespace

std::string_view to_string(Platform p) { return name_in<Platform>(kNames, p, "generic"); }

std::optional<Platform> platform_from_string(std::string_view name) {
  return value_in<Platform>(kNames, name);
}

}  // namespace navfuse::config
