#include "apps/fusion/gnss_outage_plan.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace navfuse::apps {
namespace {

std::int64_t to_ns(double s) { return std::llround(s * 1e9); }

// Index of the window `t_ns` falls in (may be negative before START), and the offset into it.
std::int64_t window_of(const GnssOutagePlan& p, std::int64_t t_ns, std::int64_t first_ns, std::int64_t& into_ns) {
  const std::int64_t period = to_ns(p.period_s);
  const std::int64_t rel = t_ns - first_ns - to_ns(p.start_s);
  std::int64_t k = rel / period;
  if (rel % period != 0 && rel < 0) --k;
  into_ns = rel - k * period;
  return k;
}

}  // namespace

std::optional<GnssOutagePlan> GnssOutagePlan::parse(const std::string& text, std::string& error) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ':')) {
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || end == nullptr || *end != '\0' || !std::isfinite(x)) {
      error = "--gnss-outage: '" + text + "' is not PERIOD_S:DURATION_S[:START_S] (e.g. 30:10)";
      return std::nullopt;
    }
    v.push_back(x);
  }
  if (v.size() < 2 || v.size() > 3) {
    error = "--gnss-outage: '" + text + "' is not PERIOD_S:DURATION_S[:START_S] (e.g. 30:10)";
    return std::nullopt;
  }
  GnssOutagePlan p{v[0], v[1], v.size() == 3 ? v[2] : 0.0};
  if (!(p.duration_s > 0.0 && p.duration_s < p.period_s && p.start_s >= 0.0 && p.period_s <= 1e6)) {
    error = "--gnss-outage: need 0 < DURATION < PERIOD <= 1e6 s and START >= 0 (got '" + text + "')";
    return std::nullopt;
  }
  return p;
}

bool GnssOutagePlan::in_outage(std::int64_t t_ns, std::int64_t first_ns) const {
  std::int64_t into = 0;
  return window_of(*this, t_ns, first_ns, into) >= 0 && into < to_ns(duration_s);
}

std::int64_t GnssOutagePlan::outage_end_ns(std::int64_t t_ns, std::int64_t first_ns) const {
  std::int64_t into = 0;
  const std::int64_t k = window_of(*this, t_ns, first_ns, into);
  return first_ns + to_ns(start_s) + k * to_ns(period_s) + to_ns(duration_s);
}

}  // namespace navfuse::apps
