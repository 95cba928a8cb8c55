// Truth trajectory of a land vehicle built from motion primitives, and the exact inertial
// quantities (angular rate and specific force) a perfect IMU at the vehicle reference point would
// measure along it.
//
// Kinematic model. The vehicle is non-holonomic: the velocity of its non-slip point P (a car's
// rear-axle centre) lies along the body x axis, v_P,b = [u, 0, 0], so v_P,n = u * [cos(theta)
// cos(psi), cos(theta) sin(psi), -sin(theta)] and pitch is the climb (flight-path) angle. The
// reference point (where the IMU is, and what the truth describes) sits at -l from P, l =
// TrajectorySpec::nonslip_point_m, and moves as a rigid body with it:
//   v_n   = v_P,n - C_nb (omega_nb_b x l)
//   dv_n/dt = dv_P,n/dt - C_nb (omega_nb_b x (omega_nb_b x l) + d(omega_nb_b)/dt x l)
// (Groves §2.5.5's lever-arm velocity, differentiated; C_nb' = C_nb [omega_nb_b x]). The rotation
// taken is omega_nb (relative to the local-level frame) rather than omega_eb: the two differ by the
// transport rate (~3e-6 rad/s at 20 m/s), so P slips by ~4e-6 m/s per metre of l, far below any
// odometry noise. With l = 0 (the default) P is the reference point. Speed u, yaw psi, pitch theta
// and roll phi are smooth functions of time (see MotionSegment); position follows from integrating
// v_n on the WGS-84 ellipsoid (curvilinear position rates, Groves §5.4) with classical RK4.
//
// Inertial quantities (the local-navigation-frame equations of Groves 2nd ed. §5.4, inverted):
//   omega_ib_b = omega_nb_b + C_bn (omega_ie_n + omega_en_n)            (attitude update)
//   f_ib_b     = C_bn [ dv_n/dt - g_n + (omega_en_n + 2 omega_ie_n) x v_n ]  (velocity update)
// with omega_nb_b from the 3-2-1 Euler-angle rates (Titterton & Weston §3.6), earth and transport
// rates from core/geodesy (eqs. 5.41, 5.44) and normal gravity g_n (gravitation plus centrifugal)
// from core/geodesy/gravity.hpp. A strapdown integrator fed with these reproduces the truth.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geodesy/geodesy.hpp"

namespace navfuse::sim {

// The motion primitives. The kind is descriptive (for logs and plots); what moves is given by the
// targets of MotionSegment, so primitives can also be combined (a turn while accelerating).
enum class MotionKind : std::uint8_t {
  kStatic = 0,      // standing still: speed exactly zero, attitude constant
  kCruise = 1,      // constant speed and attitude (straight line)
  kAccelerate = 2,  // speed changes to a target (negative speeds drive backwards)
  kTurn = 3,        // heading changes by a given angle
  kClimb = 4,       // pitch (road grade) changes to a target; height follows
  kCombined = 5,    // several of the above at once
};

// One segment of the profile. Every target that is set is reached at the end of the segment along
// the smooth step s(tau) = tau - sin(2 pi tau) / (2 pi), tau = t / duration: the rate of change,
// (1 - cos(2 pi tau)) / duration times the total change, starts and ends at zero, so speed,
// angular rate and specific force are continuous across segment boundaries (no infinite jerk).
// Quantities without a target keep their value from the end of the previous segment.
struct MotionSegment {
  MotionKind kind = MotionKind::kCruise;
  double duration_s = 0.0;
  std::optional<double> speed_mps;           // target speed along body x at the end
  std::optional<double> heading_change_rad;  // yaw change over the segment (+ = clockwise seen from above)
  std::optional<double> pitch_rad;           // target pitch (= climb angle), + nose up
  std::optional<double> roll_rad;            // target roll (e.g. road camber), + right side down

