#include "apps/common/gps_week_inference.hpp"

#include <cmath>

#include "apps/common/frontend_registry.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::apps {
namespace {

// Keeps the time of the first measurement, on the GPS base or (for the week-less input) any.
struct FirstTimeSink final : frontends::DecodeSink {
  bool gps_only = true;
  std::optional<std::int64_t> time_ns;
  void on_measurement(const Measurement& m) override {
    const MeasurementHeader& h = header_of(m);
    if (!time_ns && (!gps_only || h.time_source == TimeSource::kGps)) time_ns = h.time_ns;
  }
};

std::optional<std::int64_t> first_time_ns(const InputSpec& spec, bool gps_only) {
  FirstTimeSink sink;
  sink.gps_only = gps_only;
  auto decoder = spec.frontend->make_decoder();
  decoder->feed(spec.head, sink);
  return sink.time_ns;
}

}  // namespace

std::int32_t nearest_week(std::int64_t tow_ns, std::int64_t reference_ns) {
  return static_cast<std::int32_t>(
      std::llround(static_cast<double>(reference_ns - tow_ns) / static_cast<double>(time::kNsPerWeek)));
}

std::optional<std::int32_t> infer_gps_week(const InputSpec& spec, const std::vector<InputSpec>& all) {
  const std::optional<std::int64_t> tow_ns = first_time_ns(spec, /*gps_only=*/false);
  if (!tow_ns) return std::nullopt;
  for (const InputSpec& other : all) {
    if (other.frontend->make_decoder_in_week != nullptr) continue;
    if (const auto reference_ns = first_time_ns(other, /*gps_only=*/true)) return nearest_week(*tow_ns, *reference_ns);
  }
  return std::nullopt;
}

}  // namespace navfuse::apps
