#include "calibration/calibration_problem.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include <ceres/ceres.h>

#include "calibration/bias_segments.hpp"
#include "calibration/calibration_epochs.hpp"
#include "calibration/gnss_factors.hpp"
#include "calibration/imu_preintegration.hpp"
#include "calibration/imu_white_noise.hpp"
#include "calibration/local_frame.hpp"
#include "calibration/median.hpp"
#include "calibration/mounting_rotation.hpp"
#include "calibration/odometry_factors.hpp"
#include "calibration/preintegration_factor.hpp"
#include "calibration/vehicle_velocity_factor.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::calib {
namespace {

constexpr double kNsPerS = 1e9;

// The calibration's own parameter blocks.
struct Globals {
  double lever[3] = {0, 0, 0};
  double nhc_lever[3] = {0, 0, 0};  // the point that does not slip (NhcFactor)
  double mount[2] = {0, 0};  // residual vehicle pitch, yaw about the configured mounting (mounting_dcm)
  double dt[1] = {0};
  double scale[1] = {1};
  double sg[3] = {0, 0, 0};
  double sa[3] = {0, 0, 0};
};

bool usable_fix(const GnssPosition& p) {
  return (p.header.valid & GnssPosition::kValidPosition) != 0 && p.receiver_id == 0 && p.fix != GnssFixType::kNone &&
         p.fix != GnssFixType::kDeadReckoning;
}

// The speed at GNSS time `t_ns` interpolated between its neighbours, when both lie within
// `max_gap_ns`.
bool speed_at(const std::vector<SpeedSample>& speeds, std::int64_t t_ns, std::int64_t max_gap_ns, double& speed,
              double& std) {
  const auto it = std::lower_bound(speeds.begin(), speeds.end(), t_ns,
                                   [](const SpeedSample& s, std::int64_t t) { return s.time_ns < t; });
  if (it == speeds.begin() || it == speeds.end()) return false;
  const SpeedSample& a = *(it - 1);
  const SpeedSample& b = *it;
  if (b.time_ns - a.time_ns > max_gap_ns || b.time_ns == a.time_ns) return false;
  const double span = static_cast<double>(b.time_ns - a.time_ns) / kNsPerS;
  speed = a.speed_mps + (b.speed_mps - a.speed_mps) * static_cast<double>(t_ns - a.time_ns) / kNsPerS / span;
  std = std::max(a.std_mps, b.std_mps);
  return true;
}

// sqrt of each block's covariance diagonal; false when Ceres cannot compute it (rank deficient).
bool block_stds(ceres::Covariance& cov, const double* block, int size, double* out) {
  std::vector<double> c(static_cast<std::size_t>(size * size));
  if (!cov.GetCovarianceBlock(block, block, c.data())) return false;
  for (int i = 0; i < size; ++i) out[i] = std::sqrt(std::max(0.0, c[static_cast<std::size_t>(i * size + i)]));
  return true;
}

// The covariance block of one parameter block (row-major), or nothing when Ceres cannot compute it.
bool block_covariance(ceres::Covariance& cov, const double* block, int size, Eigen::MatrixXd& out) {
  std::vector<double> c(static_cast<std::size_t>(size * size));
  if (!cov.GetCovarianceBlock(block, block, c.data())) return false;
  out = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(c.data(), size, size);
  return true;
}

// One solve, linearised about `setup` and the mounting residual found so far (see calibrate()).
// `placement` receives a fingerprint of which IMU samples the epochs sit at (FNV-1a of their
// indices), so that calibrate() can tell a pass that pairs the fixes as an earlier one did.
CalibrationResult solve_once(const CalibrationLog& log, const CalibrationSetup& setup,
                             const Eigen::Vector2d& mount_residual_rad, const CalibrationOptions& options,
                             std::uint64_t& placement) {
  CalibrationResult result;
  result.gnss_lever_arm_m.value = setup.gnss_lever_arm_m;
  result.mounting_residual_rad.value = mount_residual_rad;
  result.mounting_rpy_rad.value = mounting_rpy(mount_residual_rad, rot::dcm_from_rpy(setup.mounting_rpy_rad));
  result.imu_time_offset_s.value = setup.imu_time_offset_s;
  if (log.trajectory.empty() || log.imu.size() < 2) {
    result.message = "no smoothed trajectory or IMU samples to start from";
    return result;
  }
  const TrajectoryPoint& first = log.trajectory.front();
  const LocalFrame frame({first.lat_rad, first.lon_rad, first.height_m});
  EpochPlan plan = plan_epochs(log, setup, frame, options.max_epoch_spacing_s, options.max_imu_gap_s,
                               options.knowns_half_window_s);
  std::vector<Epoch>& epochs = plan.epochs;
  if (epochs.size() < 3) {
    result.message = "fewer than 3 epochs where GNSS or external position fixes meet the smoothed trajectory";
    return result;
  }
  result.epochs = epochs.size();
  placement = 14695981039346656037ull;
  for (const Epoch& e : epochs) placement = (placement ^ e.imu_index) * 1099511628211ull;

  Globals g;
  for (int i = 0; i < 3; ++i) g.lever[i] = setup.gnss_lever_arm_m[i];
  for (int i = 0; i < 3; ++i) g.nhc_lever[i] = setup.nhc_lever_arm_m[i];
  BiasSegments biases(epochs.front().time_ns, epochs.back().time_ns, options.bias_segments, setup.gyro_bias_std_rps,
                      setup.accel_bias_std_mps2, plan.bg0, plan.ba0);
  g.mount[0] = mount_residual_rad.x();
  g.mount[1] = mount_residual_rad.y();
  g.dt[0] = setup.imu_time_offset_s;

  ceres::Problem problem;
  auto* quaternion = new ceres::EigenQuaternionManifold;  // owned by the problem
  for (Epoch& e : epochs) {
    problem.AddParameterBlock(e.p.data(), 3);
    problem.AddParameterBlock(e.v.data(), 3);
    problem.AddParameterBlock(e.q.data(), 4, quaternion);
  }

  // IMU factors.
  const double noise_std_scale = std::sqrt(setup.imu_noise_scale);
  const auto imu_period_ns = (log.imu.back().header.time_ns - log.imu.front().header.time_ns) /
                             static_cast<std::int64_t>(log.imu.size() - 1);
  const auto noise_half_window = static_cast<std::size_t>(
      std::max(0.0, 0.5 * options.imu_noise_window_s * kNsPerS / static_cast<double>(std::max<std::int64_t>(imu_period_ns, 1))));
  std::vector<double> measured_gyro, measured_accel;  // per IMU factor, for the result's medians
  std::vector<ceres::ResidualBlockId> imu_blocks;
  for (std::size_t k = 1; k < epochs.size(); ++k) {
    Epoch& a = epochs[k - 1];
    Epoch& b = epochs[k];
    if (!b.chained) continue;
    const Eigen::Matrix3d c_ts = Eigen::Quaterniond(a.q[3], a.q[0], a.q[1], a.q[2]).toRotationMatrix();
    ImuNoiseDensity noise{.gyro_rad_rts = setup.gyro_arw_rad_rts, .accel_mps_rts = setup.accel_vrw_mps_rts};
    if (options.imu_noise_window_s > 0.0) {
      const std::size_t centre = (a.imu_index + b.imu_index) / 2;
      // At least 8 of the interval's blocks (16 second differences at one sample's steps).
      const std::size_t half = std::max(noise_half_window, 4 * (b.imu_index - a.imu_index + 1));
      const std::size_t first = centre > half ? centre - half : 0;
      // The smaller of what single samples and blocks as long as the interval show: white noise
      // looks the same at both; an engine tone mostly cancels over the interval (as this
      // factor's increments do) but not between samples; the body's own motion (a walker's
      // steps, a bumpy road's real accelerations) grows with the block and barely shows between
      // samples.
      const double interval_s = static_cast<double>(b.time_ns - a.time_ns) / kNsPerS;
      const std::size_t last = std::min(log.imu.size() - 1, centre + half);
      const ImuWhiteNoise w = least_white_noise(measure_white_noise(log.imu, first, last),
                                                measure_white_noise(log.imu, first, last, interval_s));
      if (w.samples > 0) {
        measured_gyro.push_back(w.gyro_rad_rts);
        measured_accel.push_back(w.accel_mps_rts);
        noise.gyro_rad_rts = std::max(noise.gyro_rad_rts, w.gyro_rad_rts);
        noise.accel_mps_rts = std::max(noise.accel_mps_rts, w.accel_mps_rts);
      }
    }
    noise.gyro_rad_rts *= noise_std_scale;
    noise.accel_mps_rts *= noise_std_scale;
    ImuPreintegration pre(plan.bg0, plan.ba0, c_ts, frame.earth_rate(), noise);
    for (std::size_t i = a.imu_index + 1; i <= b.imu_index; ++i) {
      const StartFrameIncrements d = start_frame_increments(log.imu, i);
      pre.add(d.dtheta_rad, d.dvel_mps, d.dt_s);
    }
    pre.add_bias_drift(setup.gyro_bias_std_rps, setup.accel_bias_std_mps2);
    const Eigen::Vector3d gravity = 0.5 * (frame.gravity(a.llh) + frame.gravity(b.llh));
    const std::size_t seg = biases.at(a.time_ns);  // the interval's start decides
    imu_blocks.push_back(problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PreintegrationFactor, 9, 3, 3, 4, 3, 3, 4, 3, 3, 3, 3>(
            new PreintegrationFactor(pre, gravity, frame.earth_rate())),
        nullptr, a.p.data(), a.v.data(), a.q.data(), b.p.data(), b.v.data(), b.q.data(), biases.gyro(seg),
        biases.accel(seg), g.sg, g.sa));
    ++result.imu_factors;
  }
  add_bias_steps(problem, biases);
  if (!measured_gyro.empty()) {
    result.measured_gyro_noise_rad_rts = median_in_place(measured_gyro);
    result.measured_accel_noise_mps_rts = median_in_place(measured_accel);
  }
  if (result.imu_factors == 0) {
    result.message = "no two epochs are linked by IMU samples";
    return result;
  }

