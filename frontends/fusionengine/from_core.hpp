// Core measurements -> FusionEngine message structs (the encoding direction).
//
// Frames: core is NED / FRD with q_nb vehicle->NED (DESIGN.md); FusionEngine is FLU body with
// ENU-referenced intrinsic 3-2-1 yaw/pitch/roll, heading = 90 deg - yaw (spec §2.7 L635-653,
// digest §9). Units are converted here and nowhere else.
//
// Time: navfuse's P1 time base is GPS time (its clock is GNSS-disciplined), so P1 Time fields
// carry the measurement's GPS time; GPS Time fields are written only for TimeSource::kGps and
// are invalid (0xFFFFFFFF) otherwise, when P1 time carries the measurement's own clock.
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"
#include "frontends/fusionengine/messages_ros.hpp"
#include "frontends/fusionengine/messages_sensor.hpp"
#include "frontends/fusionengine/messages_solution.hpp"

namespace navfuse::frontends::fusionengine {

Timestamp p1_time_of(const MeasurementHeader& h);
Timestamp gps_time_of(const MeasurementHeader& h);
// MeasurementDetails of a sensor message: GPS time source for kGps headers, P1 otherwise.
MeasurementDetails details_of(const MeasurementHeader& h, SensorDataSource source);

// Best FusionEngine SolutionType for a navfuse mode and aiding fix (see to_core.hpp for the
// inverse). Modes without a position (invalid ... AHRS) are Invalid; dead reckoning is
// Integrate; navigation takes the fix's type, with AutonomousGPS for fixes the enum lacks.
SolutionType solution_type_of(NavMode mode, GnssFixType fix);

// Pose 10000. The undulation comes from the solution when valid, else from the EGM96 grid, else
// the spec's invalid value -32768 (L1736). Body velocity is NaN without a valid attitude
// (L1752-1754); protection levels are NaN (navfuse computes none).
PoseMessage pose_from(const NavSolution& s);
// PoseAux 10003: body-frame position std, diagonal ENU covariance, body->ENU quaternion
// (x, y, z, w) and ENU velocity.
PoseAuxMessage pose_aux_from(const NavSolution& s);
// GNSSInfo 10001 for a solution with GNSS fused: GPS time, leap second from the core table;
// counts and DOPs the caller knows are passed in (0 satellites / NaN DOPs when unknown).
GnssInfoMessage gnss_info_from(const NavSolution& s, std::uint8_t num_svs = 0, float hdop = kNanF,
                               float vdop = kNanF);

// IMUOutput 11000 (vehicle-frame samples, rates; increments are divided by dt_s).
// Returns false for increments without a dt.
bool imu_output_from(const ImuSample& imu, ImuOutputMessage& out);
// IMUInput 11004 / RawIMUOutput 11002 layout (sensor frame, scaled integers).
bool scaled_imu_from(const ImuSample& imu, ScaledImuLayout& out);

// GNSSAttitudeOutput 11005 from a dual-antenna heading: yaw = 90 deg - heading, pitch sign
// flipped (FusionEngine pitch is positive nose down, L643).
GnssAttitudeOutputMessage gnss_attitude_from(const GnssHeading& h);

WheelSpeedLayout wheel_speed_from(const WheelSpeeds& w);
VehicleSpeedLayout vehicle_speed_from(const VehicleSpeed& v);
WheelTickLayout wheel_ticks_from(const WheelTicks& t);
VehicleTickLayout vehicle_ticks_from(const WheelTicks& t);
WheelSpeedOutputMessage wheel_speed_output_from(const WheelSpeeds& w);
VehicleSpeedOutputMessage vehicle_speed_output_from(const VehicleSpeed& v);

// ROSGPSFix 12010 carrying a GNSS position (velocity fields NaN) or a GNSS velocity (position
// fields NaN). FusionEngine has no GNSS-only fix message; this is the one that carries a
// WGS-84 fix with covariance, so navfuse uses it to put GNSS fixes into FusionEngine logs.
// Below this speed the track angle is undefined and its error is written as NaN (both
// directions then assume an isotropic horizontal velocity covariance).
inline constexpr double kMinTrackSpeedMps = 1e-3;
RosGpsFixMessage gps_fix_from(const GnssPosition& p);
RosGpsFixMessage gps_fix_from(const GnssVelocity& v);

}  // namespace navfuse::frontends::fusionengine
