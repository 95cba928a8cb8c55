// The three things done with every binary type: read it from a payload, write it into one, and
// list it as named FrameRecord fields. Each group's layout is written once, as a visit function
// templated on one of these "field I/O" classes (group_*.hpp), so that the decoder, the encoder
// and `navfuse decode` output cannot disagree about an offset or a unit.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/bytes/byte_reader.hpp"
#include "core/bytes/byte_writer.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::vectornav {

using Names3 = std::array<std::string_view, 3>;

// Reads little-endian fields (all VectorNav binary payload values are LE, L699).
class FieldReader {
 public:
  explicit FieldReader(bytes::LeReader& r) : r_(r) {}
  template <typename T>
  void field(std::string_view, T& v) { v = r_.read<T>(); }
  template <typename T, std::size_t N>
  void fields(const std::array<std::string_view, N>&, std::array<T, N>& v) {
    for (auto& x : v) x = r_.read<T>();
  }
  template <typename T>
  void resize(std::vector<T>& v, std::size_t n) { v.resize(n); }
  void begin_element(std::string_view, std::size_t) {}
  void end_element() {}

 private:
  bytes::LeReader& r_;
};

class FieldWriter {
 public:
  explicit FieldWriter(bytes::LeWriter& w) : w_(w) {}
  template <typename T>
  void field(std::string_view, const T& v) { w_.write(v); }
  template <typename T, std::size_t N>
  void fields(const std::array<std::string_view, N>&, const std::array<T, N>& v) {
    for (const auto& x : v) w_.write(x);
  }
  template <typename T>
  void resize(std::vector<T>&, std::size_t) {}
  void begin_element(std::string_view, std::size_t) {}
  void end_element() {}

 private:
  bytes::LeWriter& w_;
};

// Appends "<prefix><name>" = value pairs to a FrameRecord (only when the sink wants frames).
class FieldDescriber {
 public:
  FieldDescriber(FrameRecord& record, std::string_view prefix) : record_(record), prefix_(prefix) {}
  template <typename T>
  void field(std::string_view name, const T& v) {
    std::string key;
    key.reserve(prefix_.size() + element_.size() + name.size());
    key.append(prefix_).append(element_).append(name);
    record_.fields.emplace_back(std::move(key), to_value(v));
  }
  template <typename T, std::size_t N>
  void fields(const std::array<std::string_view, N>& names, const std::array<T, N>& v) {
    for (std::size_t i = 0; i < N; ++i) field(names[i], v[i]);
  }
  template <typename T>
  void resize(std::vector<T>&, std::size_t) {}
  void begin_element(std::string_view what, std::size_t index) {
    element_.assign(what).append(std::to_string(index)).append(".");
  }
  void end_element() { element_.clear(); }
  void set_prefix(std::string_view prefix) { prefix_ = prefix; }

 private:
  template <typename T>
  static FieldValue to_value(const T& v) {
    if constexpr (std::is_floating_point_v<T>) {
      return static_cast<double>(v);
    } else if constexpr (std::is_signed_v<T>) {
      return static_cast<std::int64_t>(v);
    } else {
      return static_cast<std::uint64_t>(v);
    }
  }
  FrameRecord& record_;
  std::string_view prefix_;
  std::string element_;
};

}  // namespace navfuse::frontends::vectornav
