// The largest payload a message layout can express, derived from the layout itself.
//
// PayloadBound walks a message's visit() (the one description of its wire layout that decode,
// encode and the field dump share) with every integer field set to the largest value its type
// holds, so each count or length field reaches the entries / text / blob that follow it at its
// largest: the fixed part plus, per count field, its maximum times the entry's own bound (entries
// are walked the same way, so nested counts multiply through). A tail that is "the rest of the
// payload" (InputDataWrapper, STA5635IQData) has no count field; a u32 length (SetConfig, ...)
// can express more than a frame may carry. Both need the message's own kMaxVariableSize, the
// documented bound on the bytes after its fixed part; payload_bound() refuses a layout that
// needs one and has none (returns 0, which the bound tests flag).
//
// Used by message_catalog.cpp for the framer's per-type size check (issue 15.11). Not
// constexpr: clang 14 with libstdc++ 12 cannot construct a std::string in a constant expression,
// and VersionInfo / EventNotification hold one.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine {

class PayloadBound {
 public:
  template <typename T>
  void field(std::string_view, T& value) {
    bytes_ += sizeof(T);
    if constexpr (std::is_integral_v<T>) value = std::numeric_limits<T>::max();
  }
  template <typename T, std::size_t N>
  void array(std::string_view, std::array<T, N>&) {
    bytes_ += sizeof(T) * N;
  }
  void timestamp(std::string_view, Timestamp&) { bytes_ += 8; }
  void reserved(std::size_t n) { bytes_ += n; }
  void text(std::string_view, std::string&, std::size_t length) { variable(length); }
  void blob(std::string_view, std::vector<std::uint8_t>&, std::size_t length) { variable(length); }
  void config_value(std::string_view, std::uint16_t, std::vector<std::uint8_t>&, std::size_t length) {
    variable(length);
  }
  void rest(std::string_view, std::vector<std::uint8_t>&) { open_tail_ = true; }
  template <class E>
  void list(std::string_view, std::vector<E>&, std::size_t count) {
    E entry;
    PayloadBound inner;
    entry.visit(inner);
    open_tail_ = open_tail_ || inner.open_tail_;
    variable(count * inner.bytes_);
  }

  std::uint64_t fixed_bytes() const { return bytes_ - variable_bytes_; }
  std::uint64_t variable_bytes() const { return variable_bytes_; }
  bool open_tail() const { return open_tail_; }

 private:
  void variable(std::uint64_t n) {
    bytes_ += n;
    variable_bytes_ += n;
  }

  std::uint64_t bytes_ = 0;
  std::uint64_t variable_bytes_ = 0;
  bool open_tail_ = false;
};

// Largest payload of message type M as its layout defines it (before any growth a newer
// message version may add): fixed part + what its count fields can express, or + M's
// kMaxVariableSize when the layout is open (a rest-of-payload tail, or counts that could exceed
// kMaxPayloadSize). 0 for an open layout without kMaxVariableSize, and for a kMaxVariableSize
// on a layout whose counts already bound it (it would silently override them).
template <class M>
std::uint64_t payload_bound() {
  M msg;
  PayloadBound b;
  msg.visit(b);
  std::uint64_t variable = b.variable_bytes();
  // VersionInfo pads its strings to a multiple of 4 (spec L2611); the writer appends it.
  if constexpr (requires { msg.padding(); }) variable += msg.padding();
  const bool open = b.open_tail() || b.fixed_bytes() + variable > kMaxPayloadSize;
  constexpr bool declared = requires { M::kMaxVariableSize; };
  if (open != declared) return 0;  // an open layout without a bound, or a bound nothing needs
  if constexpr (declared) variable = M::kMaxVariableSize;
  return b.fixed_bytes() + variable;
}

}  // namespace navfuse::frontends::fusionengine
