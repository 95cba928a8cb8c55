#include "filter/control/baro_control.hpp"

#include <cmath>

#include "filter/measurements/baro_height.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& c, const FilterOptions& o, const Pressure& m, double shift_s) {
  if ((m.header.valid & Pressure::kValidPressure) == 0) return FuseResult::reject(RejectReason::kInvalid);
  // Height is only worth holding once the filter has one of its own to anchor the pressure to.
  if (!c.mode.levelled || !c.mode.position_known) return FuseResult::reject(RejectReason::kNotAligned);
  const StateView view = c.view(shift_s);
  const double altitude_m = pressure_altitude_m(m.pressure_pa);
  if (!c.baro.anchored) {
    c.baro.anchored = true;
    c.baro.offset_m = baro_height_prediction_m(view) - altitude_m;
    c.baro.anchor_std_m = std::sqrt(std::max(c.ekf.p(sx::kPos + 2, sx::kPos + 2), 0.0));
    return FuseResult::ok();
  }
  const double std_m = std::hypot(o.baro.height_std_m, c.baro.anchor_std_m);
  const Observation obs = baro_height_observation(view, altitude_m + c.baro.offset_m, std_m);
  return c.apply(o, obs, o.gate_for(GatedAid::kPressure, obs.rows()));
}

}  // namespace navfuse::filter
