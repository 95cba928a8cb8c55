// Vibration model: the broadband part has the stated RMS at the output rate (growing with speed),
// the engine tone the stated amplitude, integrated exactly in increments; own random stream.
#include "apps/sim/vibration_model.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "apps/sim/imu_model.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::sim {
namespace {

constexpr double kDt = 0.005;  // 200 Hz

struct Rms3 {
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  int n = 0;
  void add(const Eigen::Vector3d& v) { sum_sq += v.cwiseAbs2(); ++n; }
  Eigen::Vector3d value() const { return (sum_sq / n).cwiseSqrt(); }
};

TEST(Vibration, BroadbandRmsAtTheOutputRateGrowsWithSpeed) {
  VibrationSpec spec;
  spec.accel_rms_idle_mps2 = 0.1;
  spec.accel_rms_per_mps = 0.01;
  spec.gyro_rms_idle_dps = 0.1;
  spec.gyro_rms_per_mps = 0.02;
  for (const double speed : {0.0, 20.0}) {
    VibrationModel model(spec, 7);
    Rms3 accel, gyro;
    for (int i = 0; i < 40000; ++i) {
      Eigen::Vector3d g = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
      model.apply(true, kDt, speed, g, a);
      accel.add(a / kDt);  // increment over dt -> mean over the interval
      gyro.add(g / kDt);
    }
    // 40000 samples: the RMS is within ~0.35 % (1 sigma) of its true value.
    const double accel_expected = 0.1 + 0.01 * speed;
    const double gyro_expected = (0.1 + 0.02 * speed) * rot::kDegToRad;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(accel.value()[axis] / accel_expected, 1.0, 0.015) << speed;
      EXPECT_NEAR(gyro.value()[axis] / gyro_expected, 1.0, 0.015) << speed;
    }
  }
}

TEST(Vibration, EngineToneIsSampledInRatesAndIntegratedExactlyInIncrements) {
  VibrationSpec spec;
  spec.engine_idle_hz = 26.7;
  spec.engine_hz_per_mps = 0.0;
  spec.engine_accel_amplitude_mps2 = 0.5;
  spec.engine_gyro_amplitude_dps = 0.2;
  // Rates: a sinusoid of amplitude A has RMS A / sqrt(2).
  VibrationModel rates(spec, 3);
  Rms3 accel;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector3d g = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
    rates.apply(false, kDt, 0.0, g, a);
    accel.add(a);
  }
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(accel.value()[axis], 0.5 / std::sqrt(2.0), 0.01);

  // Increments: the running sum is the velocity of the oscillation, bounded by 2 A / omega
  // (closed form of the integral of A sin), so the tone does not accumulate.
  VibrationModel increments(spec, 3);
  const double omega = 2.0 * rot::kPi * 26.7;
  Eigen::Vector3d sum_v = Eigen::Vector3d::Zero(), sum_theta = Eigen::Vector3d::Zero();
  double max_v = 0.0;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector3d g = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
    increments.apply(true, kDt, 0.0, g, a);
    sum_v += a;
    sum_theta += g;
    max_v = std::max(max_v, sum_v.cwiseAbs().maxCoeff());
  }
  EXPECT_LE(max_v, 2.0 * 0.5 / omega + 1e-12);
  EXPECT_GT(max_v, 0.5 / omega);  // it does oscillate
  EXPECT_LE(sum_theta.cwiseAbs().maxCoeff(), 2.0 * 0.2 * rot::kDegToRad / omega + 1e-12);
}

TEST(Vibration, OffByDefaultAndOnItsOwnRandomStream) {
  // The IMU's other errors are the same with and without vibration (same seed).
  ImuSpec clean;
  clean.errors = imu_error_spec(ImuGrade::kIndustrial);
  ImuSpec shaken = clean;
  shaken.vibration = car_vibration();
  EXPECT_FALSE(clean.vibration.enabled());
  EXPECT_TRUE(shaken.vibration.enabled());
  const ImuModel a(clean, 11), b(shaken, 11);
  EXPECT_EQ(a.errors().gyro_bias_rps(), b.errors().gyro_bias_rps());
  EXPECT_EQ(a.errors().accel_bias_mps2(), b.errors().accel_bias_mps2());
  EXPECT_EQ(a.errors().gyro_scale_factor(), b.errors().gyro_scale_factor());
}

TEST(Vibration, CarLevelsAreTensOfTimesTheIndustrialDataSheet) {
  // car_vibration() against the industrial grade at 200 Hz: VRW 0.03 m/s/sqrt(h) is a per-sample
  // std of 0.03 / 60 / sqrt(0.005) = 0.0071 m/s^2; ARW 0.1 deg/sqrt(h) is 0.0236 deg/s.
  const VibrationSpec v = car_vibration();
  const ImuErrorSpec e = imu_error_spec(ImuGrade::kIndustrial);
  const double accel_sheet = e.accel_vrw_mps_rthr / 60.0 / std::sqrt(kDt);
  const double gyro_sheet = e.gyro_arw_deg_rthr / 60.0 / std::sqrt(kDt);
  EXPECT_NEAR(v.accel_rms_idle_mps2 / accel_sheet, 14.1, 0.1);
  EXPECT_NEAR((v.accel_rms_idle_mps2 + 20.0 * v.accel_rms_per_mps) / accel_sheet, 42.4, 0.1);
  EXPECT_NEAR((v.gyro_rms_idle_dps + 20.0 * v.gyro_rms_per_mps) / gyro_sheet, 21.2, 0.1);
}

}  // namespace
}  // namespace navfuse::sim
