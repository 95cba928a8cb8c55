// A device log made with the project's simulator and a front-end's own encoder, as the bytes a
// device would have streamed, cut into the pieces delivered at each measurement's delivery time.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "apps/common/frontend_registry.hpp"
#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"

namespace navfuse::test {

struct SimLog {
  struct Piece {
    std::size_t end = 0;            // bytes[previous end, end) were delivered at delivery_ns
    std::int64_t delivery_ns = 0;   // GPS time
  };
  std::vector<std::uint8_t> bytes;
  std::vector<Piece> pieces;
  std::int64_t start_ns = 0;
};

// The first `seconds` of scenario `name`, encoded as `format` ("vn", "mip", ...); with `only`,
// only measurements of that kind.
inline SimLog make_sim_log(std::string_view name, std::string_view format, double seconds,
                           std::optional<MeasurementKind> only = std::nullopt) {
  sim::Simulator simulator(sim::make_scenario(name));
  auto encoder = apps::find_frontend(format)->make_encoder();
  SimLog log;
  log.start_ns = simulator.start_time_ns();
  const std::int64_t end_ns = log.start_ns + static_cast<std::int64_t>(seconds * 1e9);
  Measurement m;
  while (simulator.next(m) && simulator.delivery_time_ns() <= end_ns) {
    if (only && kind_of(m) != *only) continue;
    if (encoder->encode(m, log.bytes)) log.pieces.push_back({log.bytes.size(), simulator.delivery_time_ns()});
  }
  return log;
}

}  // namespace navfuse::test
