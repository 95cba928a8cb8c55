#include "filter/process_model.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/cpu/cpu_features.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/active_dimension.hpp"

namespace navfuse::filter {

StateVector process_noise_density(const FilterOptions& o) {
  StateVector q = StateVector::Zero();
  const auto& n = o.imu;
  q.segment<3>(sx::kVel).setConstant(n.accel_vrw_mps_rts * n.accel_vrw_mps_rts);
  q.segment<3>(sx::kAtt).setConstant(n.gyro_arw_rad_rts * n.gyro_arw_rad_rts);
  // First-order Gauss-Markov driving noise q = 2 sigma^2 / tau keeps the stationary std at sigma
  // (Brown & Hwang, "Introduction to Random Signals and Applied Kalman Filtering", GM process).
  q.segment<3>(sx::kGyroBias).setConstant(2.0 * n.gyro_bias_std_rps * n.gyro_bias_std_rps /
                                          n.gyro_bias_corr_time_s);
  q.segment<3>(sx::kAccelBias).setConstant(2.0 * n.accel_bias_std_mps2 * n.accel_bias_std_mps2 /
                                           n.accel_bias_corr_time_s);
  // Slow random walks for calibration states so they can follow temperature drift without
  // freezing: 1e-4 / sqrt(h) on scale factors, 0.01 deg / sqrt(h) on mounting.
  const double sf_rw = 1e-4 / 60.0;
  q(sx::kWheelScale) = sf_rw * sf_rw;
  q.segment<3>(sx::kGyroScale).setConstant(sf_rw * sf_rw);
  q.segment<3>(sx::kAccelScale).setConstant(sf_rw * sf_rw);
  const double mount_rw = 0.01 * rot::kDegToRad / 60.0;
  q(sx::kMountPitch) = mount_rw * mount_rw;
  q(sx::kMountYaw) = mount_rw * mount_rw;
  // A receiver's latency moves with its load by milliseconds: 1 ms / sqrt(h).
  const double time_offset_rw = 1e-3 / 60.0;
  q(sx::kGnssTimeOffset) = time_offset_rw * time_offset_rw;
  for (int i = 0; i < sx::kCount; ++i) {
    if (!o.states.is_active(i)) q(i) = 0.0;
  }
  return q;
}

namespace {

// Out of line and cold: the check stays a few compares in the covariance step's loops.
[[noreturn, gnu::cold, gnu::noinline]] void entry_out_of_bounds(int row, int col, int col_end, int count) {
  throw std::logic_error("system matrix entry (" + std::to_string(row) + ", " + std::to_string(col) +
                         ") outside rows [0, " + std::to_string(sx::kDynamicCount) + ") x columns [0, " +
                         std::to_string(col_end) + ") or beyond " +
                         std::to_string(SystemMatrix::kMaxEntries) + " entries (" +
                         std::to_string(count) + " held)");
}

// P <- Phi P Phi^T + Q_d on the leading N x N block.
//
// With G = F T (only its first R = sx::kDynamicCount rows are non-zero) and H = its leading
// R x R block, the truncated series Phi = I + G + G^2 / 2 is I + A with A = (I + H / 2) G, zero
// below row R. Then
//   Phi P Phi^T = P + P A^T + (P A^T)^T + A P A^T,
//   P A^T = (P G^T) (I + H^T / 2),   A P A^T = (I + H / 2) (G (P A^T)),
// and every product with G or H runs over their non-zero entries only (F is assembled as a
// list of them: 45 in G, 27 in H for 16 states): about 1,800 multiply-adds instead of 12,000
// for three dense products.
// Q_d = Q T + (F Q + Q F^T) T^2 / 2: the first two terms of the series for
// integral(Phi Q Phi^T), exact enough at T <= 50 ms; its F Q T^2 / 2 part is again R x N.
//
// The loops run on plain arrays laid out so that each multiply-add sweeps contiguous memory
// (P A^T column-wise, G (P A^T) row-wise through a transposed copy) and the symmetrised result
// is written straight from the sums, one pass over the upper triangle: half the instructions of
// the same arithmetic on Eigen blocks. Every entry gets exactly the operations, in the same
// order, of the formulas above, so the result does not depend on the layout.
template <int N>
[[gnu::always_inline]] inline void discrete_step(Covariance& p, const SystemMatrix& f, const StateVector& q, double t) {
  constexpr int R = sx::kDynamicCount;
  static_assert(N >= R, "the active block always holds position, velocity and attitude");
  // G = F T within the active block, and H, its leading R x R block. Subsets of f's entries,
  // which push() checked as system_matrix built them: here only debug builds check again.
  SystemMatrix g, h;
  for (const SystemMatrix::Entry& e : f) {
    if (e.col >= N) continue;  // an inactive state
    assert(e.row >= 0 && e.row < R && e.col >= 0 && g.count < SystemMatrix::kMaxEntries);
    g.entries[static_cast<std::size_t>(g.count++)] = {e.row, e.col, e.value * t};
    if (e.col < R) h.entries[static_cast<std::size_t>(h.count++)] = {e.row, e.col, e.value * t};
  }
  const double* pc = p.data();  // column-major, leading dimension sx::kCount
  auto p_col = [&](int col) { return pc + static_cast<std::ptrdiff_t>(col) * sx::kCount; };

  // W = P G^T (N x R, w[i] is column i): column i gathers G(i, k) P.col(k).
  double w[R][N] = {};
  for (const SystemMatrix::Entry& e : g) {
    const double* pk = p_col(e.col);
    for (int r = 0; r < N; ++r) w[e.row][r] += e.value * pk[r];
  }
  // P A^T = W + W H^T / 2 (N x R, by columns).
  double pat[R][N];
  std::copy(&w[0][0], &w[0][0] + R * N, &pat[0][0]);
  for (const SystemMatrix::Entry& e : h) {
    const double v = 0.5 * e.value;
    for (int r = 0; r < N; ++r) pat[e.row][r] += v * w[e.col][r];
  }
  // Y = G (P A^T) (R x R, by rows), through the rows of P A^T; then A P A^T = Y + H Y / 2.
  double pat_rows[N][R];
  for (int c = 0; c < R; ++c) {
    for (int r = 0; r < N; ++r) pat_rows[r][c] = pat[c][r];
  }
  double y[R][R] = {};
  for (const SystemMatrix::Entry& e : g) {
    for (int c = 0; c < R; ++c) y[e.row][c] += e.value * pat_rows[e.col][c];
  }
  double apat[R][R];
  std::copy(&y[0][0], &y[0][0] + R * R, &apat[0][0]);
  for (const SystemMatrix::Entry& e : h) {
    const double v = 0.5 * e.value;
    for (int c = 0; c < R; ++c) apat[e.row][c] += v * y[e.col][c];
  }
  // Q F^T T^2 / 2 (N x R): entry (k, i) = q_k G(i, k) T / 2.
  for (const SystemMatrix::Entry& e : g) pat[e.row][e.col] += q(e.col) * e.value * (0.5 * t);

  // next = P + P A^T (left R columns) + (P A^T)^T (top R rows) + A P A^T + Q T (diagonal), and
  // P <- (next + next^T) / 2, each pair of mirrored entries from one evaluation. By region:
  // both indices below R get every term, one of them below R only the P A^T term it lies in,
  // none below R only the diagonal noise.
  auto store = [&](int row, int col, double next_rc, double next_cr) {
    const double sym = 0.5 * (next_rc + next_cr);
    p(row, col) = sym;
    p(col, row) = sym;
  };
  for (int col = 0; col < R; ++col) {
    for (int row = 0; row < col; ++row) {
      store(row, col, p_col(col)[row] + pat[col][row] + pat[row][col] + apat[row][col],
            p_col(row)[col] + pat[row][col] + pat[col][row] + apat[col][row]);
    }
    const double d = p_col(col)[col] + pat[col][col] + pat[col][col] + apat[col][col] + q(col) * t;
    store(col, col, d, d);
  }
  for (int col = R; col < N; ++col) {
    for (int row = 0; row < R; ++row) store(row, col, p_col(col)[row] + pat[row][col], p_col(row)[col] + pat[row][col]);
    for (int row = R; row < col; ++row) store(row, col, p_col(col)[row], p_col(row)[col]);
    const double d = p_col(col)[col] + q(col) * t;
    store(col, col, d, d);
  }
}

// The same step compiled twice: for the x86-64 baseline (SSE2) and for AVX2, whose 4-wide
// vectors halve the instructions of the column loops on CPUs that have it (chosen at run time).
// Neither enables FMA, so both round every product and sum alike: identical results.
template <int N>
void discrete_step_baseline(Covariance& p, const SystemMatrix& f, const StateVector& q, double t) {
  discrete_step<N>(p, f, q, t);
}
#if defined(__x86_64__)
template <int N>
__attribute__((target("avx2"))) void discrete_step_avx2(Covariance& p, const SystemMatrix& f, const StateVector& q,
                                                        double t) {
  discrete_step<N>(p, f, q, t);
}
#endif

}  // namespace

void SystemMatrix::push(int row, int col, double value, int col_end) {
  // One branch: negative indices wrap to large unsigned values.
  const bool outside = (static_cast<unsigned>(row) >= static_cast<unsigned>(sx::kDynamicCount)) |
                       (static_cast<unsigned>(col) >= static_cast<unsigned>(col_end)) | (count >= kMaxEntries);
  if (outside) [[unlikely]] entry_out_of_bounds(row, col, col_end, count);
  entries[static_cast<std::size_t>(count++)] = {row, col, value};
}

void SystemMatrix::add(int row, int col, double value) {
  if (value != 0.0) push(row, col, value);
}

// Inlined into system_matrix: nine adds with constant offsets.
[[gnu::always_inline]] inline void SystemMatrix::add_block(int row, int col, const Eigen::Matrix3d& block) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) add(row + r, col + c, block(r, c));
  }
}

