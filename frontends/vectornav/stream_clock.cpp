#include "frontends/vectornav/stream_clock.hpp"

namespace navfuse::frontends::vectornav {

Stamp StreamClock::resolve(std::optional<std::int64_t> gps_ns, std::optional<std::int64_t> startup_ns) {
  if (gps_ns) {
    if (startup_ns) clock_.add_pair(*startup_ns, *gps_ns);
    latest_ = {*gps_ns, TimeSource::kGps};
  } else if (startup_ns) {
    if (const auto mapped = clock_.to_gps(*startup_ns)) {
      latest_ = {*mapped, TimeSource::kGps};
    } else {
      latest_ = {*startup_ns, TimeSource::kDeviceMonotonic};
    }
  }
  return latest_;
}

}  // namespace navfuse::frontends::vectornav
