#include "filter/control/external_aiding_control.hpp"

#include "core/geodesy/geodesy.hpp"
#include "filter/alignment.hpp"
#include "filter/measurements/external_aiding.hpp"

namespace navfuse::filter {

FuseResult fuse(FilterCore& c, const FilterOptions& o, const ExternalPosition& m,
                                  double shift_s) {
  if ((m.header.valid & 0b111u) == 0) return FuseResult::reject(RejectReason::kInvalid);
  if (!c.mode.levelled) return FuseResult::reject(RejectReason::kNotAligned);
  if (!c.mode.position_known || !c.mode.heading_known) {
    // Only a complete 3-D fix can place the filter; treat it like a GNSS fix at its lever arm.
    if ((m.header.valid & 0b111u) != 0b111u) return FuseResult::reject(RejectReason::kNotAligned);
    GnssPosition fix;
    fix.header = m.header;
    fix.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
    const geo::Llh llh = m.frame == PositionFrame::kLlh ? geo::Llh{m.value.x(), m.value.y(), m.value.z()}
                                                         : geo::llh_from_ecef(m.value);
    fix.lat_rad = llh.lat_rad;
    fix.lon_rad = llh.lon_rad;
    fix.height_m = llh.height_m;
    fix.fix = GnssFixType::kFix3D;
    fix.cov_ned_m2 = m.std_m.array().square().matrix().asDiagonal();
    const Eigen::Vector3d saved = c.x.gnss_lever_arm_m;
    c.x.gnss_lever_arm_m = m.lever_arm_m;
    place_at_fix(c, o, fix);
    c.x.gnss_lever_arm_m = saved;
    return FuseResult::ok();
  }
  const Observation obs = external_position_observation(c.view(shift_s), m);
  const FuseResult r = c.apply(o, obs, o.gate_for(GatedAid::kExternalPosition, obs.rows()));
  if (r.used) c.mode.last_absolute_position_ns = m.header.time_ns;
  return r;
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const ExternalVelocity& m,
                                  double shift_s) {
  if ((m.header.valid & 0b111u) == 0) return FuseResult::reject(RejectReason::kInvalid);
  if (!c.mode.levelled || !c.mode.heading_known) return FuseResult::reject(RejectReason::kNotAligned);
  const Observation obs = external_velocity_observation(c.view(shift_s), m);
  return c.apply(o, obs, o.gate_for(GatedAid::kExternalVelocity, obs.rows()));
}

FuseResult fuse(FilterCore& c, const FilterOptions& o, const ExternalHeading& m,
                                 double shift_s) {
  if ((m.header.valid & ExternalHeading::kValidHeading) == 0) return FuseResult::reject(RejectReason::kInvalid);
  if (!c.mode.levelled) return FuseResult::reject(RejectReason::kNotAligned);
  if (!c.mode.heading_known) {
    set_heading(c, m.heading_rad, m.std_rad);
    return FuseResult::ok();
  }
  const Observation obs = external_heading_observation(c.view(shift_s), m);
  return c.apply(o, obs, o.gate_for(GatedAid::kExternalHeading, obs.rows()));
}

}  // namespace navfuse::filter
