#include "calibration/calibration_epochs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "core/measurements/imu_increments.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::calib {
namespace {

constexpr double kNsPerS = 1e9;

// The smoothed trajectory at `time_ns`: interpolated between the two points around it (position
// and velocity linearly, attitude by slerp) when both lie within `tolerance_ns`, else the nearer
// one within it, else nothing. Interpolated, a read moves continuously with the time asked for:
// a pass's offset (which sets the times read, plan_epochs) then changes its starting states and
// knowns by as much as the vehicle moved, not by whole samples. Read at the nearest sample
// instead, the knowns' window (+-0.125 s: 12.5 samples at 100 Hz, both ends midway between two)
// jumped by a whole sample between offsets 2 ms apart, and the offset it gave by 4 ms
// (parking_drive, seed 1: the passes alternated between -126.1 and -122.0 ms).
std::optional<TrajectoryPoint> trajectory_at(const std::vector<TrajectoryPoint>& traj, std::int64_t time_ns,
                                             std::int64_t tolerance_ns) {
  const auto it = std::lower_bound(traj.begin(), traj.end(), time_ns,
                                   [](const TrajectoryPoint& p, std::int64_t t) { return p.time_ns < t; });
  const TrajectoryPoint* after = it != traj.end() ? &*it : nullptr;
  const TrajectoryPoint* before = it != traj.begin() ? &*(it - 1) : nullptr;
  if (after != nullptr && after->time_ns == time_ns) return *after;
  const bool after_near = after != nullptr && after->time_ns - time_ns <= tolerance_ns;
  const bool before_near = before != nullptr && time_ns - before->time_ns <= tolerance_ns;
  if (after_near && before_near) {
    const double f =
        static_cast<double>(time_ns - before->time_ns) / static_cast<double>(after->time_ns - before->time_ns);
    TrajectoryPoint p;
    p.time_ns = time_ns;
    p.lat_rad = before->lat_rad + f * (after->lat_rad - before->lat_rad);
    p.lon_rad = before->lon_rad + f * (after->lon_rad - before->lon_rad);
    p.height_m = before->height_m + f * (after->height_m - before->height_m);
    p.vel_ned_mps = before->vel_ned_mps + f * (after->vel_ned_mps - before->vel_ned_mps);
    p.q_nv = before->q_nv.slerp(f, after->q_nv);
    p.gyro_bias_v_rps = before->gyro_bias_v_rps + f * (after->gyro_bias_v_rps - before->gyro_bias_v_rps);
    p.accel_bias_v_mps2 = before->accel_bias_v_mps2 + f * (after->accel_bias_v_mps2 - before->accel_bias_v_mps2);
    return p;
  }
  if (after_near && (!before_near || after->time_ns - time_ns <= time_ns - before->time_ns)) return *after;
  if (before_near) return *before;
  return std::nullopt;
}

}  // namespace

ImuRates imu_rates(const std::vector<ImuSample>& imu, std::size_t i) {
  const ImuSample& s = imu[i];
  double dt = i > 0 ? static_cast<double>(s.header.time_ns - imu[i - 1].header.time_ns) / kNsPerS : s.dt_s;
  if (!(dt > 0.0)) dt = s.dt_s;
  if (!(dt > 0.0)) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0};  // no interval: nothing to add
  if (s.quantity == ImuQuantity::kIncrements) {
    const double d = s.dt_s > 0.0 ? s.dt_s : dt;
    return {s.gyro / d, s.accel / d, dt};
  }
  return {s.gyro, s.accel, dt};
}

