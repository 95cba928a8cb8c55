// Every measurement Jacobian H and the system matrix F against central differences of the
// models themselves (issue 13, "checkable filter math").
//
// H: the residual h(x_hat) - z of each model is evaluated on nominal states moved along each
// error-state axis with inject_error (x_hat = x + eps e_j is inject_error(x, -eps e_j), since
// inject_error subtracts an estimate-minus-truth error), and (r(+eps) - r(-eps)) / (2 eps) is
// compared with column j of H, for all 28 states switched on and at states with non-zero
// attitude, lever arms, rates, latitude and calibration states.
//
// F: one strapdown step from a perturbed and from the unperturbed state, differenced with
// state_difference, gives a numerical transition matrix; it is compared with the filter's
// Phi = I + F T + (F T)^2 / 2 (process_model.hpp).
//
// Entries of a block a model leaves out on purpose (its kNeglected list, with the reason) are held
// only to the bound stated there; every other entry must agree to the differencing accuracy.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geodesy/geodesy.hpp"
#include "core/geodesy/wgs84.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/measurements/baro_height.hpp"
#include "filter/measurements/external_aiding.hpp"
#include "filter/measurements/gnss_heading.hpp"
#include "filter/measurements/gnss_position.hpp"
#include "filter/measurements/gnss_velocity.hpp"
#include "filter/measurements/gravity_vector.hpp"
#include "filter/measurements/magnetic_heading.hpp"
#include "filter/measurements/nonholonomic.hpp"
#include "filter/measurements/wheel_speed.hpp"
#include "filter/measurements/wheel_ticks.hpp"
#include "filter/measurements/zero_velocity.hpp"
#include "filter/nav_state.hpp"
#include "filter/process_model.hpp"
#include "filter/strapdown.hpp"

