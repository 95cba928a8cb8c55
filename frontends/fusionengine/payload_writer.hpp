// Field visitor that appends a message struct's payload bytes (the inverse of PayloadReader).
// Reserved bytes are written as 0, as every spec example does (digest §11).
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/bytes/byte_writer.hpp"
#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

// `Sink`: bytes::LeWriter (appends to a vector) or bytes::LeSpanWriter (fills bytes that already
// exist, for a frame whose payload size is known beforehand: fusionengine/writer.hpp).
template <class Sink>
class BasicPayloadWriter {
 public:
  template <class Out>
    requires std::constructible_from<Sink, Out&&>
  explicit BasicPayloadWriter(Out&& out) : w_(std::forward<Out>(out)) {}

  const Sink& sink() const { return w_; }

  template <typename T>
  void field(std::string_view, const T& value) {
    w_.write(value);
  }
  template <typename T, std::size_t N>
  void array(std::string_view, const std::array<T, N>& values) {
    for (const auto& v : values) w_.write(v);
  }
  void timestamp(std::string_view, const Timestamp& t) {
    w_.u32(t.seconds);
    w_.u32(t.fraction_ns);
  }
  void reserved(std::size_t n) { w_.zeros(n); }

  // The length fields were set from the contents by the message's sync_lengths() before the
  // visit; a length shorter than the contents writes only that many bytes, a longer one pads.
  void text(std::string_view, const std::string& s, std::size_t length) {
    const std::size_t n = s.size() < length ? s.size() : length;
    w_.bytes({reinterpret_cast<const std::uint8_t*>(s.data()), n});
    w_.zeros(length - n);
  }
  void blob(std::string_view, const std::vector<std::uint8_t>& b, std::size_t length) {
    const std::size_t n = b.size() < length ? b.size() : length;
    w_.bytes({b.data(), n});
    w_.zeros(length - n);
  }
  void rest(std::string_view, const std::vector<std::uint8_t>& b) { w_.bytes(b); }
  void config_value(std::string_view name, std::uint16_t, const std::vector<std::uint8_t>& b,
                    std::size_t length) {
    blob(name, b, length);
  }
  template <class E>
  void list(std::string_view, std::vector<E>& entries, std::size_t count) {
    for (std::size_t i = 0; i < count && i < entries.size(); ++i) entries[i].visit(*this);
  }

 private:
  Sink w_;
};

using PayloadWriter = BasicPayloadWriter<bytes::LeWriter>;
using PayloadSpanWriter = BasicPayloadWriter<bytes::LeSpanWriter>;

}  // namespace navfuse::frontends::fusionengine
