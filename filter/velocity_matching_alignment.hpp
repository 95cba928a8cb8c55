// In-motion heading alignment by velocity matching: the heading that best rotates the IMU's own
// integrated specific force onto the change of the GNSS velocity.
//
// Before the heading is known the filter already carries a levelled attitude whose yaw is
// arbitrary (vertical-gyro mode). Integrating the specific force in that provisional frame,
//   u(t) = integral C_nb' f_b dt   (horizontal part; gravity is vertical in any yawed frame),
// and comparing it with the GNSS velocity over the same span,
//   v_n(t) - v_n(t0) = R_z(psi) (u(t) - u(t0)),
// gives the rotation psi from the provisional frame to north: a 2-D Procrustes fit,
//   psi = atan2(sum du x dv, sum du . dv)
// (Silson 2011, "Coarse alignment of a ship's strapdown inertial attitude reference system using
// velocity loci", IEEE Trans. Instrum. Meas. 60(6); Wu & Pan 2013, "Velocity/position integration
// formula", IEEE Trans. AES 49(2), for the same fit over integrated velocities).
//
// Unlike heading from the GNSS course it does not assume the vehicle moves along its x axis, so it
// holds for a handheld device, a boat in a current, an aircraft with crab or a robot moving
// sideways: any platform that accelerates or turns. Its uncertainty comes from the fit's own
// residual: std(psi) = sigma / sqrt(sum |du|^2), sigma the residual velocity std per sample.
#pragma once

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"
#include "filter/filter_options.hpp"

namespace navfuse::filter {

struct VelocityMatchWindow {
  Eigen::Vector2d force_integral_mps = Eigen::Vector2d::Zero();  // u, provisional frame
  bool started = false;
  std::int64_t start_ns = 0;
  Eigen::Vector2d u0 = Eigen::Vector2d::Zero();
  Eigen::Vector2d v0 = Eigen::Vector2d::Zero();
  double sum_dot = 0.0;    // sum du . dv
  double sum_cross = 0.0;  // sum du x dv (z component)
  double sum_uu = 0.0;     // sum |du|^2
  double sum_vv = 0.0;     // sum |dv|^2
  double sum_noise_var = 0.0;  // sum of the GNSS horizontal velocity variance per axis
  int samples = 0;
};

struct HeadingEstimate {
  double rotation_rad = 0.0;  // add to the provisional yaw
  double std_rad = 0.0;
};

// One IMU interval: adds the specific force rotated by the provisional attitude.
void accumulate_velocity_match(VelocityMatchWindow& w, const Eigen::Matrix3d& c_nb,
                               const Eigen::Vector3d& dvel_b_mps);

// Starts the window again at this GNSS velocity (at rest, or after a window that did not settle).
// `force_integral_mps`: u at the velocity's time when that is not the current IMU time (see
// add_velocity_match); nullopt: the window's running u.
void restart_velocity_match(VelocityMatchWindow& w, std::int64_t t_ns, const Eigen::Vector2d& vel_ne_mps,
                            const std::optional<Eigen::Vector2d>& force_integral_mps = std::nullopt);

// Adds one GNSS horizontal velocity (with its per-axis variance) taken at the current IMU time;
// returns the heading rotation once the fit is good enough (std below
// o.velocity_match_max_std_rad with at least o.velocity_match_min_samples samples). A velocity
// that is a mean over an interval (two fixes differenced) pairs with the mean of u over that
// interval, given as `force_integral_mps`.
std::optional<HeadingEstimate> add_velocity_match(VelocityMatchWindow& w, const FilterOptions& o,
                                                  std::int64_t t_ns, const Eigen::Vector2d& vel_ne_mps,
                                                  double vel_var_m2ps2,
                                                  const std::optional<Eigen::Vector2d>& force_integral_mps = std::nullopt);

}  // namespace navfuse::filter
