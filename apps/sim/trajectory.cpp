// Truth trajectory from motion primitives (see trajectory.hpp for the model and its sources).
#include "apps/sim/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/geodesy/gravity.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr double kTwoPi = 2.0 * rot::kPi;

// Smooth step s(tau) = tau - sin(2 pi tau) / (2 pi) and its derivative with respect to tau.
// s'(0) = s'(1) = 0 and s''(0) = s''(1) = 0, so both the changing quantity's rate and its
// acceleration are continuous at segment boundaries.
double smooth_step(double tau) { return tau - std::sin(kTwoPi * tau) / kTwoPi; }
double smooth_step_rate(double tau) { return 1.0 - std::cos(kTwoPi * tau); }
double smooth_step_accel(double tau) { return kTwoPi * std::sin(kTwoPi * tau); }

// Unit vector of body x in NED for pitch theta and yaw psi (roll does not move it), and its
// partial derivatives: v_n = u * dir (non-holonomic vehicle).
Eigen::Vector3d direction(double theta, double psi) {
  return {std::cos(theta) * std::cos(psi), std::cos(theta) * std::sin(psi), -std::sin(theta)};
}
Eigen::Vector3d direction_d_theta(double theta, double psi) {
  return {-std::sin(theta) * std::cos(psi), -std::sin(theta) * std::sin(psi), -std::cos(theta)};
}
Eigen::Vector3d direction_d_psi(double theta, double psi) {
  return {-std::cos(theta) * std::sin(psi), std::cos(theta) * std::cos(psi), 0.0};
}

// Body angular rate relative to NED from 3-2-1 Euler-angle rates (Titterton & Weston §3.6):
// each rate is resolved about the axis it turns (yaw about n-frame down, pitch about the
// intermediate y, roll about body x) and expressed in the body frame.
Eigen::Vector3d omega_nb_b(const Eigen::Vector3d& rpy, const Eigen::Vector3d& rpy_rate) {
  const double sr = std::sin(rpy.x()), cr = std::cos(rpy.x());
  const double sp = std::sin(rpy.y()), cp = std::cos(rpy.y());
  return {rpy_rate.x() - rpy_rate.z() * sp,
          rpy_rate.y() * cr + rpy_rate.z() * sr * cp,
          -rpy_rate.y() * sr + rpy_rate.z() * cr * cp};
}

// Time derivative of omega_nb_b above, by the chain rule over (rpy, rpy_rate).
Eigen::Vector3d omega_nb_b_rate(const Eigen::Vector3d& rpy, const Eigen::Vector3d& rate,
                                const Eigen::Vector3d& accel) {
  const double sr = std::sin(rpy.x()), cr = std::cos(rpy.x());
  const double sp = std::sin(rpy.y()), cp = std::cos(rpy.y());
  const double dr = rate.x(), dp = rate.y(), dy = rate.z();
  return {accel.x() - accel.z() * sp - dy * dp * cp,
          accel.y() * cr - dp * dr * sr + accel.z() * sr * cp + dy * (dr * cr * cp - dp * sr * sp),
          -accel.y() * sr - dp * dr * cr + accel.z() * cr * cp - dy * (dr * sr * cp + dp * cr * sp)};
}

// Curvilinear position rates (Groves §5.4): lat, lon, height.
Eigen::Vector3d llh_rate(const geo::Llh& p, const Eigen::Vector3d& v_n) {
  const geo::Radii r = geo::radii_of_curvature(p.lat_rad);
  return {v_n.x() / (r.meridian_m + p.height_m),
          v_n.y() / ((r.prime_vertical_m + p.height_m) * std::cos(p.lat_rad)), -v_n.z()};
}

geo::Llh add(const geo::Llh& p, const Eigen::Vector3d& d, double scale) {
  return {p.lat_rad + scale * d.x(), p.lon_rad + scale * d.y(), p.height_m + scale * d.z()};
}

}  // namespace

