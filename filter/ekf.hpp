// The error-state Kalman filter's covariance and its measurement update.
//
// The update is the Joseph form, P = (I - K H) P (I - K H)^T + K R K^T (Bucy & Joseph 1968;
// Groves 2nd ed. §3.2 notes it keeps P symmetric positive definite under rounding and for any
// gain). Because K H has rank m (the measurement dimension, <= 3), both products are formed from
// rank-m factors, so the update costs O(n^2 m) instead of O(n^3) with no approximation.
#pragma once

#include <Eigen/Core>

#include "filter/state_layout.hpp"

namespace navfuse::filter {

// A linearised measurement: residual = h(x_hat) - z ~= H dx + noise, noise ~ N(0, R).
struct Observation {
  static constexpr int kMaxRows = 3;
  using Residual = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1>;
  using Jacobian = Eigen::Matrix<double, Eigen::Dynamic, sx::kCount, Eigen::RowMajor, kMaxRows, sx::kCount>;
  using Noise = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxRows>;

  Residual residual;
  Jacobian h;
  Noise r;

  explicit Observation(int rows = 0) { resize(rows); }
  void resize(int rows) {
    residual.setZero(rows);
    h.setZero(rows, sx::kCount);
    r.setZero(rows, rows);
  }
  int rows() const { return static_cast<int>(residual.size()); }
  // Keeps only the rows whose bit is set in `mask` (bit i = row i): per-axis validity.
  void keep_rows(unsigned mask);
};

struct UpdateResult {
  bool accepted = false;
  bool singular = false;
  double nis = 0.0;  // normalised innovation squared, r^T S^-1 r
  Eigen::Vector3d s_diag = Eigen::Vector3d::Zero();  // diag of S = H P H^T + R (rows used)
  StateVector dx = StateVector::Zero();
};

struct InnovationMoments {
  double nis = 0.0;     // r^T S^-1 r (0 when S is not positive definite)
  double spread = 0.0;  // tr(H P H^T): the innovation spread the state alone predicts
};

class Ekf {
 public:
  Covariance p = Covariance::Zero();
  int n = sx::kCoreCount;  // active dimension

  // The innovation's statistics without updating (for the adaptations and tests).
  InnovationMoments innovation_moments(const Observation& obs) const;
  // Gate (chi-square threshold, <= 0: no gate) then Joseph update. On acceptance `dx` is the
  // error estimate to subtract from the nominal state; P is updated. On rejection nothing changes.
  UpdateResult update(const Observation& obs, double gate);

  // Forgets everything known about states [first, first + count): zero correlations, new variance.
  void reset_states(int first, int count, double variance);
  void reset_states(int first, const Eigen::Matrix3d& covariance);
  // Clamps variances of active states below `floor` (P is kept symmetric by construction).
  void guard(const StateVector& variance_floor);
  bool finite() const;
};

}  // namespace navfuse::filter