  // GNSS factors at the epoch nearest each fix (through the configured offset).
  const auto offset_ns = static_cast<std::int64_t>(std::llround(setup.imu_time_offset_s * kNsPerS));
  auto epoch_near = [&](std::int64_t gnss_time_ns) -> Epoch* {
    const std::int64_t t = gnss_time_ns - offset_ns;
    const auto it = std::lower_bound(epochs.begin(), epochs.end(), t,
                                     [](const Epoch& e, std::int64_t tt) { return e.time_ns < tt; });
    Epoch* best = it != epochs.end() ? &*it : nullptr;
    if (it != epochs.begin() && (best == nullptr || t - (it - 1)->time_ns < best->time_ns - t)) best = &*(it - 1);
    if (best == nullptr || std::llabs(best->time_ns - t) > imu_period_ns) return nullptr;
    return best;
  };
  struct FixUse {
    const Epoch* epoch;
    Eigen::Vector3d pos_t;
    double tau_s;
  };
  std::vector<FixUse> used_fixes;
  for (const GnssPosition& fix : log.positions) {
    if (!usable_fix(fix)) continue;
    Epoch* e = epoch_near(fix.header.time_ns);
    if (e == nullptr) continue;
    const geo::Llh llh{fix.lat_rad, fix.lon_rad, fix.height_m};
    const Eigen::Matrix3d c_tn = frame.rot_from_ned(llh);
    const Eigen::Vector3d pos_t = frame.position(llh);
    const double tau = static_cast<double>(fix.header.time_ns - e->time_ns) / kNsPerS;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<GnssPositionFactor, 3, 3, 3, 4, 3, 2, 1>(
                                 new GnssPositionFactor(pos_t, c_tn * fix.cov_ned_m2 * c_tn.transpose(), tau, e->knowns)),
                             new ceres::HuberLoss(options.huber_sigmas), e->p.data(), e->v.data(), e->q.data(), g.lever,
                             g.mount, g.dt);
    used_fixes.push_back({e, pos_t, tau});
  }
  result.gnss_position_residuals = used_fixes.size();
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior<3>, 3, 3>(
                               new VectorPrior<3>(log.setup.gnss_lever_arm_m, options.lever_arm_prior_std_m)),
                           nullptr, g.lever);
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior<3>, 3, 3>(
                               new VectorPrior<3>(Eigen::Vector3d::Zero(), setup.gyro_scale_std)),
                           nullptr, g.sg);
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior<3>, 3, 3>(
                               new VectorPrior<3>(Eigen::Vector3d::Zero(), setup.accel_scale_std)),
                           nullptr, g.sa);
  for (const GnssVelocity& vel : log.velocities) {
    if ((vel.header.valid & GnssVelocity::kValidVelocity) == 0 || vel.receiver_id != 0) continue;
    Epoch* e = epoch_near(vel.header.time_ns);
    if (e == nullptr) continue;
    const Eigen::Matrix3d c_tn = frame.rot_from_ned({e->llh});
    const double s2 = setup.gnss_velocity_std_scale * setup.gnss_velocity_std_scale;
    const double tau = static_cast<double>(vel.header.time_ns - e->time_ns) / kNsPerS;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<GnssVelocityFactor, 3, 3, 4, 3, 2, 1>(new GnssVelocityFactor(
            c_tn * vel.vel_ned_mps, s2 * c_tn * vel.cov_ned_m2ps2 * c_tn.transpose(), tau, e->knowns)),
        new ceres::HuberLoss(options.huber_sigmas), e->v.data(), e->q.data(), g.lever, g.mount, g.dt);
    ++result.gnss_velocity_residuals;
  }

  // Headings: the dual-antenna baseline's, and external aiding's of the vehicle's x axis.
  std::uint64_t heading_residuals = 0;
  auto add_heading = [&](std::int64_t time_ns, double heading_rad, double std_rad, const Eigen::Vector3d& baseline_v) {
    if (!(std_rad > 0.0) || !std::isfinite(std_rad) || !std::isfinite(heading_rad)) return false;
    Epoch* e = epoch_near(time_ns);
    if (e == nullptr) return false;
    const Eigen::Matrix3d c_nt = frame.rot_from_ned({e->llh}).transpose();
    const double tau = static_cast<double>(time_ns - e->time_ns) / kNsPerS;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<GnssHeadingFactor, 1, 4, 2, 1>(
                                 new GnssHeadingFactor(heading_rad, std_rad, baseline_v, c_nt, tau, e->knowns)),
                             new ceres::HuberLoss(options.huber_sigmas), e->q.data(), g.mount, g.dt);
    ++heading_residuals;
    return true;
  };
  for (const GnssHeading& h : log.headings) {
    if ((h.header.valid & GnssHeading::kValidHeading) == 0) continue;
    if (add_heading(h.header.time_ns, h.heading_rad, h.heading_std_rad, setup.heading_baseline_v_m)) {
      ++result.gnss_heading_residuals;
    }
  }
  for (const ExternalHeading& h : log.external_headings) {
    if ((h.header.valid & ExternalHeading::kValidHeading) == 0) continue;
    if (add_heading(h.header.time_ns, h.heading_rad, h.std_rad, Eigen::Vector3d::UnitX())) ++result.external_residuals;
  }

  // External positions and velocities: at their own lever arms, held (constant blocks, one per
  // distinct arm), weighted per axis in the frame they come in.
  std::deque<std::array<double, 3>> fixed_levers;
  auto fixed_lever = [&](const Eigen::Vector3d& l) {
    for (std::array<double, 3>& a : fixed_levers) {
      if (a[0] == l.x() && a[1] == l.y() && a[2] == l.z()) return a.data();
    }
    fixed_levers.push_back({l.x(), l.y(), l.z()});
    return fixed_levers.back().data();
  };
  constexpr std::uint32_t kAxes = 0b111u;
  auto usable_axes = [](const Eigen::Vector3d& value, const Eigen::Vector3d& std, std::uint32_t valid) {
    if ((valid & kAxes) == 0) return false;
    for (int i = 0; i < 3; ++i) {
      if ((valid >> i & 1u) != 0 && (!std::isfinite(value[i]) || !(std[i] > 0.0) || !std::isfinite(std[i]))) return false;
    }
    return true;
  };
  for (const ExternalPosition& m : log.external_positions) {
    if (!usable_axes(m.value, m.std_m, m.header.valid)) continue;
    Epoch* e = epoch_near(m.header.time_ns);
    if (e == nullptr) continue;
    Eigen::Vector3d pos_t;
    Eigen::Matrix3d axes_from_t;
    if (m.frame == PositionFrame::kLlh) {
      const geo::Llh llh{m.value.x(), m.value.y(), m.value.z()};
      pos_t = frame.position(llh);
      axes_from_t = frame.rot_from_ned(llh).transpose();
    } else {
      pos_t = frame.position_from_ecef(m.value);
      axes_from_t = frame.rot_from_ecef().transpose();
    }
    double* lever = fixed_lever(m.lever_arm_m);
    const double tau = static_cast<double>(m.header.time_ns - e->time_ns) / kNsPerS;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<GnssPositionFactor, 3, 3, 3, 4, 3, 2, 1>(new GnssPositionFactor(
            pos_t, axis_sqrt_information(m.std_m, m.header.valid, axes_from_t), tau, e->knowns)),
        new ceres::HuberLoss(options.huber_sigmas), e->p.data(), e->v.data(), e->q.data(), lever, g.mount, g.dt);
    problem.SetParameterBlockConstant(lever);
    ++result.external_residuals;
  }
  std::uint64_t vehicle_velocity_residuals = 0;
  for (const ExternalVelocity& m : log.external_velocities) {
    if (!usable_axes(m.value_mps, m.std_mps, m.header.valid)) continue;
    Epoch* e = epoch_near(m.header.time_ns);
    if (e == nullptr) continue;
    const double tau = static_cast<double>(m.header.time_ns - e->time_ns) / kNsPerS;
    if (m.frame == VelocityFrame::kVehicle) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<VehicleVelocityFactor, 3, 3, 4, 2, 1>(new VehicleVelocityFactor(
              m.value_mps, axis_sqrt_information(m.std_mps, m.header.valid, Eigen::Matrix3d::Identity()),
              m.lever_arm_m, tau, e->knowns)),
          new ceres::HuberLoss(options.huber_sigmas), e->v.data(), e->q.data(), g.mount, g.dt);
      ++vehicle_velocity_residuals;
      ++result.external_residuals;
      continue;
    }
    const Eigen::Matrix3d t_from_axes = m.frame == VelocityFrame::kNed ? frame.rot_from_ned({e->llh}) : frame.rot_from_ecef();
    const Eigen::Matrix3d axes_from_t = t_from_axes.transpose();
    double* lever = fixed_lever(m.lever_arm_m);
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<GnssVelocityFactor, 3, 3, 4, 3, 2, 1>(new GnssVelocityFactor(
            axes_from_t.transpose() * m.value_mps, axis_sqrt_information(m.std_mps, m.header.valid, axes_from_t), tau,
            e->knowns)),
        new ceres::HuberLoss(options.huber_sigmas), e->v.data(), e->q.data(), lever, g.mount, g.dt);
    problem.SetParameterBlockConstant(lever);
    ++result.external_residuals;
  }

  // Odometry and NHC at every epoch.
  const Eigen::Matrix3d c_vs0 = rot::dcm_from_rpy(setup.mounting_rpy_rad);
  const Eigen::Matrix3d c_vs_start = mounting_dcm(mount_residual_rad.data(), c_vs0);
  const auto speed_gap_ns = static_cast<std::int64_t>(0.2 * kNsPerS);
  for (Epoch& e : epochs) {
    double speed = 0.0, std = 0.0;
    if (speed_at(log.speeds, e.time_ns + offset_ns, speed_gap_ns, speed, std)) {
      // The speed's rate of change from the IMU's acceleration, not from the speeds themselves:
      // a slope from the same noisy samples as the speed correlates with its noise and biases
      // the time offset (errors in variables). For motion along x, d(v_x)/dt = a_x.
      const Eigen::Matrix3d c_ts = Eigen::Quaterniond(e.q[3], e.q[0], e.q[1], e.q[2]).toRotationMatrix();
      const double slope = (c_vs_start * c_ts.transpose() * e.knowns.accel_t_mps2).x();
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<WheelSpeedFactor, 1, 3, 4, 2, 1, 1>(new WheelSpeedFactor(
                                   speed, slope, setup.imu_time_offset_s, std, c_vs0, e.knowns.rate_s_rps,
                                   setup.wheel_lever_arm_m)),
                               new ceres::HuberLoss(options.huber_sigmas), e.v.data(), e.q.data(), g.mount, g.scale,
                               g.dt);
      ++result.speed_residuals;
    }
    const Eigen::Vector3d v(e.v[0], e.v[1], e.v[2]);
    if (setup.land_vehicle && v.norm() > setup.nhc_min_speed_mps) {
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<NhcFactor, 2, 3, 4, 2, 3>(new NhcFactor(
                                   setup.nhc_lateral_std_mps, setup.nhc_vertical_std_mps, c_vs0, e.knowns.rate_s_rps)),
                               new ceres::HuberLoss(options.huber_sigmas), e.v.data(), e.q.data(), g.mount,
                               g.nhc_lever);
      ++result.nhc_residuals;
    }
  }
  // The non-slip point: held where the config gives it; where it only guesses it, estimated about
  // the guess with the guess's std (an axis of std 0 held at 1 um).
  result.nhc_lever_arm_m.value = setup.nhc_lever_arm_m;
  result.nhc_lever_arm_estimated = result.nhc_residuals > 0 && !log.setup.nhc_lever_arm_std_m.isZero(0.0);
  if (result.nhc_lever_arm_estimated) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior<3>, 3, 3>(new VectorPrior<3>(
                                 log.setup.nhc_lever_arm_m, log.setup.nhc_lever_arm_std_m.cwiseMax(1e-6))),
                             nullptr, g.nhc_lever);
  } else if (result.nhc_residuals > 0) {
    problem.SetParameterBlockConstant(g.nhc_lever);
  }
  result.mounting_estimated =
      result.speed_residuals + result.nhc_residuals + heading_residuals + vehicle_velocity_residuals > 0;
  result.mounting_is_residual = setup.imu_in_vehicle_frame;
  if (!result.mounting_estimated) {
    problem.SetParameterBlockConstant(g.mount);
  } else {
    // Around the configured mounting (residual zero), in every pass.
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VectorPrior<2>, 2, 2>(
                                 new VectorPrior<2>(Eigen::Vector2d::Zero(), options.mounting_prior_std_rad)),
                             nullptr, g.mount);
  }

  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = options.threads;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  result.iterations = static_cast<int>(summary.iterations.size());
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  result.message = summary.BriefReport();
  if (!summary.IsSolutionUsable()) return result;

  double sum_sq = 0.0;
  for (const FixUse& f : used_fixes) {
    const GnssPositionFactor unweighted(f.pos_t, Eigen::Matrix3d::Identity(), f.tau_s, f.epoch->knowns);
    double r[3];
    unweighted(f.epoch->p.data(), f.epoch->v.data(), f.epoch->q.data(), g.lever, g.mount, g.dt, r);
    sum_sq += r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  }
  result.position_rms_m = used_fixes.empty() ? 0.0 : std::sqrt(sum_sq / static_cast<double>(used_fixes.size()));
  // The IMU factors' share of the cost per residual dimension: their variance factor (the
  // redundancy is shared by every group, so this slightly underestimates it; the passes converge
  // on it all the same).
  ceres::Problem::EvaluateOptions imu_only;
  imu_only.residual_blocks = imu_blocks;
  double imu_cost = 0.0;
  problem.Evaluate(imu_only, &imu_cost, nullptr, nullptr, nullptr);
  result.imu_noise_scale = setup.imu_noise_scale;
  result.imu_variance_factor = 2.0 * imu_cost / (9.0 * static_cast<double>(imu_blocks.size()));

  result.gnss_lever_arm_m.value = Eigen::Vector3d(g.lever[0], g.lever[1], g.lever[2]);
  result.nhc_lever_arm_m.value = Eigen::Vector3d(g.nhc_lever[0], g.nhc_lever[1], g.nhc_lever[2]);
  result.mounting_residual_rad.value = Eigen::Vector2d(g.mount[0], g.mount[1]);
  result.mounting_rpy_rad.value = mounting_rpy(result.mounting_residual_rad.value, c_vs0);
  result.imu_time_offset_s.value = g.dt[0];
  result.gyro_scale.value = Eigen::Vector3d(g.sg[0], g.sg[1], g.sg[2]);
  result.accel_scale.value = Eigen::Vector3d(g.sa[0], g.sa[1], g.sa[2]);
  if (result.speed_residuals > 0) result.odometer_scale = Estimate1{.value = g.scale[0], .std = 0.0};

  // Uncertainties: ceres::Covariance on the calibration blocks, scaled by the variance factor of
  // the fit when it exceeds one (residuals larger than their stated noise).
  std::vector<const double*> blocks = {g.lever, g.dt, g.sg, g.sa};
  if (result.mounting_estimated) blocks.push_back(g.mount);
  if (result.speed_residuals > 0) blocks.push_back(g.scale);
  if (result.nhc_lever_arm_estimated) blocks.push_back(g.nhc_lever);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (const double* b : blocks) pairs.emplace_back(b, b);
  add_bias_covariance_pairs(biases, pairs);
  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::SPARSE_QR;
  cov_options.num_threads = options.threads;
  ceres::Covariance covariance(cov_options);
  const auto redundancy = static_cast<double>(summary.num_residuals_reduced - summary.num_effective_parameters_reduced);
  const double variance_factor = redundancy > 0 ? std::max(1.0, 2.0 * summary.final_cost / redundancy) : 1.0;
  const double k = std::sqrt(variance_factor);
  if (covariance.Compute(pairs, &problem)) {
    double s[3];
    result.covariance_ok = block_stds(covariance, g.lever, 3, s);
    result.gnss_lever_arm_m.std = k * Eigen::Vector3d(s[0], s[1], s[2]);
    result.covariance_ok = result.covariance_ok && block_stds(covariance, g.dt, 1, s);
    result.imu_time_offset_s.std = k * s[0];
    result.covariance_ok = bias_estimates(&covariance, biases, k, result) && result.covariance_ok;
    result.covariance_ok = result.covariance_ok && block_stds(covariance, g.sg, 3, s);
    result.gyro_scale.std = k * Eigen::Vector3d(s[0], s[1], s[2]);
    result.covariance_ok = result.covariance_ok && block_stds(covariance, g.sa, 3, s);
    result.accel_scale.std = k * Eigen::Vector3d(s[0], s[1], s[2]);
    Eigen::MatrixXd mount_cov;
    if (result.mounting_estimated && block_covariance(covariance, g.mount, 2, mount_cov)) {
      const Eigen::Matrix2d c = k * k * mount_cov;
      result.mounting_residual_rad.std = c.diagonal().cwiseMax(0.0).cwiseSqrt();
      result.mounting_rpy_rad.std = mounting_rpy_std(result.mounting_residual_rad.value, c, c_vs0);
    }
    if (result.odometer_scale && block_stds(covariance, g.scale, 1, s)) result.odometer_scale->std = k * s[0];
    if (result.nhc_lever_arm_estimated && block_stds(covariance, g.nhc_lever, 3, s)) {
      result.nhc_lever_arm_m.std = k * Eigen::Vector3d(s[0], s[1], s[2]);
      // Held axes (std 0 in the config) report 0: not estimated.
      for (int i = 0; i < 3; ++i) {
        if (log.setup.nhc_lever_arm_std_m[i] == 0.0) result.nhc_lever_arm_m.std[i] = 0.0;
      }
    }
  } else {
    bias_estimates(nullptr, biases, k, result);
    result.message += "; covariance not computable (a calibration parameter is unobservable in this log)";
  }
  return result;
}

}  // namespace

