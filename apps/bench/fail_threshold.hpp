// `navfuse bench --fail-above METRIC=VALUE`: regression gates for users' CI. METRIC is a dotted
// path into metrics.json (navfuse_vs_truth.horizontal_m.rms, device_vs_truth.heading_deg.p95,
// navfuse_vs_truth.by_phase.gnss_outage.horizontal_m.max, ...). A bound is exceeded when the
// metric is greater than VALUE. A path that names nothing is an error, not a pass: a gate that
// silently passes because a pair vanished (no device solution, no truth) would gate nothing.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace navfuse::apps::bench {

struct FailThreshold {
  std::string metric;  // dotted path
  double bound = 0.0;
};

// Parses "path=value"; throws CommandError naming the argument when malformed.
FailThreshold parse_fail_threshold(const std::string& argument);

// One line per exceeded bound ("navfuse_vs_truth.horizontal_m.rms = 0.731 > 0.5"); empty when
// all hold. Throws CommandError when a path names no number in `metrics`.
std::vector<std::string> exceeded_thresholds(const std::vector<FailThreshold>& thresholds,
                                             const nlohmann::ordered_json& metrics);

}  // namespace navfuse::apps::bench
