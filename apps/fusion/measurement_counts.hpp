// Per-kind measurement counts an app keeps beside the filter's own: how many were decoded, and
// how many its time-base gate (apps/fusion/time_base_gate.hpp) kept from the filter, by reason.
// fill_measurement_counts() merges them with the filter's used / rejected-by-reason into the run
// Summary, the same way for `navfuse replay`, `bench` and `run`.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "apps/common/summary.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/engine.hpp"

namespace navfuse::apps {

struct MeasurementCounts {
  static constexpr std::size_t kKinds = static_cast<std::size_t>(MeasurementKind::kCount);
  std::array<std::uint64_t, kKinds> decoded{};
  std::array<std::map<std::string, std::uint64_t, std::less<>>, kKinds> gated;

  // Allocates only the first time a kind meets a reason.
  void count_gated(MeasurementKind kind, std::string_view reason);
};

// decoded, used, rejected by reason (the filter's reasons, "ignored" for kinds it does not fuse,
// and the gate's reasons) and pending at the end (held by the filter for the IMU to reach them).
void fill_measurement_counts(const filter::Engine& engine, const MeasurementCounts& counts, Summary& summary);

}  // namespace navfuse::apps
