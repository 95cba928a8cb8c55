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
#include "filter/neglected_term.hpp"
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
// angular rate, as the list of its non-zero entries (about 70 of 27 x 27; all in rows
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

  // Appends an entry. One outside rows [0, sx::kDynamicCount) x columns [0, col_end), or beyond
  // kMaxEntries, is a bug in whoever builds the list (the covariance step indexes fixed-size
  // blocks with it): std::logic_error, in every build type.
  void push(int row, int col, double value, int col_end = sx::kCount);
  void add(int row, int col, double value);  // push(), except that exact zeros are not stored
  void add_block(int row, int col, const Eigen::Matrix3d& block);
  SystemRows dense() const;  // rows [0, sx::kDynamicCount) of F
  const Entry* begin() const { return entries.data(); }
  const Entry* end() const { return entries.data() + count; }
};
SystemMatrix system_matrix(const NavState& x, const LocalEarth& earth, const ProcessAccumulator& step);

// Terms of F left out on purpose, in units of F (per second, per second squared): all are
// below the process noise over a step by orders of magnitude at MEMS grade. F is also evaluated
// at the start of the step, C_nb and the mean f and w held over it, and takes the compensation's
// 1 / (1 + s) as 1 (relative errors of |w| T and |s|, a few 1e-3 of each entry).
inline constexpr std::array<NeglectedTerm, 4> kSystemMatrixNeglected{{
    {sx::kPos, 3, sx::kPos, 3, 1e-5,
     "curvature terms of the NED position error, O(|v| / R): <= 1e-5 /s for |v| <= 60 m/s"},
    {sx::kVel, 3, sx::kVel, 3, 2e-5,
     "transport rate's change with velocity in the Coriolis term, O(|v| / R): <= 2e-5 /s for "
     "|v| <= 60 m/s"},
    {sx::kVel, 2, sx::kPos, 3, 3e-8,
     "horizontal: gravity's and the earth rate's change with position, ~1e-8 /s^2 per m"},
    {sx::kVel + 2, 1, sx::kPos, 3, 3e-8,
     "vertical: gravity's change with latitude, and the free-air gradient taken as 2 g / R "
     "(0.4 % below the normal-gravity one, 1.2e-8 /s^2)"},
}};

// Which compiled variant of the covariance step runs: the fastest this CPU has (AVX2 where
// cpu::has_avx2()) or the x86-64 baseline. Neither uses FMA, so both give the same bits; the
// choice exists for the test that shows it.
enum class CovarianceKernel { kFastest, kBaseline };

// P <- Phi P Phi^T + Q_d over the accumulated step (a no-op for an empty step).
void propagate_covariance(Covariance& p, int active_dimension, const NavState& x,
                          const LocalEarth& earth, const ProcessAccumulator& step,
                          const StateVector& noise_density, CovarianceKernel kernel = CovarianceKernel::kFastest);

}  // namespace navfuse::filter