StartFrameIncrements start_frame_increments(const std::vector<ImuSample>& imu, std::size_t i) {
  const ImuRates r = imu_rates(imu, i);
  StartFrameIncrements out{r.gyro_rps * r.dt_s, r.accel_mps2 * r.dt_s, r.dt_s};
  const ImuSample& s = imu[i];
  if (s.quantity == ImuQuantity::kIncrements && s.increments == ImuIncrements::kCompensated) return out;
  Eigen::Vector3d prev_dtheta = out.dtheta_rad, prev_dvel = out.dvel_mps;
  if (i > 0) {
    const ImuRates p = imu_rates(imu, i - 1);
    prev_dtheta = p.gyro_rps * p.dt_s;
    prev_dvel = p.accel_mps2 * p.dt_s;
  }
  const StartFrameIncrement b = start_frame_increment(out.dtheta_rad, out.dvel_mps, prev_dtheta, prev_dvel);
  out.dtheta_rad = b.phi_rad;
  out.dvel_mps = b.dvel_mps;
  return out;
}

std::size_t nearest_imu(const std::vector<ImuSample>& imu, std::int64_t time_ns) {
  const auto it = std::lower_bound(imu.begin(), imu.end(), time_ns,
                                   [](const ImuSample& s, std::int64_t t) { return s.header.time_ns < t; });
  if (it == imu.end()) return imu.size() - 1;
  const auto i = static_cast<std::size_t>(it - imu.begin());
  if (i > 0 && time_ns - imu[i - 1].header.time_ns < it->header.time_ns - time_ns) return i - 1;
  return i;
}

