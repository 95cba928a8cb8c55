// A device log made with the project's simulator and a front-end's own encoder, as the bytes a
// device would have streamed, cut into the pieces delivered at each measurement's delivery time,
// and played into a simulated serial device at the pace of those times.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <thread>
#include <optional>
#include <string_view>
#include <vector>

#include "apps/common/frontend_registry.hpp"
#include "apps/sim/scenarios.hpp"
#include "apps/sim/simulator.hpp"
#include "tests/integration/pty_device.hpp"

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

// Plays pieces [first, last) of the log into the device at speed_up times real time.
inline bool play(PtyDevice& device, const SimLog& log, std::size_t first, std::size_t last, double speed_up) {
  const auto wall_start = std::chrono::steady_clock::now();
  const std::int64_t data_start = log.pieces[first].delivery_ns;
  std::size_t begin = first == 0 ? 0 : log.pieces[first - 1].end;
  for (std::size_t i = first; i < last;) {
    // One write per 10 ms of wall time: everything delivered by then.
    const auto due = wall_start + std::chrono::nanoseconds(static_cast<std::int64_t>(
                                      static_cast<double>(log.pieces[i].delivery_ns - data_start) / speed_up));
    std::this_thread::sleep_until(due);
    const auto horizon = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::steady_clock::now() - wall_start + std::chrono::milliseconds(10));
    std::size_t j = i;
    while (j < last && static_cast<double>(log.pieces[j].delivery_ns - data_start) / speed_up <=
                           static_cast<double>(horizon.count())) {
      ++j;
    }
    j = std::max(j, i + 1);
    const std::size_t end = log.pieces[j - 1].end;
    if (!device.write_all(log.bytes.data() + begin, end - begin)) return false;
    begin = end;
    i = j;
  }
  return true;
}

}  // namespace navfuse::test