CalibrationResult calibrate(const CalibrationLog& log, const CalibrationOptions& options) {
  // Outer passes: the knowns of the factors (which fix meets which state, the first-order time
  // shifts, the speed's slope, the trajectory read on the IMU clock) are taken at the offset and
  // installation of the previous pass, until the offset stops moving.
  // The IMU's noise is re-weighted between passes as well: an IMU noisier than its data sheet
  // (vibration) shows as IMU factors whose whitened residuals exceed 1 per dimension, and the fit
  // then trusts their integration more than it holds. Their own variance factor (variance
  // component estimation, as Helmert's; the forward filter's innovation-based process-noise
  // adaptation is the same idea) scales their covariance until it is near the threshold. With
  // the data sheet's noise on the vibrating parking_drive it went 1.6 -> 1.2 and one round's time
  // offset -99.6 -> -119.2 ms (truth -125); since each factor's noise is at least what its samples
  // show (imu_white_noise.hpp) the factor stays near 0.04 there and 0.1 on the walk, so it acts
  // only on noise the samples' scatter does not show; on calibration_drive it never acts.
  const auto start = std::chrono::steady_clock::now();
  // The mounting stays the configured one in `setup` (the smoothed attitude was made with it, and
  // the epochs turn it into the sensor's); the residual found so far is carried instead.
  CalibrationSetup setup = log.setup;
  Eigen::Vector2d mount_residual_rad = Eigen::Vector2d::Zero();
  // The passes so far, each the estimate f(x) of a pass placed at offset x. The epochs' states and
  // knowns are read at x (interpolated: calibration_epochs.cpp), so within one pairing of fixes
  // with samples f is continuous and the passes iterate towards the consistent offset, f(x) = x:
  // on parking_drive f moves by ~0.1-0.4 ms per ms of x there. A pass that pairs the fixes as an
  // earlier one did without moving less than the pass before it is no longer getting there (two
  // pairings taking turns): the loop ends with the most nearly consistent pass (|f(x) - x| least)
  // since the earlier one.
  struct Pass {
    std::uint64_t placement;
    double noise_scale;
    double moved_s;  // |f(x) - x|
    CalibrationResult result;
  };
  std::vector<Pass> passes;
  CalibrationResult result;
  for (int pass = 0; pass < options.max_passes; ++pass) {
    std::uint64_t placement = 0;
    result = solve_once(log, setup, mount_residual_rad, options, placement);
    if (result.iterations == 0 || !result.converged) break;
    const double moved_s = std::abs(result.imu_time_offset_s.value - setup.imu_time_offset_s);
    const auto same_pairing = [&](const Pass& p) {
      return p.placement == placement && p.noise_scale == setup.imu_noise_scale;
    };
    const auto seen = static_cast<std::size_t>(std::find_if(passes.begin(), passes.end(), same_pairing) - passes.begin());
    const bool contracting = !passes.empty() && moved_s < passes.back().moved_s;
    passes.push_back({placement, setup.imu_noise_scale, moved_s, result});
    if (seen + 1 < passes.size() && !contracting && moved_s >= options.offset_tolerance_s) {
      result = std::min_element(passes.begin() + static_cast<std::ptrdiff_t>(seen), passes.end(),
                                [](const Pass& a, const Pass& b) { return a.moved_s < b.moved_s; })
                   ->result;
      break;
    }
    setup.imu_time_offset_s = result.imu_time_offset_s.value;
    setup.gnss_lever_arm_m = result.gnss_lever_arm_m.value;
    setup.nhc_lever_arm_m = result.nhc_lever_arm_m.value;
    mount_residual_rad = result.mounting_residual_rad.value;
    const bool reweight = result.imu_variance_factor > options.imu_variance_threshold &&
                          setup.imu_noise_scale < options.max_imu_noise_scale;
    if (reweight) {
      setup.imu_noise_scale = std::min(options.max_imu_noise_scale, setup.imu_noise_scale * result.imu_variance_factor);
    }
    if (moved_s < options.offset_tolerance_s && !reweight) break;
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace navfuse::calib
