#include "filter/ekf.hpp"

#include <Eigen/Cholesky>

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

UpdateResult Ekf::update(const Observation& obs, double gate) {
  UpdateResult result;
  const int m = obs.rows();
  if (m == 0) return result;
  const auto hn = obs.h.leftCols(n);
  auto pn = p.topLeftCorner(n, n);

  // P H^T (n x m) and S = H P H^T + R (m x m).
  const GainMatrix pht = pn * hn.transpose();
  Observation::Noise s = obs.r;
  s.noalias() += hn * pht;
  Eigen::LLT<Observation::Noise> llt(s);
  if (llt.info() != Eigen::Success) {
    result.singular = true;
    return result;
  }
  result.nis = obs.residual.dot(llt.solve(obs.residual));
  if (gate > 0.0 && !(result.nis <= gate)) return result;

  // K = P H^T S^-1, as (S^-1 H P)^T since S is symmetric.
  const GainMatrix k = llt.solve(pht.transpose()).transpose();
  result.dx.head(n) = k * obs.residual;

  // Joseph form through rank-m factors:
  //   M = (I - K H) P = P - K (H P)
  //   M (I - K H)^T = M - (M H^T) K^T
  //   P' = M (I - K H)^T + K R K^T
  Covariance mm;
  auto mn = mm.topLeftCorner(n, n);
  mn = pn;
  mn.noalias() -= k * pht.transpose();
  const GainMatrix mht = mn * hn.transpose();
  mn.noalias() -= mht * k.transpose();
  const GainMatrix kr = k * obs.r;
  mn.noalias() += kr * k.transpose();
  pn = 0.5 * (mn + mn.transpose());
  result.accepted = true;
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
bool Ekf::finite() const { return p.diagonal().head(n).allFinite(); }

}  // namespace navfuse::filter