SystemRows SystemMatrix::dense() const {
  SystemRows f = SystemRows::Zero();
  for (const Entry& e : *this) f(e.row, e.col) += e.value;
  return f;
}

SystemMatrix system_matrix(const NavState& x, const LocalEarth& earth, const ProcessAccumulator& step) {
  const double t = step.dt_s;
  const Eigen::Matrix3d c_nb = x.q_nb.toRotationMatrix();
  const Eigen::Vector3d f_b = step.dvel_mps / t;
  const Eigen::Vector3d w_b = step.dtheta_rad / t;
  const Eigen::Vector3d f_n = c_nb * f_b;
  const Eigen::Vector3d w_ie = earth.earth_rate_ned_rps;
  const Eigen::Vector3d w_en = earth.transport_rate(x.vel_ned_mps);
  const double rn_h = earth.radii.meridian_m + x.height_m;
  const double re_h = earth.radii.prime_vertical_m + x.height_m;
  const double tan_lat = std::tan(x.lat_rad);
  const double omega = w_ie.norm();

  SystemMatrix f;
  // Position: d(dr)/dt = dv (the curvature terms are O(v/R) ~ 1e-6 /s and are dropped).
  for (int i = 0; i < 3; ++i) f.add(sx::kPos + i, sx::kVel + i, 1.0);
  // Velocity: Coriolis, the vertical gravity gradient 2 g / R (the term that makes the vertical
  // channel unstable), tilt coupling [f^n x] and the accelerometer errors.
  f.add_block(sx::kVel, sx::kVel, -rot::skew(2.0 * w_ie + w_en));
  f.add(sx::kVel + 2, sx::kPos + 2,
        2.0 * earth.gravity_ned_mps2.z() / (std::sqrt(earth.radii.meridian_m * earth.radii.prime_vertical_m) + x.height_m));
  f.add_block(sx::kVel, sx::kAtt, rot::skew(f_n));
  f.add_block(sx::kVel, sx::kAccelBias, -c_nb);
  f.add_block(sx::kVel, sx::kAccelScale, -c_nb * f_b.asDiagonal());
  // Attitude: phi_dot = -w_in x phi + d(w_in) + C_nb (d b_g + diag(w) d s_g), with d(w_in) the
  // earth-rate change with latitude and the transport-rate change with velocity.
  f.add_block(sx::kAtt, sx::kAtt, -rot::skew(w_ie + w_en));
  f.add(sx::kAtt + 0, sx::kPos + 0, -omega * std::sin(x.lat_rad) / rn_h);
  f.add(sx::kAtt + 2, sx::kPos + 0, -omega * std::cos(x.lat_rad) / rn_h);
  f.add(sx::kAtt + 0, sx::kVel + 1, 1.0 / re_h);
  f.add(sx::kAtt + 1, sx::kVel + 0, -1.0 / rn_h);
  f.add(sx::kAtt + 2, sx::kVel + 1, -tan_lat / re_h);
  f.add_block(sx::kAtt, sx::kGyroBias, c_nb);
  f.add_block(sx::kAtt, sx::kGyroScale, c_nb * w_b.asDiagonal());
  // Biases: F = 0. The bias is a turn-on constant plus a slow Gauss-Markov part; a -1/tau decay
  // on the sum would pull the (large) turn-on estimate toward zero and decorrelate it from the
  // tilt it was levelled with. Over the filter's horizons (tau >= minutes) the GM part is a random
  // walk with the GM driving noise, which process_noise_density supplies.
  return f;
}

void propagate_covariance(Covariance& p, int n, const NavState& x, const LocalEarth& earth,
                          const ProcessAccumulator& step, const StateVector& q, CovarianceKernel kernel) {
  const double t = step.dt_s;
  if (t <= 0.0) return;
  const SystemMatrix f = system_matrix(x, earth, step);
  with_active_dimension(n, [&](auto dim) {
#if defined(__x86_64__)
    if (kernel == CovarianceKernel::kFastest && cpu::has_avx2()) {
      return discrete_step_avx2<decltype(dim)::value>(p, f, q, t);
    }
#endif
    discrete_step_baseline<decltype(dim)::value>(p, f, q, t);
  });
}

}  // namespace navfuse::filter
