// IMU model: noise statistics against the IEEE 952 definitions, bias processes, scale factor,
// mounting rotation, saturation, and increments against closed forms.
#include "apps/sim/imu_model.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr double kDeg = rot::kDegToRad;
constexpr std::int64_t kStart = 1'400'000'000LL * 1'000'000'000LL;

// Sample standard deviation of one axis.
double std_of(const std::vector<Eigen::Vector3d>& v, int axis) {
  double mean = 0.0;
  for (const auto& x : v) mean += x[axis];
  mean /= static_cast<double>(v.size());
  double ss = 0.0;
  for (const auto& x : v) ss += (x[axis] - mean) * (x[axis] - mean);
  return std::sqrt(ss / static_cast<double>(v.size() - 1));
}

TEST(ImuErrorModel, AngleAndVelocityRandomWalkMatchTheirDefinition) {
  // ARW 0.1 deg/sqrt(h) = 0.1 * (pi/180) / 60 rad/sqrt(s); an increment over dt = 5 ms has std
  // ARW sqrt(dt), a rate sample ARW / sqrt(dt). 60000 samples: std estimate within ~0.3 % (1 sigma).
  ImuErrorSpec spec;
  spec.gyro_arw_deg_rthr = 0.1;
  spec.accel_vrw_mps_rthr = 0.03;
  const double dt = 0.005;
  const double arw = 0.1 * kDeg / 60.0, vrw = 0.03 / 60.0;
  for (bool increments : {true, false}) {
    ImuErrorModel model(spec, 7);
    std::vector<Eigen::Vector3d> g, a;
    for (int i = 0; i < 60000; ++i) {
      Eigen::Vector3d gyro = Eigen::Vector3d::Zero(), accel = Eigen::Vector3d::Zero();
      model.apply(increments, dt, gyro, accel);
      g.push_back(gyro);
      a.push_back(accel);
    }
    const double scale = increments ? std::sqrt(dt) : 1.0 / std::sqrt(dt);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(std_of(g, axis) / (arw * scale), 1.0, 0.015) << "increments=" << increments;
      EXPECT_NEAR(std_of(a, axis) / (vrw * scale), 1.0, 0.015) << "increments=" << increments;
    }
  }
}

TEST(ImuErrorModel, BiasInstabilityIsGaussMarkovWithTheGivenSigmaAndCorrelationTime) {
  // sigma 2 deg/h, tau 2 s, sampled at 100 Hz for 4000 s (2000 correlation times): variance
  // within ~5 %, lag-tau autocorrelation e^-1.
  ImuErrorSpec spec;
  spec.gyro_bias_instability_deg_hr = 2.0;
  spec.gyro_bias_corr_time_s = 2.0;
  const double sigma = 2.0 * kDeg / 3600.0, dt = 0.01;
  ImuErrorModel model(spec, 11);
  std::vector<double> b;
  for (int i = 0; i < 400000; ++i) {
    b.push_back(model.gyro_bias_rps().x());
    Eigen::Vector3d gyro = Eigen::Vector3d::Zero(), accel = Eigen::Vector3d::Zero();
    model.apply(false, dt, gyro, accel);
  }
  double var = 0.0, cov = 0.0;
  const std::size_t lag = 200;  // tau / dt
  for (std::size_t i = 0; i < b.size(); ++i) var += b[i] * b[i];
  for (std::size_t i = 0; i + lag < b.size(); ++i) cov += b[i] * b[i + lag];
  var /= static_cast<double>(b.size());
  cov /= static_cast<double>(b.size() - lag);
  EXPECT_NEAR(std::sqrt(var) / sigma, 1.0, 0.08);
  EXPECT_NEAR(cov / var, std::exp(-1.0), 0.06);
}

