// Field visitor that fills a message struct from its payload bytes.
//
// Every message struct describes its wire layout once, in a `visit(V&)` member template; this
// reader, PayloadWriter and RecordBuilder walk that same description, so decode, encode and the
// `navfuse decode` field dump can never disagree about a layout.
//
// Reads past the payload never touch memory (LeReader is bounds-checked) and turn ok() false.
// Variable-length parts are bounded by the bytes actually present before anything is resized,
// so an absurd count or length costs nothing.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/bytes/byte_reader.hpp"
#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

class PayloadReader {
 public:
  explicit PayloadReader(std::span<const std::uint8_t> payload) : r_(payload) {}

  template <typename T>
  void field(std::string_view, T& value) {
    value = r_.read<T>();
  }
  template <typename T, std::size_t N>
  void array(std::string_view, std::array<T, N>& values) {
    for (auto& v : values) v = r_.read<T>();
  }
  void timestamp(std::string_view, Timestamp& t) {
    t.seconds = r_.u32();
    t.fraction_ns = r_.u32();
  }
  void reserved(std::size_t n) { r_.skip(n); }

  // `length` bytes of text (not null-terminated, spec §2.1 L171).
  void text(std::string_view, std::string& s, std::size_t length) {
    auto bytes = r_.take(length);
    s.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
  void blob(std::string_view, std::vector<std::uint8_t>& b, std::size_t length) {
    auto bytes = r_.take(length);
    b.assign(bytes.begin(), bytes.end());
  }
  // Everything left in the payload (variable tails whose size is payload_size - fixed part).
  void rest(std::string_view, std::vector<std::uint8_t>& b) { blob({}, b, r_.remaining()); }
  // A config value: the bytes are kept raw and interpreted per ConfigType by the user.
  void config_value(std::string_view name, std::uint16_t, std::vector<std::uint8_t>& b,
                    std::size_t length) {
    blob(name, b, length);
  }

  // `count` fixed-size entries (E::kSize bytes each, E::visit describes one).
  template <class E>
  void list(std::string_view, std::vector<E>& entries, std::size_t count) {
    if (count > r_.remaining() / E::kSize) {
      r_.skip(r_.remaining() + 1);  // marks the read failed without touching the entries
      entries.clear();
      return;
    }
    entries.resize(count);
    for (auto& e : entries) e.visit(*this);
  }

  bool ok() const { return r_.ok(); }
  std::size_t position() const { return r_.position(); }

 private:
  bytes::LeReader r_;
};

// Decodes `payload` into `msg` (any catalogue struct). False when the payload is shorter than
// the layout needs; longer payloads (newer message versions) decode their known prefix, as
// spec §2.3 L189 allows ("safe to interpret a newer version using an older message definition").
// The header's message version is never a reason to reject: the spec's versions differ from the
// public client's for several messages (digest §13 A15); message_versions.hpp handles the few
// older layouts that matter.
template <class M>
bool decode_payload(std::span<const std::uint8_t> payload, M& msg) {
  PayloadReader r(payload);
  msg.visit(r);
  return r.ok();
}

}  // namespace navfuse::frontends::fusionengine
