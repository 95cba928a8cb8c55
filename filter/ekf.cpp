#include "filter/ekf.hpp"

#include <Eigen/Cholesky>

#include "core/cpu/cpu_features.hpp"
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

namespace {

// What the O(N^2) part of the Joseph update needs, by columns (k[m] is column m of K): small
// fixed arrays the loops below index directly.
template <int N, int M>
struct RankFactors {
  double k[M][N];    // K
  double pht[M][N];  // P H^T
  double h[M][N];    // H^T
  double kr[M][N];   // K R
};

// Joseph form through rank-M factors, on P's leading N x N block in place:
//   X = (I - K H) P = P - K (H P)
//   X (I - K H)^T = X - (X H^T) K^T
//   P' = X (I - K H)^T + K R K^T,  then P' <- (P' + P'^T) / 2.
// Plain loops down P's columns, which the compiler vectorises for the CPU a variant is compiled
// for (joseph_rank_update_avx2). Every sum runs in the order Eigen's fixed-size lazy products
// evaluate it (over the inner index, first to last) and nothing is fused into an FMA, so both
// variants give the bits of the Eigen expressions they replace.
template <int N, int M>
[[gnu::always_inline]] inline void joseph_rank_update(double* __restrict x, const RankFactors<N, M>& f) {
  constexpr int kStride = sx::kCount;  // P is column-major
  // X = P - K (P H^T)^T, column by column; X H^T accumulated over the columns as they finish
  // (column 0 starts the sums).
  double xht[M][N];
  const auto subtract = [&](double* __restrict col, int j) {
    for (int i = 0; i < N; ++i) {
      double s = f.k[0][i] * f.pht[0][j];
      for (int m = 1; m < M; ++m) s += f.k[m][i] * f.pht[m][j];
      col[i] -= s;
    }
  };
  subtract(x, 0);
  for (int m = 0; m < M; ++m) {
    for (int i = 0; i < N; ++i) xht[m][i] = x[i] * f.h[m][0];
  }
  for (int j = 1; j < N; ++j) {
    double* __restrict const col = x + j * kStride;
    subtract(col, j);
    for (int m = 0; m < M; ++m) {
      const double h = f.h[m][j];
      for (int i = 0; i < N; ++i) xht[m][i] += col[i] * h;
    }
  }
  // X - (X H^T) K^T + (K R) K^T.
  for (int j = 0; j < N; ++j) {
    double* __restrict const col = x + j * kStride;
    for (int i = 0; i < N; ++i) {
      double a = xht[0][i] * f.k[0][j];
      double b = f.kr[0][i] * f.k[0][j];
      for (int m = 1; m < M; ++m) {
        a += xht[m][i] * f.k[m][j];
        b += f.kr[m][i] * f.k[m][j];
      }
      col[i] = (col[i] - a) + b;
    }
  }
  // (X + X^T) / 2, evaluated once per pair of mirrored entries (IEEE addition commutes: both get
  // the same bits).
  for (int col = 0; col < N; ++col) {
    for (int row = 0; row < col; ++row) {
      const double sym = 0.5 * (x[col * kStride + row] + x[row * kStride + col]);
      x[col * kStride + row] = sym;
      x[row * kStride + col] = sym;
    }
    double& d = x[col * kStride + col];
    d = 0.5 * (d + d);  // as the full form rounds it (overflow)
  }
}

// The same loops compiled for the x86-64 baseline (SSE2) and for AVX2 (chosen at run time), as
// the covariance step is (process_model.cpp): no FMA in either, so identical results.
template <int N, int M>
void joseph_rank_update_baseline(Covariance& p, const RankFactors<N, M>& f) {
  joseph_rank_update<N, M>(p.data(), f);
}
#if defined(__x86_64__)
template <int N, int M>
__attribute__((target("avx2"))) void joseph_rank_update_avx2(Covariance& p, const RankFactors<N, M>& f) {
  joseph_rank_update<N, M>(p.data(), f);
}
#endif

// P H^T and S = H P H^T + R for an M-row measurement on the leading N x N block, with S's
// Cholesky factor: what the update, the gate and the adaptations' statistics all start from.
template <int N, int M>
struct Innovation {
  Eigen::Matrix<double, M, N> h;
  Eigen::Matrix<double, N, M> pht;
  Eigen::Matrix<double, M, M> s;
  Eigen::LLT<Eigen::Matrix<double, M, M>> llt;

  Innovation(const Covariance& p, const Observation& obs) : h(obs.h.template topLeftCorner<M, N>()) {
    pht = p.template topLeftCorner<N, N>().lazyProduct(h.transpose());
    s = obs.r.template topLeftCorner<M, M>();
    s.noalias() += h.lazyProduct(pht);
    llt.compute(s);
  }
  bool ok() const { return llt.info() == Eigen::Success; }
  double nis(const Observation& obs) const {
    const Eigen::Matrix<double, M, 1> residual = obs.residual.template head<M>();
    return residual.dot(llt.solve(residual));
  }
};

// The gated Joseph update on the leading N x N block for an M-row measurement. Both are
// compile-time constants (N one of the possible active dimensions, M <= 3) so that every product
// has fixed sizes: the M x M algebra in Eigen, the O(N^2) part in joseph_rank_update.
template <int N, int M>
void joseph_update(Covariance& p, const Observation& obs, double gate, UpdateResult& result) {
  using Gain = Eigen::Matrix<double, N, M>;
  const Innovation<N, M> in(p, obs);
  if (!in.ok()) {
    result.singular = true;
    return;
  }
  const Eigen::Matrix<double, M, 1> residual = obs.residual.template head<M>();
  const Eigen::Matrix<double, M, M> r = obs.r.template topLeftCorner<M, M>();
  const Eigen::Matrix<double, M, N>& h = in.h;
  const Gain& pht = in.pht;
  result.nis = in.nis(obs);
  result.s_diag.template head<M>() = in.s.diagonal();
  if (gate > 0.0 && !(result.nis <= gate)) return;

  // K = P H^T S^-1, as (S^-1 H P)^T since S is symmetric.
  const Gain k = in.llt.solve(pht.transpose()).transpose();
  result.dx.template head<N>() = k * residual;
  const Gain kr = k.lazyProduct(r);

  RankFactors<N, M> f;
  for (int m = 0; m < M; ++m) {
    for (int i = 0; i < N; ++i) {
      f.k[m][i] = k(i, m);
      f.pht[m][i] = pht(i, m);
      f.h[m][i] = h(m, i);
      f.kr[m][i] = kr(i, m);
    }
  }
#if defined(__x86_64__)
  if (cpu::has_avx2()) {
    joseph_rank_update_avx2<N, M>(p, f);
    result.accepted = true;
    return;
  }
#endif
  joseph_rank_update_baseline<N, M>(p, f);
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

InnovationMoments Ekf::innovation_moments(const Observation& obs) const {
  InnovationMoments out;
  if (obs.rows() == 0) return out;
  with_active_dimension(n, [&](auto dim) {
    constexpr int N = decltype(dim)::value;
    const auto of_rows = [&](auto rows) {
      const Innovation<N, decltype(rows)::value> in(p, obs);
      out.spread = in.h.lazyProduct(in.pht).trace();
      if (in.ok()) out.nis = in.nis(obs);
    };
    static_assert(Observation::kMaxRows == 3, "one case per possible measurement dimension");
    switch (obs.rows()) {
      case 1: return of_rows(std::integral_constant<int, 1>{});
      case 2: return of_rows(std::integral_constant<int, 2>{});
      default: return of_rows(std::integral_constant<int, 3>{});
    }
  });
  return out;
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