TEST(ImuErrorModel, TurnOnBiasAndScaleFactorAreConstantPerSeedWithTheGivenSpread) {
  ImuErrorSpec spec;
  spec.gyro_turn_on_bias_std_deg_hr = 20.0;
  spec.accel_turn_on_bias_std_mps2 = 5e-3 * 9.80665;
  spec.gyro_scale_factor_std_ppm = 500.0;
  std::vector<Eigen::Vector3d> gb, ab, sf;
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    ImuErrorModel m(spec, seed);
    gb.push_back(m.gyro_bias_rps());
    ab.push_back(m.accel_bias_mps2());
    sf.push_back(m.gyro_scale_factor());
    // Constant within a run: the output of a zero input is the bias (rates), unchanged later.
    if (seed == 1) {
      for (int i = 0; i < 100; ++i) {
        Eigen::Vector3d g = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
        m.apply(false, 0.005, g, a);
        EXPECT_EQ(g, gb.back());
        EXPECT_EQ(a, ab.back());
      }
      // Scale factor: a 1 rad/s input reads 1 + sf + bias.
      Eigen::Vector3d g = Eigen::Vector3d::Ones(), a = Eigen::Vector3d::Zero();
      m.apply(false, 0.005, g, a);
      EXPECT_LT((g - (Eigen::Vector3d::Ones() + sf.back() + gb.back())).norm(), 1e-15);
    }
  }
  // 9000 draws: std within ~1.5 % (2 sigma).
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(std_of(gb, axis) / (20.0 * kDeg / 3600.0), 1.0, 0.05);
    EXPECT_NEAR(std_of(ab, axis) / (5e-3 * 9.80665), 1.0, 0.05);
    EXPECT_NEAR(std_of(sf, axis) / 500e-6, 1.0, 0.05);
  }
}

TEST(ImuErrorModel, SaturationClipsAndFlags) {
  ImuErrorSpec spec;
  spec.gyro_range_dps = 100.0;
  spec.accel_range_mps2 = 20.0;
  ImuErrorModel model(spec, 1);
  Eigen::Vector3d g(3.0, -0.5, -2.0), a(0.0, 25.0, -9.8);  // 3 rad/s = 172 deg/s
  const std::uint8_t bits = model.apply(false, 0.005, g, a);
  EXPECT_EQ(bits, ImuSample::kSatGyroX | ImuSample::kSatGyroZ | ImuSample::kSatAccelY);
  EXPECT_DOUBLE_EQ(g.x(), 100.0 * kDeg);
  EXPECT_DOUBLE_EQ(g.z(), -100.0 * kDeg);
  EXPECT_DOUBLE_EQ(g.y(), -0.5);
  EXPECT_DOUBLE_EQ(a.y(), 20.0);
}

// Truth nodes of one IMU interval ending at `t_end_s`.
std::vector<TruthSample> interval(const Trajectory& traj, double t_end_s, const ImuModel& imu) {
  const int n = imu.spec().substeps;
  const std::int64_t sub = imu.period_ns() / n;
  std::vector<TruthSample> nodes(static_cast<std::size_t>(n) + 1);
  nodes[0] = traj.initial();
  const std::int64_t first = static_cast<std::int64_t>(std::llround(t_end_s * 1e9)) - imu.period_ns();
  for (std::int64_t done = 0; done < first;) {
    const std::int64_t step = std::min<std::int64_t>(first - done, 5'000'000);
    nodes[0] = traj.propagate(nodes[0], step);
    done += step;
  }
  for (int j = 1; j <= n; ++j) nodes[static_cast<std::size_t>(j)] = traj.propagate(nodes[static_cast<std::size_t>(j) - 1], sub);
  return nodes;
}

