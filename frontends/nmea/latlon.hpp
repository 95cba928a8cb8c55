// NMEA latitude / longitude fields: "ddmm.mmmm" + N/S and "dddmm.mmmm" + E/W (Unicore spec GGA
// table L875-L878, h30 L1096-L1101), kept with their printed minute decimals so that a decoded
// sentence re-encodes byte for byte (the decimals differ between tables and examples, digest
// §11 item 17).
#pragma once

#include <optional>
#include <string_view>

#include "frontends/nmea/writer.hpp"

namespace navfuse::frontends::nmea {

struct LatLonField {
  double deg = 0.0;        // signed degrees: + north / + east
  int minute_decimals = 0; // decimals printed after the minutes' point
};

// `value` "ddmm.mmmm", `hemisphere` "N"/"S" (latitude) or "dddmm.mmmm", "E"/"W" (longitude).
// nullopt for empty, malformed, minutes >= 60 or out-of-range values.
std::optional<LatLonField> parse_latitude(std::string_view value, std::string_view hemisphere);
std::optional<LatLonField> parse_longitude(std::string_view value, std::string_view hemisphere);

// Appends the two fields (value and hemisphere letter).
void add_latitude(SentenceWriter& w, const LatLonField& lat);
void add_longitude(SentenceWriter& w, const LatLonField& lon);

}  // namespace navfuse::frontends::nmea
