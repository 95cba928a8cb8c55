// GNSS antenna position: p_ant = p + C_nb l (Groves 2nd ed. §14.3.1, lever-arm position model).
#pragma once

#include "core/measurements/measurements.hpp"
#include "filter/measurements/state_view.hpp"

namespace navfuse::filter {

// 1-sigma position noise assumed when a fix reports no covariance (typical receiver figures).
Eigen::Vector3d default_gnss_position_std_m(GnssFixType fix);

// h(x): the antenna position.
PointPrediction gnss_position_prediction(const StateView& s);
// Rows north, east (and down when the height is valid).
Observation gnss_position_observation(const StateView& s, const GnssPosition& m);

}  // namespace navfuse::filter