TEST(ImuModel, PerfectStaticIncrementsMatchTheClosedForm) {
  // At rest the body rate omega and specific force f are constant in the body frame, so
  // delta_theta = omega dt, and delta_v = integral of exp([omega x] t) f dt, resolved in the start
  // frame, = f dt + (omega x f) dt^2 / 2 + O(omega^2 dt^3) (the ~9e-9 m/s rotation term is real).
  TrajectorySpec spec;
  spec.start = {40.0 * kDeg, 0.0, 0.0};
  spec.segments = {MotionSegment::stationary(10.0)};
  const Trajectory traj(spec, kStart);
  ImuSpec imu_spec;
  ImuModel imu(imu_spec, 1);
  const auto nodes = interval(traj, 5.0, imu);
  ImuSample s;
  imu.make_sample(nodes.data(), s);
  EXPECT_EQ(s.header.time_ns, kStart + 5'000'000'000LL);
  EXPECT_EQ(s.header.time_source, TimeSource::kGps);
  EXPECT_EQ(s.quantity, ImuQuantity::kIncrements);
  EXPECT_DOUBLE_EQ(s.dt_s, 0.005);
  EXPECT_LT((s.gyro - nodes.back().omega_ib_b_rps * 0.005).norm(), 1e-16);
  const Eigen::Vector3d w = nodes.back().omega_ib_b_rps, f = nodes.back().f_ib_b_mps2;
  EXPECT_LT((s.accel - (f * 0.005 + w.cross(f) * 0.005 * 0.005 / 2)).norm(), 1e-14);
  EXPECT_GT((w.cross(f) * 0.005 * 0.005 / 2).norm(), 5e-9);
}

TEST(ImuModel, CompensatedIncrementsAgreeWithRawIntegralsToSecondOrder) {
  // In a turn, the attitude-change rotation vector and the integral of omega differ only by the
  // coning term (~ |omega|^2 dt^2 / 12, here < 1e-8 rad); delta-v differs by the rotation of the
  // frame (~ |omega| |f| dt^2 / 2, here ~1e-5 m/s) and both are close to rate * dt.
  TrajectorySpec spec;
  spec.start = {40.0 * kDeg, 0.0, 0.0};
  spec.segments = {MotionSegment::accelerate(15.0, 5.0), MotionSegment::turn(90.0 * kDeg, 6.0)};
  const Trajectory traj(spec, kStart);
  ImuSpec comp_spec, raw_spec;
  raw_spec.convention = ImuIncrements::kRawIntegrals;
  ImuModel comp(comp_spec, 1), raw(raw_spec, 1);
  const auto nodes = interval(traj, 8.0, comp);  // mid-turn, yaw rate ~0.52 rad/s
  ImuSample a, b;
  comp.make_sample(nodes.data(), a);
  raw.make_sample(nodes.data(), b);
  EXPECT_LT((a.gyro - b.gyro).norm(), 1e-7);
  EXPECT_GT((a.accel - b.accel).norm(), 1e-7);  // sculling/rotation really is in there
  EXPECT_LT((a.accel - b.accel).norm(), 1e-4);
  const Eigen::Vector3d mid_rate = traj.kinematics(7.9975).rpy_rate_rps;
  EXPECT_NEAR(b.gyro.z() / 0.005, mid_rate.z(), 2e-4);
}

TEST(ImuModel, MountingRotatesVehicleQuantitiesIntoTheSensorFrame) {
  // Sensor yawed +90 deg relative to the vehicle: C_vs = Rz(90), x_s = C_vs^T x_v =
  // (x_v.y, -x_v.x, x_v.z) (by hand). Rates mode, during an acceleration (f_x ~ 3 m/s^2).
  TrajectorySpec spec;
  spec.start = {40.0 * kDeg, 0.0, 0.0};
  spec.segments = {MotionSegment::accelerate(15.0, 10.0)};
  const Trajectory traj(spec, kStart);
  ImuSpec mounted;
  mounted.quantity = ImuQuantity::kRates;
  mounted.mounting_rpy_deg = {0.0, 0.0, 90.0};
  ImuModel imu(mounted, 1);
  const auto nodes = interval(traj, 5.0, imu);
  ImuSample s;
  imu.make_sample(nodes.data(), s);
  const Eigen::Vector3d f = nodes.back().f_ib_b_mps2, w = nodes.back().omega_ib_b_rps;
  EXPECT_GT(f.x(), 2.5);
  EXPECT_NEAR(s.accel.x(), f.y(), 1e-12);
  EXPECT_NEAR(s.accel.y(), -f.x(), 1e-12);
  EXPECT_NEAR(s.accel.z(), f.z(), 1e-12);
  EXPECT_NEAR(s.gyro.x(), w.y(), 1e-18);
  EXPECT_NEAR(s.gyro.y(), -w.x(), 1e-18);
  EXPECT_EQ(s.frame, SensorFrame::kSensor);
  // Asking for the vehicle frame undoes the mounting.
  mounted.frame = SensorFrame::kVehicle;
  ImuModel vehicle(mounted, 1);
  vehicle.make_sample(nodes.data(), s);
  EXPECT_LT((s.accel - f).norm(), 1e-12);
}

TEST(ImuModel, RejectsPeriodsThatAreNotWholeNanoseconds) {
  ImuSpec spec;
  spec.rate_hz = 300.0;  // 3333333.33 ns
  EXPECT_THROW(ImuModel(spec, 1), std::invalid_argument);
  spec.rate_hz = 200.0;
  spec.substeps = 3;
  EXPECT_THROW(ImuModel(spec, 1), std::invalid_argument);
}

}  // namespace
}  // namespace navfuse::sim
