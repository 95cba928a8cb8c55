// A field visitor that fills any catalogue message with random values (finite floats, valid
// timestamps, short strings/blobs/lists), for the randomised round trips.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/wire.hpp"

namespace navfuse::frontends::fusionengine::test {

class RandomFill {
 public:
  explicit RandomFill(std::mt19937_64& rng) : rng_(rng) {}

  template <typename T>
  void field(std::string_view, T& value) {
    if constexpr (std::is_floating_point_v<T>) {
      value = static_cast<T>(std::uniform_real_distribution<double>(-1e4, 1e4)(rng_));
    } else {
      value = static_cast<T>(rng_());
    }
  }
  template <typename T, std::size_t N>
  void array(std::string_view name, std::array<T, N>& values) {
    for (auto& v : values) field(name, v);
  }
  void timestamp(std::string_view, Timestamp& t) {
    t.seconds = static_cast<std::uint32_t>(rng_() % 0xFFFFFFFEu);
    t.fraction_ns = static_cast<std::uint32_t>(rng_() % 1'000'000'000u);
  }
  void reserved(std::size_t) {}
  void text(std::string_view, std::string& s, std::size_t) {
    s.resize(rng_() % 17);
    for (auto& c : s) c = static_cast<char>('a' + rng_() % 26);
  }
  void blob(std::string_view, std::vector<std::uint8_t>& b, std::size_t) {
    b.resize(rng_() % 23);
    for (auto& x : b) x = static_cast<std::uint8_t>(rng_());
  }
  void rest(std::string_view name, std::vector<std::uint8_t>& b) { blob(name, b, 0); }
  // Values of the size the config type defines (random bytes otherwise).
  void config_value(std::string_view name, std::uint16_t config_type, std::vector<std::uint8_t>& b, std::size_t) {
    blob(name, b, 0);
    if (const std::size_t n = config_value_size(config_type); n > 0) b.resize(n);
  }
  template <class E>
  void list(std::string_view, std::vector<E>& entries, std::size_t) {
    const std::size_t n = rng_() % 6;
    entries.clear();
    for (std::size_t i = 0; i < n; ++i) {
      E e;
      e.visit(*this);
      entries.push_back(e);
    }
  }

 private:
  std::mt19937_64& rng_;
};

}  // namespace navfuse::frontends::fusionengine::test