namespace navfuse::filter {
namespace {

// A nominal state with every optional state non-zero, and the raw IMU rates at it.
struct TestPoint {
  std::string name;
  NavState x;
  Eigen::Vector3d raw_rate_rps;
  Eigen::Vector3d raw_force_mps2;
  double shift_s;
  Eigen::Vector3d accel_ned_mps2;  // the view's acceleration input (GNSS time-offset models)
};

std::vector<TestPoint> test_points() {
  std::vector<TestPoint> points;
  const auto make = [](std::string name, double lat_deg, double height_m, const Eigen::Vector3d& vel,
                       const Eigen::Vector3d& rpy_deg, const Eigen::Vector3d& rate, double shift_s,
                       double gnss_time_offset_s) {
    TestPoint p;
    p.name = std::move(name);
    p.x.lat_rad = lat_deg * rot::kDegToRad;
    p.x.lon_rad = 0.3;
    p.x.height_m = height_m;
    p.x.vel_ned_mps = vel;
    p.x.q_nb = rot::quat_from_rpy(rpy_deg * rot::kDegToRad);
    p.x.gyro_bias_rps = {2e-4, -3e-4, 1e-4};
    p.x.accel_bias_mps2 = {0.02, -0.03, 0.05};
    // Scale errors up to 5e-4: the bound kLeverRateBiasScale is stated for.
    p.x.gyro_scale = {3e-4, -2e-4, 4e-4};
    p.x.accel_scale = {-4e-4, 2e-4, 3e-4};
    p.x.wheel_scale = 0.015;
    p.x.mount_pitch_rad = 0.01;
    p.x.mount_yaw_rad = -0.02;
    p.x.gnss_lever_arm_m = {0.8, -0.4, -1.3};
    p.x.gnss_time_offset_s = gnss_time_offset_s;
    p.accel_ned_mps2 = Eigen::Vector3d(1.2, -0.7, 0.3);
    p.raw_rate_rps = rate;
    p.raw_force_mps2 = Eigen::Vector3d(0.8, -0.3, -9.7);
    p.shift_s = shift_s;
    return p;
  };
  points.push_back(make("turning_mid_latitude", 48.0, 350.0, {14.0, -6.0, 0.3}, {4.0, -3.0, 35.0},
                        {0.02, -0.03, 0.35}, 0.003, 0.125));
  points.push_back(make("banked_southern", -33.0, 20.0, {-9.0, 18.0, -0.5}, {-12.0, 8.0, -150.0},
                        {-0.1, 0.05, -0.5}, -0.004, -0.06));
  points.push_back(make("slow_high_latitude", 71.0, 1200.0, {1.5, 0.8, 0.1}, {2.0, 15.0, 100.0},
                        {0.01, 0.2, 0.05}, 0.0, 0.01));
  return points;
}

// Derivative step per error state: large enough that rounding of the residual (latitude
// resolution 1e-16 rad * 6.4e6 m ~ 1e-9 m, angles ~1e-16 rad) stays below 1e-7 of a unit, small
// enough that the central difference's eps^2 h''' / 6 term is below 1e-7 (attitude: |h'''| is
// about the lever arm, <= 2 m, times 1e-8 / 6).
double step_for(int j) {
  if (j < sx::kVel) return 1e-2;          // m
  if (j < sx::kAtt) return 1e-3;          // m/s
  if (j < sx::kGyroBias) return 1e-4;     // rad
  if (j < sx::kAccelBias) return 1e-6;    // rad/s
  if (j < sx::kCoreCount) return 1e-4;    // m/s^2
  if (j >= sx::kLeverArm && j < sx::kLeverArm + 3) return 1e-3;  // m
  if (j == sx::kGnssTimeOffset) return 1e-3;                       // s (the models are linear in it)
  return 1e-6;                            // scale factors, mounting angles
}

// x_hat = x + e: the state whose error relative to x is e.
NavState with_error(const NavState& x, int j, double e) {
  NavState out = x;
  StateVector dx = StateVector::Zero();
  dx(j) = -e;
  inject_error(out, dx);
  return out;
}

// Agreement needed where no term is left out: the differencing accuracy above, with a relative
// part for the large entries (rounding in the products that form H itself).
constexpr double kAbsTolerance = 1e-6;
constexpr double kRelTolerance = 1e-6;
constexpr double kDoubleEpsilon = std::numeric_limits<double>::epsilon();

const NeglectedTerm* neglected_at(std::span<const NeglectedTerm> terms, int row, int col) {
  for (const NeglectedTerm& t : terms) {
    if (row >= t.first_row && row < t.first_row + t.rows && col >= t.first_col && col < t.first_col + t.cols) {
      return &t;
    }
  }
  return nullptr;
}

// Compares `model` with `numeric` entry by entry and reports every disagreement.
// `value_scale`: the size of the predicted quantity when it is large (ECEF coordinates, 6.4e6 m),
// whose rounding, a few ulp, limits the differences to 4 eps |h| / step.
void expect_close(const Eigen::MatrixXd& model, const Eigen::MatrixXd& numeric,
                  std::span<const NeglectedTerm> neglected, const std::string& what, double value_scale = 0.0) {
  for (int i = 0; i < model.rows(); ++i) {
    for (int j = 0; j < model.cols(); ++j) {
      const double diff = std::abs(model(i, j) - numeric(i, j));
      const NeglectedTerm* t = neglected_at(neglected, i, j);
      const double floor = kAbsTolerance + 4.0 * kDoubleEpsilon * value_scale / step_for(j);
      const double allowed = t != nullptr ? t->max_abs + floor : floor + kRelTolerance * std::abs(numeric(i, j));
      EXPECT_LE(diff, allowed) << what << " entry (" << i << ", " << j << "): model " << model(i, j)
                               << ", central difference " << numeric(i, j)
                               << (t != nullptr ? " [neglected: " + std::string(t->reason) + "]" : "");
    }
  }
}

// One measurement model: its observation on a view of any nominal state.
struct Model {
  std::string name;
  std::function<Observation(const StateView&)> observe;
  std::vector<NeglectedTerm> neglected;
  bool angle = false;        // residual wraps at +-pi
  double value_scale = 0.0;  // see expect_close
};

template <std::size_t N>
std::vector<NeglectedTerm> list(const std::array<NeglectedTerm, N>& a) { return {a.begin(), a.end()}; }

std::vector<Model> models(const TestPoint& p) {
  const NavState& x = p.x;
  const geo::Llh here{x.lat_rad, x.lon_rad, x.height_m};
  const Eigen::Vector3d ext_lever(0.4, 0.2, -0.9);
  const Eigen::Vector3d wheel_lever(-1.2, 0.0, 0.3);

  GnssPosition gp;
  gp.header.valid = GnssPosition::kValidPosition | GnssPosition::kValidHeight | GnssPosition::kValidCovariance;
  const geo::Llh fix = geo::llh_offset(here, {1.5, -2.0, 0.7});
  gp.lat_rad = fix.lat_rad;
  gp.lon_rad = fix.lon_rad;
  gp.height_m = fix.height_m;
  gp.cov_ned_m2 = Eigen::Matrix3d::Identity();
  GnssVelocity gv;
  gv.header.valid = GnssVelocity::kValidVelocity;
  gv.vel_ned_mps = x.vel_ned_mps + Eigen::Vector3d(0.1, -0.2, 0.05);
  GnssHeading gh;
  gh.header.valid = GnssHeading::kValidHeading;
  gh.heading_rad = 0.4;
  gh.heading_std_rad = 0.01;
  const Eigen::Vector3d secondary_lever(-0.6, 0.5, -1.2);
  const Eigen::Vector3d baseline = heading_baseline_b({0.8, -0.4, -1.3}, secondary_lever);
  // Receiver 0 at the primary antenna (its lever arm a state), receiver 1 at the secondary.
  const auto primary = [=](const StateView& s) { return antenna_of_receiver(s.x, secondary_lever, 0); };
  const auto secondary = [=](const StateView& s) { return antenna_of_receiver(s.x, secondary_lever, 1); };

  ExternalPosition ep_llh;
  ep_llh.header.valid = 0b111u;
  ep_llh.frame = PositionFrame::kLlh;
  ep_llh.value = {fix.lat_rad, fix.lon_rad, fix.height_m};
  ep_llh.std_m = {1.0, 1.0, 1.0};
  ep_llh.lever_arm_m = ext_lever;
  ExternalPosition ep_ecef = ep_llh;
  ep_ecef.frame = PositionFrame::kEcef;
  ep_ecef.value = geo::ecef_from_llh(fix);
  ExternalVelocity ev_ned;
  ev_ned.header.valid = 0b111u;
  ev_ned.frame = VelocityFrame::kNed;
  ev_ned.value_mps = gv.vel_ned_mps;
  ev_ned.std_mps = {0.1, 0.1, 0.1};
  ev_ned.lever_arm_m = ext_lever;
  ExternalVelocity ev_ecef = ev_ned;
  ev_ecef.frame = VelocityFrame::kEcef;
  ev_ecef.value_mps = geo::rot_ecef_from_ned(x.lat_rad, x.lon_rad) * ev_ned.value_mps;
  ExternalVelocity ev_body = ev_ned;
  ev_body.frame = VelocityFrame::kVehicle;
  ev_body.value_mps = {10.0, 0.1, -0.05};
  ExternalHeading eh;
  eh.header.valid = ExternalHeading::kValidHeading;
  eh.heading_rad = -2.9;
  eh.std_rad = 0.02;
  // A steep field (inclination ~60 deg), so roll and pitch errors enter the magnetic heading.
  const Eigen::Vector3d field_b(0.21, -0.12, 0.41);
  const double baro_height_m = x.height_m + 3.0;
  // The point model's neglected velocity-over-shift term, down row only (row 0 of the baro row).
  std::vector<NeglectedTerm> baro_terms;
  for (NeglectedTerm t : kPointNeglected) baro_terms.push_back({0, 1, t.first_col, t.cols, t.max_abs, t.reason});
  const SpeedReading speed{12.0, 0.05};
  const Eigen::Vector3d mean_raw_rate(1e-4, -2e-4, 5e-5);

  // The GNSS position moved by v_ant dt carries dt times the antenna velocity's rows, and with them
  // what those leave out (|dt| < 1 s keeps each within its bound).
  std::vector<NeglectedTerm> gnss_position_terms = list(kPointNeglected);
  for (NeglectedTerm t : kAntennaVelocityNeglected) gnss_position_terms.push_back(t);
  std::vector<NeglectedTerm> ecef_velocity = list(kAntennaVelocityNeglected);
  ecef_velocity.push_back(kEcefAxesTurn);
  std::vector<NeglectedTerm> body_velocity = list(kBodyVelocityNeglected);
  std::vector<NeglectedTerm> speed_terms;  // the body-velocity terms, in row 0 only
  std::vector<NeglectedTerm> nhc_terms;    // the body-velocity terms, rows y and z as rows 0 and 1
  for (NeglectedTerm t : kBodyVelocityNeglected) {
    speed_terms.push_back({0, 1, t.first_col, t.cols, t.max_abs, t.reason});
    nhc_terms.push_back({0, 2, t.first_col, t.cols, t.max_abs, t.reason});
  }

  return {
      {"gnss_position", [=](const StateView& s) { return gnss_position_observation(s, gp, primary(s)); },
       gnss_position_terms},
      {"gnss_position_secondary_receiver",
       [=](const StateView& s) { return gnss_position_observation(s, gp, secondary(s)); }, gnss_position_terms},
      {"gnss_velocity", [=](const StateView& s) { return gnss_velocity_observation(s, gv, primary(s)); },
       list(kAntennaVelocityNeglected)},
      {"gnss_velocity_secondary_receiver",
       [=](const StateView& s) { return gnss_velocity_observation(s, gv, secondary(s)); },
       list(kAntennaVelocityNeglected)},
      {"gnss_heading", [=](const StateView& s) { return gnss_heading_observation(s, gh, baseline); }, {}, true},
      {"external_position_llh", [=](const StateView& s) { return external_position_observation(s, ep_llh); },
       list(kPointNeglected)},
      {"external_position_ecef", [=](const StateView& s) { return external_position_observation(s, ep_ecef); },
       list(kPointNeglected), false, geo::wgs84::kSemiMajorAxis_m},
      {"external_velocity_ned", [=](const StateView& s) { return external_velocity_observation(s, ev_ned); },
       list(kAntennaVelocityNeglected)},
      {"external_velocity_ecef", [=](const StateView& s) { return external_velocity_observation(s, ev_ecef); },
       ecef_velocity},
      {"external_velocity_vehicle", [=](const StateView& s) { return external_velocity_observation(s, ev_body); },
       body_velocity},
      {"external_heading", [=](const StateView& s) { return external_heading_observation(s, eh); }, {}, true},
      {"magnetic_heading", [=](const StateView& s) { return magnetic_heading_observation(s, field_b, 0.2, 0.05); },
       list(kMagneticHeadingNeglected), true},
      {"baro_height", [=](const StateView& s) { return baro_height_observation(s, baro_height_m, 1.0); },
       baro_terms},
      {"wheel_speed", [=](const StateView& s) { return wheel_speed_observation(s, speed, wheel_lever, 1.5); },
       speed_terms},
      {"wheel_ticks",
       [=](const StateView& s) { return wheel_tick_observation(s, TickSpeed{speed, 0.1}, wheel_lever, 1.5); },
       speed_terms},
      {"nonholonomic", [=](const StateView& s) { return nonholonomic_observation(s, wheel_lever, Eigen::Vector3d::Zero(), 0.1, 0.1); },
       nhc_terms},
      {"zero_velocity", [](const StateView& s) { return zero_velocity_observation(s, 0.01); }, {}},
      {"gravity_vector",
       [=](const StateView& s) { return gravity_vector_observation(s, p.raw_force_mps2, 0.5); }, {}},
      {"zero_rate", [=](const StateView& s) { return zero_rate_observation(s, mean_raw_rate, 1e-4); },
       list(kZeroRateNeglected)},
  };
}

// The compensated rate a view of `x` sees: the raw rate through x's own gyro bias and scale.
Eigen::Vector3d compensated_rate(const NavState& x, const Eigen::Vector3d& raw_rate) {
  ImuIncrement raw;
  raw.dt_s = 1.0;
  raw.dtheta_rad = raw_rate;
  return compensate(raw, x).dtheta_rad;
}

Eigen::VectorXd residual_of(const Model& m, const NavState& x, const LocalEarth& earth, const TestPoint& p) {
  StateView view(x, earth, compensated_rate(x, p.raw_rate_rps), p.shift_s);
  view.accel_ned_mps2 = p.accel_ned_mps2;
  return m.observe(view).residual;
}

// state_difference is inject_error's inverse, also for differences far outside the linear range.
TEST(Jacobians, StateDifferenceInvertsInjectError) {
  const std::vector<TestPoint> points = test_points();
  const NavState& a = points[0].x;
  NavState b = points[1].x;
  b.lon_rad = a.lon_rad + 0.01;
  NavState c = a;
  inject_error(c, state_difference(a, b));
  EXPECT_NEAR(c.lat_rad, b.lat_rad, 1e-15);
  EXPECT_NEAR(c.lon_rad, b.lon_rad, 1e-15);
  EXPECT_NEAR(c.height_m, b.height_m, 1e-9);
  EXPECT_LT((c.vel_ned_mps - b.vel_ned_mps).norm(), 1e-12);
  EXPECT_LT(c.q_nb.angularDistance(b.q_nb), 1e-14);
  EXPECT_LT((c.gyro_bias_rps - b.gyro_bias_rps).norm() + (c.accel_bias_mps2 - b.accel_bias_mps2).norm() +
                (c.gyro_scale - b.gyro_scale).norm() + (c.accel_scale - b.accel_scale).norm() +
                (c.gnss_lever_arm_m - b.gnss_lever_arm_m).norm() + std::abs(c.wheel_scale - b.wheel_scale) +
                std::abs(c.mount_pitch_rad - b.mount_pitch_rad) + std::abs(c.mount_yaw_rad - b.mount_yaw_rad),
            1e-15);
  // And a small difference is the error inject_error was given.
  StateVector dx;
  for (int i = 0; i < sx::kCount; ++i) dx(i) = 1e-3 * (i % 5 - 2);
  NavState d = a;
  inject_error(d, dx);
  const StateVector err = (state_difference(a, d) - dx).cwiseAbs();
  EXPECT_LT(err.segment<3>(sx::kPos).maxCoeff(), 1e-8);  // latitude resolution ~7e-10 m
  EXPECT_LT(err.tail<sx::kCount - 3>().maxCoeff(), 1e-12);
}

TEST(Jacobians, EveryMeasurementModelMatchesCentralDifferences) {
  for (const TestPoint& p : test_points()) {
    // Earth quantities are those of the filter's covariance grid step: constants of the update.
    const LocalEarth earth = LocalEarth::at(p.x.lat_rad, p.x.height_m);
    for (const Model& m : models(p)) {
      StateView view(p.x, earth, compensated_rate(p.x, p.raw_rate_rps), p.shift_s);
      view.accel_ned_mps2 = p.accel_ned_mps2;
      const Observation obs = m.observe(view);
      ASSERT_GT(obs.rows(), 0) << m.name;
      Eigen::MatrixXd numeric(obs.rows(), sx::kCount);
      for (int j = 0; j < sx::kCount; ++j) {
        const double e = step_for(j);
        Eigen::VectorXd d = residual_of(m, with_error(p.x, j, e), earth, p) -
                            residual_of(m, with_error(p.x, j, -e), earth, p);
        if (m.angle) d = d.unaryExpr([](double a) { return rot::wrap_pi(a); });
        numeric.col(j) = d / (2.0 * e);
      }
      expect_close(obs.h, numeric, m.neglected, p.name + " " + m.name, m.value_scale);
    }
  }
}


// One strapdown step of `raw` from `x`, with the earth quantities at x itself (the gravity
// gradient and the earth-rate change with latitude are part of F).
NavState step_from(NavState x, const ImuIncrement& raw) {
  StrapdownMemory memory;
  strapdown_step(x, memory, compensate(raw, x), LocalEarth::at(x.lat_rad, x.height_m));
  return x;
}

// Step sizes for F: as large as the model stays linear over (central differences cancel the
// second-order part; the third, e.g. |f| phi^3 with phi = 1e-3, is ~1e-8 m/s^2), because the
// differences are taken between propagated states and divided by 2 eps T.
double f_step_for(int j) {
  if (j < sx::kVel) return 1.0;           // m
  if (j < sx::kAtt) return 0.1;           // m/s
  if (j < sx::kGyroBias) return 1e-3;     // rad
  if (j < sx::kAccelBias) return 1e-3;    // rad/s
  if (j < sx::kCoreCount) return 0.1;     // m/s^2
  return 1e-3;                            // scale factors (the other states do not enter F)
}

// Rounding of the propagated state's error, per row: positions are latitude / longitude near 1 rad
// (ulp 1.1e-16) times R, with a few operations: 3e-9 m; velocity a few ulp of 20 m/s; angles a few
// ulp of 1.
double rounding_of_row(int i) {
  if (i < sx::kVel) return 3e-9;
  if (i < sx::kAtt) return 2e-14;
  return 1e-15;
}

// F is evaluated at the start of the step with C_nb held (the body turns by |w| T / 2 <= 1.3e-3
// rad on average over it) and the compensation's 1 / (1 + s) on biases taken as 1 (|s| <= 5e-4):
// each 3 x 3 block is right to that part of its largest entry.
constexpr double kSystemRelTolerance = 3e-3;

// The strapdown evaluates the earth and transport rates at the start of each interval, so the
// second-order products of Phi that run through them (present in (F T)^2 / 2) are missing from
// one step of it. Not terms of F: differences between the series and the integration scheme.
constexpr std::array<NeglectedTerm, 2> kIntegrationScheme{{
    {sx::kVel, 3, 0, sx::kCount, 5e-6,
     "Coriolis on the velocity change within the step, |2 w_ie + w_en| |f| T / 2 <= 4e-6"},
    {sx::kAtt, 3, 0, sx::kCount, 1e-8,
     "transport rate of the velocity change within the step, |f| T / (2 R) <= 4e-9"},
}};

// The largest entry of the 3 x 3 state block holding (i, j); a trailing block may be narrower
// (the single GNSS time-offset state after the 3-wide groups).
double block_max(const Eigen::MatrixXd& m, int i, int j) {
  const Eigen::Index row = i / 3 * 3, col = j / 3 * 3;
  return m.block(row, col, std::min<Eigen::Index>(3, m.rows() - row), std::min<Eigen::Index>(3, m.cols() - col))
      .cwiseAbs()
      .maxCoeff();
}

void expect_close_f(const Eigen::MatrixXd& model, const Eigen::MatrixXd& numeric, double t,
                    std::span<const NeglectedTerm> neglected, const std::string& what) {
  for (int i = 0; i < model.rows(); ++i) {
    for (int j = 0; j < model.cols(); ++j) {
      const double diff = std::abs(model(i, j) - numeric(i, j));
      const NeglectedTerm* n = neglected_at(neglected, i, j);
      const double floor = 1e-12 + rounding_of_row(i) / (2.0 * f_step_for(j) * t);
      const NeglectedTerm* scheme = neglected_at(kIntegrationScheme, i, j);
      const double allowed = floor + kSystemRelTolerance * block_max(model, i, j) +
                             (n != nullptr ? n->max_abs : 0.0) + (scheme != nullptr ? scheme->max_abs : 0.0);
      EXPECT_LE(diff, allowed) << what << " entry (" << i << ", " << j << "): model " << model(i, j)
                               << ", finite difference " << numeric(i, j)
                               << (n != nullptr ? " [neglected: " + std::string(n->reason) + "]" : "");
    }
  }
}

TEST(Jacobians, SystemMatrixMatchesFiniteDifferencesOfTheStrapdown) {
  // One 200 Hz IMU interval: the filter's shortest covariance step.
  constexpr double kT = 0.005;
  for (const TestPoint& p : test_points()) {
    ImuIncrement raw;
    raw.dt_s = kT;
    raw.dtheta_rad = p.raw_rate_rps * kT;
    raw.dvel_mps = p.raw_force_mps2 * kT;
    ProcessAccumulator step;
    step.add(compensate(raw, p.x));
    Covariance f = Covariance::Zero();
    f.topRows<sx::kDynamicCount>() = system_matrix(p.x, LocalEarth::at(p.x.lat_rad, p.x.height_m), step).dense();
    const Covariance ft = f * kT;
    const Covariance phi = Covariance::Identity() + ft + 0.5 * ft * ft;

    const NavState next = step_from(p.x, raw);
    Covariance numeric = Covariance::Zero();
    for (int j = 0; j < sx::kCount; ++j) {
      const double e = f_step_for(j);
      numeric.col(j) = (state_difference(step_from(with_error(p.x, j, e), raw), next) -
                        state_difference(step_from(with_error(p.x, j, -e), raw), next)) / (2.0 * e);
    }
    // Compared as (Phi - I) / T, i.e. in units of F, rows of the dynamic states only.
    const Eigen::MatrixXd model = (phi - Covariance::Identity()).topRows<sx::kDynamicCount>() / kT;
    const Eigen::MatrixXd num = (numeric - Covariance::Identity()).topRows<sx::kDynamicCount>() / kT;
    expect_close_f(model, num, kT, kSystemMatrixNeglected, p.name + " F");
  }
}

}  // namespace
}  // namespace navfuse::filter
