#include "apps/fusion/measurement_counts.hpp"

namespace navfuse::apps {
namespace {

InnovationSummary innovation_summary(const filter::InnovationStats& in) {
  return {in.count, in.mean_nis(), in.mean_nis_per_dim(), in.fraction_above_gate()};
}

}  // namespace

void MeasurementCounts::count_gated(MeasurementKind kind, std::string_view reason) {
  auto& reasons = gated[static_cast<std::size_t>(kind)];
  auto it = reasons.find(reason);
  if (it == reasons.end()) it = reasons.emplace(std::string(reason), 0).first;
  ++it->second;
}

void fill_measurement_counts(const filter::Engine& engine, const MeasurementCounts& counts, Summary& summary) {
  const filter::FilterStats& stats = engine.stats();
  for (std::size_t k = 0; k < summary.kinds.size(); ++k) {
    KindSummary& ks = summary.kinds[k];
    const filter::KindStats& fs = stats.kinds[k];
    ks.decoded = counts.decoded[k];
    ks.used = fs.used;
    ks.pending = engine.pending(static_cast<MeasurementKind>(k));
    for (std::size_t r = 0; r < fs.rejected.size(); ++r) {
      if (fs.rejected[r] > 0) ks.rejected[std::string(filter::to_string(static_cast<filter::RejectReason>(r)))] += fs.rejected[r];
    }
    // A kind the filter does not fuse (device solutions, magnetometer...): "ignored".
    if (fs.ignored > 0) ks.rejected["ignored"] += fs.ignored;
    for (const auto& [reason, n] : counts.gated[k]) ks.rejected[reason] += n;
    if (fs.innovation.count > 0) {
      ks.innovation = innovation_summary(fs.innovation);
    }
  }
  summary.nhc_updates = stats.nhc_updates;
  if (stats.nhc_innovation.count > 0) {
    summary.nhc = innovation_summary(stats.nhc_innovation);
  }
  summary.adaptation =
      AdaptationSummary{stats.covariance_inflations,          stats.process_noise_scale,
                        stats.max_process_noise_scale,        stats.gnss_recoveries,
                        stats.max_gnss_position_noise_scale, stats.max_gnss_velocity_noise_scale,
                        stats.output_jumps_blended};
}

}  // namespace navfuse::apps
