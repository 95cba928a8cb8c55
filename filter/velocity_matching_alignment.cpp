#include "filter/velocity_matching_alignment.hpp"

#include <algorithm>
#include <cmath>

namespace navfuse::filter {

void accumulate_velocity_match(VelocityMatchWindow& w, const Eigen::Matrix3d& c_nb,
                               const Eigen::Vector3d& dvel_b_mps) {
  w.force_integral_mps += (c_nb * dvel_b_mps).head<2>();
}

void restart_velocity_match(VelocityMatchWindow& w, std::int64_t t_ns, const Eigen::Vector2d& vel_ne_mps,
                            const std::optional<Eigen::Vector2d>& force_integral_mps) {
  const Eigen::Vector2d u = w.force_integral_mps;
  w = VelocityMatchWindow{};
  w.force_integral_mps = u;
  w.started = true;
  w.start_ns = t_ns;
  w.u0 = force_integral_mps.value_or(u);
  w.v0 = vel_ne_mps;
}

std::optional<HeadingEstimate> add_velocity_match(VelocityMatchWindow& w, const FilterOptions& o,
                                                  std::int64_t t_ns, const Eigen::Vector2d& vel_ne_mps,
                                                  double vel_var_m2ps2,
                                                  const std::optional<Eigen::Vector2d>& force_integral_mps) {
  if (!w.started || static_cast<double>(t_ns - w.start_ns) * 1e-9 > o.velocity_match_window_s) {
    // A long window lets tilt and bias errors pile up in u: start again from here.
    restart_velocity_match(w, t_ns, vel_ne_mps, force_integral_mps);
    return std::nullopt;
  }
  const Eigen::Vector2d du = force_integral_mps.value_or(w.force_integral_mps) - w.u0;
  const Eigen::Vector2d dv = vel_ne_mps - w.v0;
  w.sum_dot += du.dot(dv);
  w.sum_cross += du.x() * dv.y() - du.y() * dv.x();
  w.sum_uu += du.squaredNorm();
  w.sum_vv += dv.squaredNorm();
  // dv differences two GNSS velocities: twice the per-axis variance, two axes.
  w.sum_noise_var += 2.0 * vel_var_m2ps2;
  ++w.samples;
  if (w.samples < o.velocity_match_min_samples || !(w.sum_uu > 0.0)) return std::nullopt;

  // At the best rotation the residual sum is |dv|^2 + |du|^2 - 2 |(dot, cross)|.
  const double fit = std::hypot(w.sum_dot, w.sum_cross);
  const double residual = std::max(0.0, w.sum_vv + w.sum_uu - 2.0 * fit);
  // Per-axis residual variance, one parameter fitted over 2 n residuals; never below the noise of
  // a velocity difference itself (a lucky near-perfect fit over few samples proves nothing).
  const double n = static_cast<double>(w.samples);
  const double sigma_sq = std::max(residual / std::max(2.0 * n - 1.0, 1.0), w.sum_noise_var / n);
  // Fisher information of psi is sum |du|^2 / sigma^2; doubled because every sample shares the
  // window's first velocity and force integral, so the residuals are not independent.
  const double std_rad = std::sqrt(2.0 * sigma_sq / w.sum_uu);
  if (!(std_rad <= o.velocity_match_max_std_rad)) return std::nullopt;
  return HeadingEstimate{std::atan2(w.sum_cross, w.sum_dot), std_rad};
}

}  // namespace navfuse::filter
