#include "apps/run/status_reporter.hpp"

#include <algorithm>

namespace navfuse::apps {
namespace {

void add_rejection(navfuse::status_t& s, std::string kind, std::string reason, std::uint64_t count) {
  if (count == 0) return;
  navfuse::rejection_t r;
  r.kind = std::move(kind);
  r.reason = std::move(reason);
  r.count = static_cast<std::int64_t>(count);
  s.rejections.push_back(std::move(r));
}

// One entry of innovations[], for a kind with at least one update tried.
void add_innovation(navfuse::status_t& s, std::string kind, const filter::InnovationStats& stats,
                    std::uint64_t accepted, std::uint64_t rejected) {
  if (stats.count == 0) return;
  navfuse::innovation_t i;
  i.kind = std::move(kind);
  i.count = static_cast<std::int64_t>(stats.count);
  i.accepted = static_cast<std::int64_t>(accepted);
  i.rejected = static_cast<std::int64_t>(rejected);
  i.mean_nis = static_cast<float>(stats.mean_nis());
  i.mean_nis_per_dim = static_cast<float>(stats.mean_nis_per_dim());
  i.fraction_above_gate = static_cast<float>(stats.fraction_above_gate());
  s.innovations.push_back(std::move(i));
}

}  // namespace

navfuse::status_t StatusReporter::make(const StatusInputs& in, std::int64_t now_ns) {
  navfuse::status_t s;
  s.time_gps_ns = in.solution.header.time_ns;
  s.mode = static_cast<std::int8_t>(in.solution.mode);
  s.mode_name = std::string(to_string(in.solution.mode));
  s.status_flags = static_cast<std::int32_t>(in.solution.status_flags);

  if (previous_.size() != in.inputs.size()) previous_.assign(in.inputs.size(), InputCounters{});
  const double dt_s = previous_ns_ > 0 ? static_cast<double>(now_ns - previous_ns_) * 1e-9 : 0.0;
  for (std::size_t i = 0; i < in.inputs.size(); ++i) {
    const InputCounters& c = in.inputs[i].counters;
    navfuse::input_rate_t r;
    r.name = in.inputs[i].name;
    r.bytes_per_s = dt_s > 0 ? static_cast<float>(static_cast<double>(c.bytes - previous_[i].bytes) / dt_s) : 0.0f;
    r.frames_per_s = dt_s > 0 ? static_cast<float>(static_cast<double>(c.frames - previous_[i].frames) / dt_s) : 0.0f;
    r.bad_frames = static_cast<std::int64_t>(c.bad_frames);
    r.reconnects = static_cast<std::int64_t>(c.reconnects);
    s.inputs.push_back(std::move(r));
    previous_[i] = c;
  }
  previous_ns_ = now_ns;
  s.num_inputs = static_cast<std::int16_t>(s.inputs.size());

  for (std::size_t k = 0; k < in.filter.kinds.size(); ++k) {
    const filter::KindStats& ks = in.filter.kinds[k];
    const std::string kind(to_string(static_cast<MeasurementKind>(k)));
    for (std::size_t r = 0; r < ks.rejected.size(); ++r) {
      add_rejection(s, kind, std::string(filter::to_string(static_cast<filter::RejectReason>(r))), ks.rejected[r]);
    }
  }
  for (std::size_t k = 0; k < in.filter.kinds.size(); ++k) {
    const filter::KindStats& ks = in.filter.kinds[k];
    add_innovation(s, std::string(to_string(static_cast<MeasurementKind>(k))), ks.innovation, ks.used,
                   ks.rejected_total());
  }
  // The non-holonomic constraint, as --summary-json's constraints.nhc: its updates tried are
  // either applied or gated.
  const filter::InnovationStats& nhc = in.filter.nhc_innovation;
  const std::uint64_t nhc_applied = std::min(nhc.count, in.filter.nhc_updates);
  add_innovation(s, kNhcInnovationKind, nhc, nhc_applied, nhc.count - nhc_applied);
  s.num_innovations = static_cast<std::int16_t>(s.innovations.size());
  add_rejection(s, "all", "queue_full", in.rejected_queue_full);
  add_rejection(s, "all", "time_base", in.rejected_time_base);
  s.num_rejections = static_cast<std::int16_t>(s.rejections.size());

  s.output_drops = static_cast<std::int64_t>(in.output_drops);
  s.latency_p50_us = static_cast<float>(in.latency.p50_us);
  s.latency_p99_us = static_cast<float>(in.latency.p99_us);
  return s;
}

}  // namespace navfuse::apps