  // Convenience constructors for the primitives.
  static MotionSegment stationary(double duration_s);
  static MotionSegment cruise(double duration_s);
  static MotionSegment accelerate(double target_speed_mps, double duration_s);
  static MotionSegment turn(double heading_change_rad, double duration_s);
  static MotionSegment climb(double target_pitch_rad, double duration_s);
};

struct TrajectorySpec {
  geo::Llh start{};                 // reference point at t = 0 (radians, ellipsoidal metres)
  double initial_yaw_rad = 0.0;     // heading of body x, clockwise from true north
  double initial_pitch_rad = 0.0;   // the initial speed is zero, so any pitch is allowed
  double initial_roll_rad = 0.0;
  std::vector<MotionSegment> segments;
  // The non-slip point P from the reference point, vehicle frame (FRD), metres: a car whose IMU is
  // 1.2 m ahead of its rear axle has (-1.2, 0, z). Zero: the reference point itself does not slip.
  Eigen::Vector3d nonslip_point_m = Eigen::Vector3d::Zero();
};

// Truth at one instant. The IMU rates are those of a perfect IMU at the vehicle reference point,
// in the vehicle (FRD) frame; the biases are the simulated sensor's true total biases (turn-on
// plus bias instability), rotated into the vehicle frame, so that filter tests can check their
// bias estimates (zero in trajectory-only samples).
struct TruthSample {
  std::int64_t time_ns = 0;  // GPS time
  geo::Llh llh{};
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();  // vehicle FRD -> NED
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();         // roll, pitch, yaw (3-2-1), yaw in [-pi, pi)
  Eigen::Vector3d omega_ib_b_rps = Eigen::Vector3d::Zero();  // angular rate w.r.t. inertial space
  Eigen::Vector3d f_ib_b_mps2 = Eigen::Vector3d::Zero();     // specific force
  Eigen::Vector3d accel_ned_mps2 = Eigen::Vector3d::Zero();  // dv_n/dt
  double speed_mps = 0.0;  // of the non-slip point, along body x (signed)
  Eigen::Vector3d gyro_bias_vehicle_rps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_vehicle_mps2 = Eigen::Vector3d::Zero();
  bool stationary = false;      // exactly zero velocity and angular rate w.r.t. the earth
  bool gnss_available = false;  // a GNSS fix would be produced now (enabled and not in an outage)
};

// Speed, attitude and their time derivatives at one instant: everything the profile defines
// without integrating position.
struct Kinematics {
  double speed_mps = 0.0, speed_rate_mps2 = 0.0;
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();       // yaw not wrapped (continuous)
  Eigen::Vector3d rpy_rate_rps = Eigen::Vector3d::Zero();  // Euler-angle rates
  Eigen::Vector3d rpy_accel_rps2 = Eigen::Vector3d::Zero();  // their time derivatives
  bool stationary = false;
};

class Trajectory {
 public:
  // Throws std::invalid_argument when a segment has a non-positive duration or a kStatic segment
  // starts (or is asked to end) at a non-zero speed.
  // `start_time_ns` is the GPS time of t = 0.
  Trajectory(TrajectorySpec spec, std::int64_t start_time_ns);

  const TrajectorySpec& spec() const { return spec_; }
  double duration_s() const { return total_duration_s_; }

  // Analytic profile at t seconds from the start (clamped to [0, duration]).
  Kinematics kinematics(double t_s) const;
  // Velocity of the reference point in NED (along body x at the non-slip point) and its time
  // derivative.
  Eigen::Vector3d velocity_ned(const Kinematics& k) const;
  Eigen::Vector3d acceleration_ned(const Kinematics& k) const;

  // Truth at the start (time_ns = start_time_ns()).
  TruthSample initial() const;
  // Truth at `from.time_ns + dt_ns`, integrating position from `from` with one RK4 step. Keep
  // dt small (a few ms): the error is O(dt^5) in the (smooth) velocity profile.
  TruthSample propagate(const TruthSample& from, std::int64_t dt_ns) const;
  // Fills attitude, velocity, rates and specific force of `s` from the profile at its time and
  // its (already set) position.
  void complete(TruthSample& s) const;

  std::int64_t start_time_ns() const { return start_time_ns_; }

 private:
  struct SegmentStart {
    double t0_s = 0.0;
    double speed_mps = 0.0;
    Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();
  };
  double seconds_since_start(std::int64_t time_ns) const;

  TrajectorySpec spec_;
  std::vector<SegmentStart> starts_;  // one per segment, plus the end state
  double total_duration_s_ = 0.0;
  std::int64_t start_time_ns_ = 0;
};

}  // namespace navfuse::sim
