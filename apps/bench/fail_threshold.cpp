#include "apps/bench/fail_threshold.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "apps/common/command_error.hpp"

namespace navfuse::apps::bench {

FailThreshold parse_fail_threshold(const std::string& argument) {
  const auto eq = argument.rfind('=');
  const auto bad = [&](const std::string& why) {
    return CommandError("--fail-above '" + argument + "': " + why + " (expected METRIC=VALUE, e.g. "
                        "navfuse_vs_truth.horizontal_m.rms=0.5)");
  };
  if (eq == std::string::npos || eq == 0) throw bad("no METRIC=VALUE");
  FailThreshold t;
  t.metric = argument.substr(0, eq);
  const std::string value = argument.substr(eq + 1);
  const auto r = std::from_chars(value.data(), value.data() + value.size(), t.bound);
  if (value.empty() || r.ec != std::errc() || r.ptr != value.data() + value.size() || !std::isfinite(t.bound)) {
    throw bad("VALUE is not a number");
  }
  return t;
}

std::vector<std::string> exceeded_thresholds(const std::vector<FailThreshold>& thresholds,
                                             const nlohmann::ordered_json& metrics) {
  std::vector<std::string> out;
  for (const FailThreshold& t : thresholds) {
    const nlohmann::ordered_json* node = &metrics;
    std::string_view rest = t.metric;
    while (!rest.empty()) {
      const auto dot = rest.find('.');
      const std::string key(rest.substr(0, dot));
      if (!node->is_object() || !node->contains(key)) {
        std::string pairs;
        for (const auto& [k, v] : metrics.items()) {
          if (k.find("_vs_") != std::string::npos) pairs += (pairs.empty() ? "" : ", ") + k;
        }
        throw CommandError("--fail-above: metrics.json has no '" + t.metric + "' (compared pairs: " +
                           (pairs.empty() ? "none" : pairs) + ")");
      }
      node = &(*node)[key];
      rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot + 1);
    }
    if (!node->is_number()) throw CommandError("--fail-above: '" + t.metric + "' is not a number in metrics.json");
    const double value = node->get<double>();
    if (value > t.bound) {
      char line[256];
      std::snprintf(line, sizeof line, "%s = %.6g > %.6g", t.metric.c_str(), value, t.bound);
      out.emplace_back(line);
    }
  }
  return out;
}

}  // namespace navfuse::apps::bench
