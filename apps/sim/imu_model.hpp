// A simulated IMU: true increments (or rates) along the truth trajectory, rotated into the sensor
// frame by the mounting and corrupted by ImuErrorModel.
//
// Increments follow the convention of core ImuSample (kIncrements: "coning/sculling done"), i.e.
// what a device that integrates internally at a high rate reports:
//   delta_theta = rotation vector of C_b(k-1)->b(k) relative to inertial space, computed exactly as
//                 C_bn(k-1) C_ne(k-1) R_z(omega_ie dt) C_en(k) C_nb(k): the body attitude change
//                 w.r.t. the inertial frame, over which the earth turned by omega_ie dt;
//   delta_v     = integral over the interval of C_b(k-1)b(t) f_ib_b(t) dt, by composite Simpson
//                 over `substeps` truth nodes: specific force resolved in the body frame at the
//                 start of the interval, which includes the rotation/sculling terms (Groves §5.5).
// The alternative kRawIntegral (plain integrals of omega and f, as a sensor without internal
// compensation outputs) is available to exercise a filter's own coning/sculling.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "apps/sim/imu_error_model.hpp"
#include "apps/sim/trajectory.hpp"
#include "apps/sim/vibration_model.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::sim {

struct ImuSpec {
  double rate_hz = 200.0;                          // output rate; 1e9 / rate must be whole ns
  ImuQuantity quantity = ImuQuantity::kIncrements;  // increments over 1/rate, or rates at the stamp
  // kCompensated: attitude-change rotation vector and start-frame delta-v (a VN-300's);
  // kRawIntegrals: integrals of omega_ib_s dt and f_ib_s dt in the moving sensor frame (a MIP
  // device's). `navfuse sim` sets the one of the format it writes (FrontendInfo::imu_increments).
  ImuIncrements convention = ImuIncrements::kCompensated;
  SensorFrame frame = SensorFrame::kSensor;  // kVehicle: output rotated back by the mounting
  Eigen::Vector3d mounting_rpy_deg = Eigen::Vector3d::Zero();  // sensor -> vehicle, 3-2-1 (DESIGN.md)
  ImuErrorSpec errors{};
  int substeps = 4;  // truth nodes per IMU interval for the delta-v quadrature (even, >= 2)
  VibrationSpec vibration{};  // engine and road vibration (off by default)
  // The IMU clock's offset from GPS time: samples are stamped this much before the true time of
  // their motion, so config imu.time_offset_s = time_offset_s puts them back (calibration tests).
  double time_offset_s = 0.0;
};

class ImuModel {
 public:
  ImuModel(const ImuSpec& spec, std::uint64_t seed);

  const ImuSpec& spec() const { return spec_; }
  std::int64_t period_ns() const { return period_ns_; }
  // C_vs: rotates sensor-frame vectors into the vehicle frame.
  const Eigen::Matrix3d& c_vehicle_sensor() const { return c_vs_; }

  // Makes the sample stamped at nodes[n] (n = substeps) from the truth at the interval's
  // `substeps + 1` equally spaced nodes nodes[0] .. nodes[n]. Rates use nodes[n] only.
  void make_sample(const TruthSample* nodes, ImuSample& out);

  // Current true biases rotated into the vehicle frame.
  Eigen::Vector3d gyro_bias_vehicle_rps() const { return c_vs_ * errors_.gyro_bias_rps(); }
  Eigen::Vector3d accel_bias_vehicle_mps2() const { return c_vs_ * errors_.accel_bias_mps2(); }
  const ImuErrorModel& errors() const { return errors_; }
  // The stamp of the sample whose motion ends at true time `true_time_ns` (ImuSpec::time_offset_s).
  std::int64_t stamp_ns(std::int64_t true_time_ns) const { return true_time_ns - time_offset_ns_; }

 private:
  ImuSpec spec_;
  std::int64_t period_ns_ = 0;
  std::int64_t time_offset_ns_ = 0;
  Eigen::Matrix3d c_vs_ = Eigen::Matrix3d::Identity();
  ImuErrorModel errors_;
  VibrationModel vibration_;
};

// Exact attitude increment of the body w.r.t. inertial space between two truth samples (see the
// file comment), as a rotation vector in the body frame at `a`.
Eigen::Vector3d inertial_delta_theta(const TruthSample& a, const TruthSample& b);

}  // namespace navfuse::sim
