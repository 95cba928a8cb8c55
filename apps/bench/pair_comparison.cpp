#include "apps/bench/pair_comparison.hpp"

namespace navfuse::apps::bench {

nlohmann::ordered_json PairComparison::to_json() const {
  nlohmann::ordered_json j;
  j["estimate"] = spec.estimate;
  j["reference"] = spec.reference;
  j["samples"] = samples();
  j["overlap_s"] = overlap_s();
  const nlohmann::ordered_json all = metrics.all().metrics_json();
  for (const auto& [key, value] : all.items()) {
    if (key != "samples" && key != "span_s") j[key] = value;
  }
  j["consistency"] = metrics.all().consistency_json();
  j["by_phase"] = metrics.by_phase_json();
  j["by_mode"] = metrics.by_mode_json();
  j["unaligned"] = {{"outside", outside}, {"gap", gaps}, {"no_common_quantity", no_common_quantity}};
  return j;
}

PairComparison compare_pair(const PairSpec& spec, const TrackView& sampled, const SolutionLookup& other,
                            const PhaseTimeline& phases) {
  PairComparison out;
  out.spec = spec;
  PhaseTimeline::Cursor phase = phases.cursor();
  TrackView::Reader reader = sampled.reader();
  for (TrackSample s; reader.next(s);) {
    TrackInterpolator::Miss miss = TrackInterpolator::Miss::kNone;
    const std::optional<TrackSample> o = other(s.time_ns, &miss);
    if (!o) {
      ++(miss == TrackInterpolator::Miss::kGap ? out.gaps : out.outside);
      continue;
    }
    const TrackSample& est = spec.sampled_is_estimate ? s : *o;
    const TrackSample& ref = spec.sampled_is_estimate ? *o : s;
    SolutionError e = solution_error(est, ref, spec.reference_is_truth);
    if (!e.any()) {
      ++out.no_common_quantity;
      continue;
    }
    e.time_ns = s.time_ns;
    const std::optional<PhaseLabel> label = phase.at(s.time_ns);
    out.metrics.add(e, label);
    out.errors.push_back({.error = e, .phase = label});
  }
  return out;
}

SolutionLookup interpolating_lookup(TrackInterpolator& track) {
  return [&track](std::int64_t time_ns, TrackInterpolator::Miss* miss) { return track.at(time_ns, miss); };
}

}  // namespace navfuse::apps::bench