EpochPlan plan_epochs(const CalibrationLog& log, const CalibrationSetup& setup, const LocalFrame& frame,
                      double max_spacing_s, double max_imu_gap_s, double knowns_half_window_s) {
  EpochPlan plan;
  if (log.imu.size() < 2 || log.trajectory.empty()) return plan;
  const auto offset_ns = static_cast<std::int64_t>(std::llround(setup.imu_time_offset_s * kNsPerS));
  const std::int64_t shift_ns =
      offset_ns - static_cast<std::int64_t>(std::llround(log.setup.imu_time_offset_s * kNsPerS));
  const auto traj_at = [&](std::int64_t imu_time_ns, std::int64_t tolerance_ns) {
    return trajectory_at(log.trajectory, imu_time_ns + shift_ns, tolerance_ns);
  };
  const auto tolerance_ns = static_cast<std::int64_t>(0.02 * kNsPerS);
  const auto half_window_ns = static_cast<std::int64_t>(std::llround(knowns_half_window_s * kNsPerS));

  // The samples at the fixes (the receiver's and external aiding's positions), then fill-ins
  // between fixes further apart than the spacing.
  std::set<std::size_t> chosen;
  const auto anchor_at = [&](std::int64_t fix_time_ns) {
    const std::size_t i = nearest_imu(log.imu, fix_time_ns - offset_ns);
    if (traj_at(log.imu[i].header.time_ns, tolerance_ns)) chosen.insert(i);
  };
  for (const GnssPosition& fix : log.positions) anchor_at(fix.header.time_ns);
  for (const ExternalPosition& fix : log.external_positions) anchor_at(fix.header.time_ns);
  const auto spacing_ns = static_cast<std::int64_t>(max_spacing_s * kNsPerS);
  const auto gap_ns = static_cast<std::int64_t>(max_imu_gap_s * kNsPerS);
  std::vector<std::size_t> base(chosen.begin(), chosen.end());
  for (std::size_t k = 1; k < base.size(); ++k) {
    std::int64_t last = log.imu[base[k - 1]].header.time_ns;
    for (std::size_t i = base[k - 1] + 1; i < base[k]; ++i) {
      const std::int64_t t = log.imu[i].header.time_ns;
      if (t - log.imu[i - 1].header.time_ns > gap_ns) last = t;  // a new chain starts here
      if (t - last >= spacing_ns && log.imu[base[k]].header.time_ns - t >= spacing_ns / 2 &&
          traj_at(t, tolerance_ns)) {
        chosen.insert(i);
        last = t;
      }
    }
  }

  const Eigen::Matrix3d c_vs = rot::dcm_from_rpy(setup.mounting_rpy_rad);
  // Biases: the smoothed ones, averaged over the log (the calibration holds them constant).
  Eigen::Vector3d bg_v = Eigen::Vector3d::Zero(), ba_v = Eigen::Vector3d::Zero();
  for (const TrajectoryPoint& p : log.trajectory) {
    bg_v += p.gyro_bias_v_rps;
    ba_v += p.accel_bias_v_mps2;
  }
  plan.bg0 = c_vs.transpose() * bg_v / static_cast<double>(log.trajectory.size());
  plan.ba0 = c_vs.transpose() * ba_v / static_cast<double>(log.trajectory.size());

  std::size_t previous = 0;
  for (const std::size_t i : chosen) {
    const std::optional<TrajectoryPoint> tp = traj_at(log.imu[i].header.time_ns, tolerance_ns);
    Epoch e;
    e.imu_index = i;
    e.time_ns = log.imu[i].header.time_ns;
    e.llh = {tp->lat_rad, tp->lon_rad, tp->height_m};
    const Eigen::Matrix3d c_tn = frame.rot_from_ned(e.llh);
    const Eigen::Vector3d p = frame.position(e.llh);
    const Eigen::Vector3d v = c_tn * tp->vel_ned_mps;
    const Eigen::Matrix3d c_ts = c_tn * tp->q_nv.toRotationMatrix() * c_vs;
    const Eigen::Quaterniond q(c_ts);
    e.p = {p.x(), p.y(), p.z()};
    e.v = {v.x(), v.y(), v.z()};
    e.q = {q.x(), q.y(), q.z(), q.w()};
    e.knowns.c_vs0 = c_vs;
    // The rate and acceleration as the trajectory changes over +-half_window (its attitude and
    // velocity differenced): one sample's would carry the vibration (10-60 times the data sheet's
    // noise on a car, imu_white_noise.hpp) into the first-order time shifts as a noisy regressor,
    // which biases the offset towards zero (errors in variables). Over 0.25 s that noise falls
    // by sqrt(25) at 100 Hz, while a central difference is exact up to the jerk's change.
    const std::optional<TrajectoryPoint> behind = traj_at(e.time_ns - half_window_ns, tolerance_ns);
    const std::optional<TrajectoryPoint> ahead = traj_at(e.time_ns + half_window_ns, tolerance_ns);
    if (half_window_ns > 0 && behind && ahead && ahead->time_ns > behind->time_ns) {
      const double span_s = static_cast<double>(ahead->time_ns - behind->time_ns) / kNsPerS;
      struct Tangent {
        Eigen::Matrix3d c_ts;
        Eigen::Vector3d v;
      };
      const auto tangent = [&](const TrajectoryPoint& tp) {
        const Eigen::Matrix3d c_tn_p = frame.rot_from_ned({tp.lat_rad, tp.lon_rad, tp.height_m});
        return Tangent{c_tn_p * tp.q_nv.toRotationMatrix() * c_vs, c_tn_p * tp.vel_ned_mps};
      };
      const Tangent b = tangent(*behind), f = tangent(*ahead);
      e.knowns.rate_s_rps = rot::rotvec_from_quat(Eigen::Quaterniond(b.c_ts.transpose() * f.c_ts)) / span_s;
      e.knowns.accel_t_mps2 = (f.v - b.v) / span_s;
    } else {
      const ImuRates r = imu_rates(log.imu, i);
      e.knowns.rate_s_rps = r.gyro_rps - plan.bg0 - c_ts.transpose() * frame.earth_rate();
      e.knowns.accel_t_mps2 = c_ts * (r.accel_mps2 - plan.ba0) + frame.gravity(e.llh) - 2.0 * frame.earth_rate().cross(v);
    }
    if (!plan.epochs.empty()) {
      e.chained = true;
      for (std::size_t j = previous + 1; j <= i; ++j) {
        if (log.imu[j].header.time_ns - log.imu[j - 1].header.time_ns > gap_ns) e.chained = false;
      }
    }
    previous = i;
    plan.epochs.push_back(e);
  }
  return plan;
}

}  // namespace navfuse::calib
