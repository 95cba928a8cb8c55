// Required-field readers shared by the UM220 message files.
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {

bool read(std::string_view field, Real& v) {
  const auto r = nmea::parse_real(field);
  if (r) v = *r;
  return r.has_value();
}

bool read(std::string_view field, std::uint32_t& v) {
  const auto r = nmea::parse_uint(field);
  if (r) v = *r;
  return r.has_value();
}

bool read(std::string_view field, std::int32_t& v) {
  const auto r = nmea::parse_int(field);
  if (r) v = *r;
  return r.has_value();
}

}  // namespace navfuse::frontends::unicore