MotionSegment MotionSegment::stationary(double duration_s) {
  MotionSegment s;
  s.kind = MotionKind::kStatic;
  s.duration_s = duration_s;
  s.speed_mps = 0.0;
  return s;
}
MotionSegment MotionSegment::cruise(double duration_s) {
  MotionSegment s;
  s.kind = MotionKind::kCruise;
  s.duration_s = duration_s;
  return s;
}
MotionSegment MotionSegment::accelerate(double target_speed_mps, double duration_s) {
  MotionSegment s;
  s.kind = MotionKind::kAccelerate;
  s.duration_s = duration_s;
  s.speed_mps = target_speed_mps;
  return s;
}
MotionSegment MotionSegment::turn(double heading_change_rad, double duration_s) {
  MotionSegment s;
  s.kind = MotionKind::kTurn;
  s.duration_s = duration_s;
  s.heading_change_rad = heading_change_rad;
  return s;
}
MotionSegment MotionSegment::climb(double target_pitch_rad, double duration_s) {
  MotionSegment s;
  s.kind = MotionKind::kClimb;
  s.duration_s = duration_s;
  s.pitch_rad = target_pitch_rad;
  return s;
}

Trajectory::Trajectory(TrajectorySpec spec, std::int64_t start_time_ns)
    : spec_(std::move(spec)), start_time_ns_(start_time_ns) {
  SegmentStart state;
  state.rpy_rad = {spec_.initial_roll_rad, spec_.initial_pitch_rad, spec_.initial_yaw_rad};
  starts_.reserve(spec_.segments.size() + 1);
  for (std::size_t i = 0; i < spec_.segments.size(); ++i) {
    const MotionSegment& seg = spec_.segments[i];
    if (!(seg.duration_s > 0.0) || !std::isfinite(seg.duration_s)) {
      throw std::invalid_argument("trajectory segment " + std::to_string(i) +
                                  ": duration must be positive");
    }
    if (seg.kind == MotionKind::kStatic &&
        (state.speed_mps != 0.0 || seg.speed_mps.value_or(0.0) != 0.0 || seg.heading_change_rad ||
         seg.pitch_rad || seg.roll_rad)) {
      throw std::invalid_argument("trajectory segment " + std::to_string(i) +
                                  ": a static segment needs zero speed and no attitude change");
    }
    starts_.push_back(state);
    state.t0_s += seg.duration_s;
    state.speed_mps = seg.speed_mps.value_or(state.speed_mps);
    state.rpy_rad.x() = seg.roll_rad.value_or(state.rpy_rad.x());
    state.rpy_rad.y() = seg.pitch_rad.value_or(state.rpy_rad.y());
    state.rpy_rad.z() += seg.heading_change_rad.value_or(0.0);
  }
  starts_.push_back(state);
  total_duration_s_ = state.t0_s;
}

Kinematics Trajectory::kinematics(double t_s) const {
  Kinematics k;
  // Segment containing t: the last start at or before it.
  const auto it = std::upper_bound(starts_.begin(), starts_.end() - 1, t_s,
                                   [](double t, const SegmentStart& s) { return t < s.t0_s; });
  if (it == starts_.begin() || t_s >= total_duration_s_) {
    const SegmentStart& s = (t_s >= total_duration_s_) ? starts_.back() : starts_.front();
    k.speed_mps = s.speed_mps;
    k.rpy_rad = s.rpy_rad;
  } else {
    const std::size_t i = static_cast<std::size_t>(std::distance(starts_.begin(), it)) - 1;
    const SegmentStart& a = starts_[i];
    const SegmentStart& b = starts_[i + 1];
    const double duration = spec_.segments[i].duration_s;
    const double tau = (t_s - a.t0_s) / duration;
    const double s = smooth_step(tau);
    const double s_rate = smooth_step_rate(tau) / duration;
    const double s_accel = smooth_step_accel(tau) / (duration * duration);
    k.speed_mps = a.speed_mps + (b.speed_mps - a.speed_mps) * s;
    k.speed_rate_mps2 = (b.speed_mps - a.speed_mps) * s_rate;
    k.rpy_rad = a.rpy_rad + (b.rpy_rad - a.rpy_rad) * s;
    k.rpy_rate_rps = (b.rpy_rad - a.rpy_rad) * s_rate;
    k.rpy_accel_rps2 = (b.rpy_rad - a.rpy_rad) * s_accel;
  }
  k.stationary = k.speed_mps == 0.0 && k.speed_rate_mps2 == 0.0 && k.rpy_rate_rps.isZero(0.0);
  return k;
}

Eigen::Vector3d Trajectory::velocity_ned(const Kinematics& k) const {
  const Eigen::Vector3d v_p = k.speed_mps * direction(k.rpy_rad.y(), k.rpy_rad.z());
  const Eigen::Vector3d& l = spec_.nonslip_point_m;
  if (l.isZero(0.0)) return v_p;
  const Eigen::Vector3d w = omega_nb_b(k.rpy_rad, k.rpy_rate_rps);
  return v_p - rot::quat_from_rpy(k.rpy_rad) * w.cross(l);
}

