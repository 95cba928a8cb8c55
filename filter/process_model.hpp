// Error-state dynamics: the continuous-time system matrix F and noise of the phi-angle error
// model in local NED (Shin 2005 thesis ch. 3, "INS error model"; Groves 2nd ed. §14.2 for the
// same terms in its own sign convention), discretised over one covariance step.
//
// The covariance runs at a lower rate than the strapdown (FilterOptions::covariance_interval_s):
// specific force and angular rate are averaged over the step and the transition matrix is the
// truncated power series Phi = I + F T + (F T)^2 / 2 (Groves ch. 3, system model). Every entry of
// F T is small for T <= 50 ms (the largest, the tilt coupling |f| T, is 0.5 rad per rad of tilt
// but multiplies milliradian errors), so the truncation error is well below the process noise.
#pragma once

#include <array>

#include <Eigen/Core>

#include "filter/filter_options.hpp"
#include "filter/nav_state.hpp"
#include "filter/state_layout.hpp"
#include "filter/strapdown.hpp"

namespace navfuse::filter {

// Compensated IMU increments summed over one covariance step.
struct ProcessAccumulator {
  double dt_s = 0.0;
  Eigen::Vector3d dtheta_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d dvel_mps = Eigen::Vector3d::Zero();

  void add(const ImuIncrement& compensated) {
    dt_s += compensated.dt_s;
    dtheta_rad += compensated.dtheta_rad;
    dvel_mps += compensated.dvel_mps;
  }
};

// Continuous-time white-noise spectral densities, one per state (zero for random constants).
StateVector process_noise_density(const FilterOptions& options);

// The continuous-time system matrix F at state `x` for the step's mean specific force and
// angular rate, as the list of its non-zero entries (about 60 of 27 x 27; all in rows
// [0, sx::kDynamicCount)), which is what the covariance step multiplies with.
using SystemRows = Eigen::Matrix<double, sx::kDynamicCount, sx::kCount>;
struct SystemMatrix {
  struct Entry {
    int row;
    int col;
    double value;
  };
  static constexpr int kMaxEntries = 3 + 5 * 9 + 1 + 5 * 9;  // the blocks system_matrix() writes
  std::array<Entry, kMaxEntries> entries;
  int count = 0;

  void add(int row, int col, double value);  // exact zeros are not stored
  void add_block(int row, int col, const Eigen::Matrix3d& block);
  SystemRows dense() const;  // rows [0, sx::kDynamicCount) of F
};
SystemMatrix system_matrix(const NavState& x, const LocalEarth& earth, const ProcessAccumulator& step);

// P <- Phi P Phi^T + Q_d over the accumulated step (a no-op for an empty step).
void propagate_covariance(Covariance& p, int active_dimension, const NavState& x,
                          const LocalEarth& earth, const ProcessAccumulator& step,
                          const StateVector& noise_density);

}  // namespace navfuse::filter
