#include "filter/ekf.hpp"

#include <Eigen/Cholesky>

#include "filter/active_dimension.hpp"

namespace navfuse::filter {

void Observation::keep_rows(unsigned mask) {
  const int rows_in = rows();
  int out = 0;
  for (int i = 0; i < rows_in; ++i) {
    if ((mask & (1u << i)) == 0) continue;
    residual(out) = residual(i);
    h.row(out) = h.row(i);
    int out_col = 0;
    for (int j = 0; j < rows_in; ++j) {
      if ((mask & (1u << j)) == 0) continue;
      r(out, out_col++) = r(i, j);
    }
    ++out;
  }
  // Shrink without losing the compacted leading rows (conservativeResize keeps them).
  residual.conservativeResize(out);
  h.conservativeResize(out, sx::kCount);
  r.conservativeResize(out, out);
}

double Ekf::predicted_spread(const Observation& obs) const {
  double spread = 0.0;
  for (int i = 0; i < obs.rows(); ++i) {
    const auto h = obs.h.row(i).head(n);
    spread += h.dot(p.topLeftCorner(n, n) * h.transpose());
  }
  return spread;
}

namespace {
using GainMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, sx::kCount, Observation::kMaxRows>;
}  // namespace

double Ekf::nis(const Observation& obs) const {
  if (obs.rows() == 0) return 0.0;
  const auto hn = obs.h.leftCols(n);
  const GainMatrix pht = p.topLeftCorner(n, n) * hn.transpose();
  Observation::Noise s = obs.r;
  s.noalias() += hn * pht;
  Eigen::LLT<Observation::Noise> llt(s);
  if (llt.info() != Eigen::Success) return 0.0;
  return obs.residual.dot(llt.solve(obs.residual));
}

namespace {

// The gated Joseph update on the leading N x N block for an M-row measurement. Both are
// compile-time constants (N one of the possible active dimensions, M <= 3) so that every product
// below has fixed sizes with inner dimension M or N, which Eigen evaluates coefficient-wise,
// unrolled and vectorised, instead of through its blocked GEMM kernels.
template <int N, int M>
void joseph_update(Covariance& p, const Observation& obs, double gate, UpdateResult& result) {
  using Gain = Eigen::Matrix<double, N, M>;
  using Block = Eigen::Matrix<double, N, N>;
  using Square = Eigen::Matrix<double, M, M>;
  const Eigen::Matrix<double, M, N> h = obs.h.template topLeftCorner<M, N>();
  const Eigen::Matrix<double, M, 1> residual = obs.residual.template head<M>();
  const Square r = obs.r.template topLeftCorner<M, M>();
  const Block pn = p.template topLeftCorner<N, N>();

  // P H^T (N x M) and S = H P H^T + R (M x M).
  const Gain pht = pn.lazyProduct(h.transpose());
  Square s = r;
  s.noalias() += h.lazyProduct(pht);
  Eigen::LLT<Square> llt(s);
  if (llt.info() != Eigen::Success) {
    result.singular = true;
    return;
  }
  result.nis = residual.dot(llt.solve(residual));
  result.s_diag.template head<M>() = s.diagonal();
  if (gate > 0.0 && !(result.nis <= gate)) return;

  // K = P H^T S^-1, as (S^-1 H P)^T since S is symmetric.
  const Gain k = llt.solve(pht.transpose()).transpose();
  result.dx.template head<N>() = k * residual;

  // Joseph form through rank-M factors:
  //   X = (I - K H) P = P - K (H P)
  //   X (I - K H)^T = X - (X H^T) K^T
  //   P' = X (I - K H)^T + K R K^T
  // X is formed in P's own block (P is still held in pn), and (X + X^T) / 2 is evaluated once per
  // pair of mirrored entries (IEEE addition commutes: both get the same bits).
  auto x = p.template topLeftCorner<N, N>();
  x.noalias() -= k.lazyProduct(pht.transpose());
  const Gain xht = x.lazyProduct(h.transpose());
  x.noalias() -= xht.lazyProduct(k.transpose());
  const Gain kr = k.lazyProduct(r);
  x.noalias() += kr.lazyProduct(k.transpose());
  for (int col = 0; col < N; ++col) {
    for (int row = 0; row < col; ++row) {
      const double sym = 0.5 * (x(row, col) + x(col, row));
      x(row, col) = sym;
      x(col, row) = sym;
    }
    x(col, col) = 0.5 * (x(col, col) + x(col, col));  // as the full form rounds it (overflow)
  }
  result.accepted = true;
}

template <int N>
void joseph_update_rows(Covariance& p, const Observation& obs, double gate, UpdateResult& result) {
  static_assert(Observation::kMaxRows == 3, "one case per possible measurement dimension");
  switch (obs.rows()) {
    case 1: return joseph_update<N, 1>(p, obs, gate, result);
    case 2: return joseph_update<N, 2>(p, obs, gate, result);
    default: return joseph_update<N, 3>(p, obs, gate, result);
  }
}

}  // namespace

UpdateResult Ekf::update(const Observation& obs, double gate) {
  UpdateResult result;
  if (obs.rows() == 0) return result;
  with_active_dimension(n, [&](auto dim) { joseph_update_rows<decltype(dim)::value>(p, obs, gate, result); });
  return result;
}

void Ekf::reset_states(int first, int count, double variance) {
  p.middleRows(first, count).setZero();
  p.middleCols(first, count).setZero();
  p.block(first, first, count, count).diagonal().setConstant(variance);
}

void Ekf::reset_states(int first, const Eigen::Matrix3d& covariance) {
  p.middleRows(first, 3).setZero();
  p.middleCols(first, 3).setZero();
  p.block<3, 3>(first, first) = covariance;
}

void Ekf::guard(const StateVector& floor) {
  // Updates and propagation leave P exactly symmetric; only the diagonal needs a floor.
  for (int i = 0; i < n; ++i) {
    if (floor(i) > 0.0 && !(p(i, i) >= floor(i))) p(i, i) = floor(i);
  }
}

// NaN or inf anywhere in P reaches the diagonal within one propagation step.
// Checked at every IMU sample: over the fixed-size diagonal, which Eigen vectorises.
bool Ekf::finite() const {
  bool all = true;
  with_active_dimension(n, [&](auto dim) { all = p.diagonal().template head<decltype(dim)::value>().allFinite(); });
  return all;
}

}  // namespace navfuse::filter
