// Field visitor that lists a decoded message's fields as a FrameRecord (for `navfuse decode`
// CSV/JSONL output). Names come from the message's visit(); units are part of the names.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

class RecordBuilder {
 public:
  explicit RecordBuilder(frontends::FrameRecord& record) : rec_(record) {}

  template <typename T>
  void field(std::string_view name, const T& value) {
    if constexpr (std::is_floating_point_v<T>) {
      add(name, static_cast<double>(value));
    } else if constexpr (std::is_signed_v<T>) {
      add(name, static_cast<std::int64_t>(value));
    } else {
      add(name, static_cast<std::uint64_t>(value));
    }
  }
  template <typename T, std::size_t N>
  void array(std::string_view name, const std::array<T, N>& values) {
    for (std::size_t i = 0; i < N; ++i) {
      std::string indexed(name);
      indexed += '[';
      indexed += std::to_string(i);
      indexed += ']';
      field(indexed, values[i]);
    }
  }
  // "<name>_ns" as integer nanoseconds, or the string "invalid" (spec §2.6.1 L256-257).
  void timestamp(std::string_view name, const Timestamp& t);
  void reserved(std::size_t) {}
  void text(std::string_view name, const std::string& s, std::size_t) { add(name, s); }
  void blob(std::string_view name, const std::vector<std::uint8_t>& b, std::size_t);
  void rest(std::string_view name, const std::vector<std::uint8_t>& b) { blob(name, b, b.size()); }
  // Decodes the value of the config types navfuse knows (lever arms, orientation, vehicle,
  // wheel config, ...) into named fields; other types are listed as hex.
  void config_value(std::string_view name, std::uint16_t config_type,
                    const std::vector<std::uint8_t>& b, std::size_t length);
  template <class E>
  void list(std::string_view name, std::vector<E>& entries, std::size_t count) {
    const std::string saved = prefix_;
    for (std::size_t i = 0; i < count && i < entries.size(); ++i) {
      prefix_ = saved + std::string(name) + std::to_string(i) + "_";
      entries[i].visit(*this);
    }
    prefix_ = saved;
  }

 private:
  void add(std::string_view name, frontends::FieldValue value) {
    rec_.fields.emplace_back(prefix_ + std::string(name), std::move(value));
  }

  frontends::FrameRecord& rec_;
  std::string prefix_;
};

}  // namespace navfuse::frontends::fusionengine
