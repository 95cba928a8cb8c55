#include "filter/measurement_kinds.hpp"

#include <variant>

#include "filter/control/baro_control.hpp"
#include "filter/control/external_aiding_control.hpp"
#include "filter/control/gnss_control.hpp"
#include "filter/control/magnetometer_control.hpp"
#include "filter/control/odometry_control.hpp"
#include "filter/filter_core.hpp"
#include "filter/input_checks.hpp"

namespace navfuse::filter {

// Kind K is the variant's alternative K (core/measurements: "one kind per variant alternative, in
// the same order"), so the typed overloads are chosen at compile time.
template <MeasurementKind K>
std::optional<RejectReason> check_kind(const Measurement& m) {
  return check_input(*std::get_if<static_cast<std::size_t>(K)>(&m));
}

template <MeasurementKind K>
FuseResult fuse_kind(FilterCore& core, const FilterOptions& o, const Measurement& m, double shift_s) {
  return fuse(core, o, *std::get_if<static_cast<std::size_t>(K)>(&m), shift_s);
}

#define NAVFUSE_CHECKED_KIND(K) \
  template std::optional<RejectReason> check_kind<MeasurementKind::K>(const Measurement&);
#define NAVFUSE_FUSED_KIND(K)   \
  NAVFUSE_CHECKED_KIND(K)       \
  template FuseResult fuse_kind<MeasurementKind::K>(FilterCore&, const FilterOptions&, const Measurement&, double);
NAVFUSE_CHECKED_KIND(kImu)
NAVFUSE_FUSED_KIND(kGnssPosition)
NAVFUSE_FUSED_KIND(kGnssVelocity)
NAVFUSE_FUSED_KIND(kGnssHeading)
NAVFUSE_FUSED_KIND(kWheelSpeed)
NAVFUSE_FUSED_KIND(kVehicleSpeed)
NAVFUSE_FUSED_KIND(kWheelTicks)
NAVFUSE_FUSED_KIND(kExternalPosition)
NAVFUSE_FUSED_KIND(kExternalVelocity)
NAVFUSE_FUSED_KIND(kExternalHeading)
NAVFUSE_FUSED_KIND(kMagnetometer)
NAVFUSE_FUSED_KIND(kPressure)
#undef NAVFUSE_FUSED_KIND
#undef NAVFUSE_CHECKED_KIND

}  // namespace navfuse::filter
