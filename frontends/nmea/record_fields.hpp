// Small helpers that append named values to a FrameRecord (for `navfuse decode`), writing an
// absent (null) field as an empty string so that every record of a sentence type has the same
// columns.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/nmea/fields.hpp"

namespace navfuse::frontends::nmea {

inline void put(frontends::FrameRecord& r, std::string_view name, frontends::FieldValue v) {
  r.fields.emplace_back(std::string(name), std::move(v));
}
inline void put(frontends::FrameRecord& r, std::string_view name, double v) {
  put(r, name, frontends::FieldValue{v});
}
inline void put(frontends::FrameRecord& r, std::string_view name, std::int64_t v) {
  put(r, name, frontends::FieldValue{v});
}
inline void put(frontends::FrameRecord& r, std::string_view name, std::uint64_t v) {
  put(r, name, frontends::FieldValue{v});
}
inline void put(frontends::FrameRecord& r, std::string_view name, std::uint32_t v) {
  put(r, name, frontends::FieldValue{static_cast<std::uint64_t>(v)});
}
inline void put(frontends::FrameRecord& r, std::string_view name, std::int32_t v) {
  put(r, name, frontends::FieldValue{static_cast<std::int64_t>(v)});
}
inline void put(frontends::FrameRecord& r, std::string_view name, std::string_view v) {
  put(r, name, frontends::FieldValue{std::string(v)});
}
inline void put(frontends::FrameRecord& r, std::string_view name, char v) {
  put(r, name, frontends::FieldValue{std::string(1, v)});
}
inline void put_null(frontends::FrameRecord& r, std::string_view name) {
  put(r, name, frontends::FieldValue{std::string()});
}
template <class T>
void put(frontends::FrameRecord& r, std::string_view name, const std::optional<T>& v) {
  if (v) {
    put(r, name, *v);
  } else {
    put_null(r, name);
  }
}
inline void put(frontends::FrameRecord& r, std::string_view name, const Real& v) {
  put(r, name, v.value);
}
inline void put(frontends::FrameRecord& r, std::string_view name, const Count& v) {
  put(r, name, v.value);
}

}  // namespace navfuse::frontends::nmea