Eigen::Vector3d Trajectory::acceleration_ned(const Kinematics& k) const {
  const double theta = k.rpy_rad.y(), psi = k.rpy_rad.z();
  const Eigen::Vector3d a_p = k.speed_rate_mps2 * direction(theta, psi) +
                              k.speed_mps * (direction_d_theta(theta, psi) * k.rpy_rate_rps.y() +
                                             direction_d_psi(theta, psi) * k.rpy_rate_rps.z());
  const Eigen::Vector3d& l = spec_.nonslip_point_m;
  if (l.isZero(0.0)) return a_p;
  const Eigen::Vector3d w = omega_nb_b(k.rpy_rad, k.rpy_rate_rps);
  const Eigen::Vector3d w_dot = omega_nb_b_rate(k.rpy_rad, k.rpy_rate_rps, k.rpy_accel_rps2);
  return a_p - rot::quat_from_rpy(k.rpy_rad) * (w.cross(w.cross(l)) + w_dot.cross(l));
}

double Trajectory::seconds_since_start(std::int64_t time_ns) const {
  return static_cast<double>(time_ns - start_time_ns_) * 1e-9;
}

TruthSample Trajectory::initial() const {
  TruthSample s;
  s.time_ns = start_time_ns_;
  s.llh = spec_.start;
  complete(s);
  return s;
}

TruthSample Trajectory::propagate(const TruthSample& from, std::int64_t dt_ns) const {
  // Classical RK4 on (lat, lon, h); the velocity is an explicit function of time, so only the
  // radii of curvature couple the stages to the position.
  const double t0 = seconds_since_start(from.time_ns);
  const double h = static_cast<double>(dt_ns) * 1e-9;
  const Eigen::Vector3d v0 = velocity_ned(kinematics(t0));
  const Eigen::Vector3d vm = velocity_ned(kinematics(t0 + 0.5 * h));
  const Eigen::Vector3d v1 = velocity_ned(kinematics(t0 + h));
  const Eigen::Vector3d k1 = llh_rate(from.llh, v0);
  const Eigen::Vector3d k2 = llh_rate(add(from.llh, k1, 0.5 * h), vm);
  const Eigen::Vector3d k3 = llh_rate(add(from.llh, k2, 0.5 * h), vm);
  const Eigen::Vector3d k4 = llh_rate(add(from.llh, k3, h), v1);
  TruthSample s;
  s.time_ns = from.time_ns + dt_ns;
  s.llh = add(from.llh, k1 + 2.0 * k2 + 2.0 * k3 + k4, h / 6.0);
  complete(s);
  return s;
}

void Trajectory::complete(TruthSample& s) const {
  const Kinematics k = kinematics(seconds_since_start(s.time_ns));
  s.q_nb = rot::quat_from_rpy(k.rpy_rad);
  s.rpy_rad = {k.rpy_rad.x(), k.rpy_rad.y(), rot::wrap_pi(k.rpy_rad.z())};
  s.vel_ned_mps = velocity_ned(k);
  s.accel_ned_mps2 = acceleration_ned(k);
  s.speed_mps = k.speed_mps;
  s.stationary = k.stationary;

  const Eigen::Matrix3d c_bn = s.q_nb.toRotationMatrix().transpose();
  const Eigen::Vector3d w_ie = geo::earth_rate_ned(s.llh.lat_rad);
  const Eigen::Vector3d w_en = geo::transport_rate_ned(s.llh.lat_rad, s.llh.height_m, s.vel_ned_mps);
  const Eigen::Vector3d g = geo::normal_gravity_ned(s.llh.lat_rad, s.llh.height_m);
  s.omega_ib_b_rps = omega_nb_b(k.rpy_rad, k.rpy_rate_rps) + c_bn * (w_ie + w_en);
  // NED velocity equation (Groves §5.4): dv/dt = C_nb f + g - (omega_en + 2 omega_ie) x v,
  // solved for f.
  s.f_ib_b_mps2 = c_bn * (s.accel_ned_mps2 - g + (w_en + 2.0 * w_ie).cross(s.vel_ned_mps));
}

}  // namespace navfuse::sim
