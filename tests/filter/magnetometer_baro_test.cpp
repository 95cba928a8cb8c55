// Magnetometer heading and barometric height aiding on closed-form streams: the tilt-compensated
// heading against a hand-built field, alignment from the magnetometer at a known attitude,
// rejection of disturbed readings, the configuration switch, and the ISA pressure altitude
// against the standard's table.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geodesy/magnetic_declination.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "filter/measurements/baro_height.hpp"
#include "filter/measurements/magnetic_heading.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter {
namespace {

constexpr double kDeg = rot::kDegToRad;

// The earth's field in NED for a declination and inclination (gauss): horizontal part along
// magnetic north, vertical part down in the northern hemisphere.
Eigen::Vector3d earth_field_ned(double declination_rad, double inclination_rad, double strength_gauss) {
  const double h = strength_gauss * std::cos(inclination_rad);
  return {h * std::cos(declination_rad), h * std::sin(declination_rad), strength_gauss * std::sin(inclination_rad)};
}

Magnetometer reading(std::int64_t time_ns, const Eigen::Vector3d& rpy_rad, const Eigen::Vector3d& field_ned) {
  Magnetometer m;
  m.header.time_ns = time_ns;
  m.header.time_source = TimeSource::kGps;
  m.header.valid = Magnetometer::kValidField;
  m.frame = SensorFrame::kVehicle;
  m.field_gauss = rot::dcm_from_rpy(rpy_rad).transpose() * field_ned;
  return m;
}

TEST(MagneticHeading, TiltCompensatedHeadingOfAHandBuiltField) {
  // Steep field (inclination 65 deg): at 5/-3 deg of tilt an uncompensated heading is off by
  // degrees, the compensated one exactly right.
  const double d = 10.0 * kDeg;
  const Eigen::Vector3d b_n = earth_field_ned(d, 65.0 * kDeg, 0.5);
  for (double yaw_deg : {-170.0, -60.0, 0.0, 40.0, 135.0}) {
    const Eigen::Vector3d rpy(5.0 * kDeg, -3.0 * kDeg, yaw_deg * kDeg);
    const Eigen::Vector3d m_b = rot::dcm_from_rpy(rpy).transpose() * b_n;
    // Any heading in the quaternion: only its roll and pitch are used.
    const Eigen::Quaterniond q = rot::quat_from_rpy(Eigen::Vector3d(rpy.x(), rpy.y(), 1.234));
    EXPECT_NEAR(rot::wrap_pi(magnetic_heading_rad(q, m_b, d) - rpy.z()), 0.0, 1e-12) << yaw_deg;
    EXPECT_NEAR(horizontal_field(q, m_b), 0.5 * std::cos(65.0 * kDeg), 1e-12);
  }
}

TEST(MagneticHeading, ResidualIsZeroAtTheTrueAttitudeAndDeclination) {
  const double d = -7.0 * kDeg;
  const Eigen::Vector3d rpy(2.0 * kDeg, 4.0 * kDeg, 100.0 * kDeg);
  const Eigen::Vector3d m_b = rot::dcm_from_rpy(rpy).transpose() * earth_field_ned(d, 60.0 * kDeg, 0.45);
  NavState x;
  x.q_nb = rot::quat_from_rpy(rpy);
  const LocalEarth earth = LocalEarth::at(0.8, 0.0);
  const Observation obs = magnetic_heading_observation(StateView(x, earth, Eigen::Vector3d::Zero(), 0.0), m_b, d,
                                                       2.0 * kDeg);
  EXPECT_NEAR(obs.residual(0), 0.0, 1e-12);
  EXPECT_NEAR(obs.r(0, 0), std::pow(2.0 * kDeg, 2), 1e-15);
  // A heading error of 3 deg shows as a 3 deg residual.
  x.q_nb = rot::quat_from_rpy(Eigen::Vector3d(rpy.x(), rpy.y(), rpy.z() + 3.0 * kDeg));
  const Observation off = magnetic_heading_observation(StateView(x, earth, Eigen::Vector3d::Zero(), 0.0), m_b, d,
                                                       2.0 * kDeg);
  EXPECT_NEAR(off.residual(0), 3.0 * kDeg, 1e-9);
}

FilterOptions magnetometer_options(double declination_deg) {
  FilterOptions o;
  o.magnetometer.enabled = true;
  o.magnetometer.heading_std_rad = 2.0 * kDeg;
  o.magnetometer.declination_rad = declination_deg * kDeg;
  return o;
}

TEST(MagnetometerControl, AlignsHeadingWhileStandingAndTracksIt) {
  const Eigen::Vector3d rpy(1.0 * kDeg, -2.0 * kDeg, -120.0 * kDeg);
  const Eigen::Vector3d b_n = earth_field_ned(12.0 * kDeg, 67.0 * kDeg, 0.52);
  Engine e{magnetometer_options(12.0)};
  test::LineTrajectory traj({0.9, 0.2, 50.0}, Eigen::Vector3d::Zero(), rpy, 100.0);
  for (int k = 0; k < 3000; ++k) {
    e.process(traj.next());
    if (k % 10 == 0) e.process(reading(traj.truth().time_ns, rpy, b_n));
  }
  EXPECT_EQ(e.solution().mode, NavMode::kAhrs);
  EXPECT_NEAR(rot::wrap_pi(e.solution().rpy_rad.z() - rpy.z()), 0.0, 0.2 * kDeg);
  const KindStats& st = e.stats().of(MeasurementKind::kMagnetometer);
  EXPECT_GT(st.used, 250u);
  EXPECT_EQ(st.rejected_total(), st.rejected_for(RejectReason::kNotAligned));  // only before levelling
}

TEST(MagnetometerControl, DisturbedReadingsAreRejectedAndDoNotTurnTheHeading) {
  const Eigen::Vector3d rpy(0.0, 0.0, 30.0 * kDeg);
  const Eigen::Vector3d b_n = earth_field_ned(0.0, 60.0 * kDeg, 0.5);
  Engine e{magnetometer_options(0.0)};
  test::LineTrajectory traj({0.9, 0.2, 50.0}, Eigen::Vector3d::Zero(), rpy, 100.0);
  for (int k = 0; k < 2000; ++k) {
    e.process(traj.next());
    if (k % 10 != 0) continue;
    // From 10 s on a steel object next to the sensor: 3x the field, turned 90 deg.
    const Eigen::Vector3d disturbed = rot::dcm_from_rpy(Eigen::Vector3d(0.0, 0.0, 90.0 * kDeg)) * b_n * 3.0;
    e.process(reading(traj.truth().time_ns, rpy, k >= 1000 ? disturbed : b_n));
  }
  EXPECT_EQ(e.stats().of(MeasurementKind::kMagnetometer).rejected_for(RejectReason::kMagneticDisturbance), 100u);
  EXPECT_NEAR(rot::wrap_pi(e.solution().rpy_rad.z() - rpy.z()), 0.0, 0.2 * kDeg);
}

TEST(MagnetometerControl, OffUnlessConfiguredAndNeedsADeclination) {
  const Eigen::Vector3d rpy(0.0, 0.0, 30.0 * kDeg);
  const Eigen::Vector3d b_n = earth_field_ned(0.0, 60.0 * kDeg, 0.5);
  FilterOptions no_declination = magnetometer_options(0.0);
  no_declination.magnetometer.declination_rad.reset();
  Engine off{FilterOptions{}};
  Engine undeclared{no_declination};
  test::LineTrajectory traj({0.9, 0.2, 50.0}, Eigen::Vector3d::Zero(), rpy, 100.0);
  for (int k = 0; k < 500; ++k) {
    const ImuSample s = traj.next();
    off.process(s);
    undeclared.process(s);
    if (k % 10 != 0) continue;
    off.process(reading(traj.truth().time_ns, rpy, b_n));
    undeclared.process(reading(traj.truth().time_ns, rpy, b_n));
  }
  EXPECT_EQ(off.stats().of(MeasurementKind::kMagnetometer).ignored, 50u);
  EXPECT_EQ(off.solution().mode, NavMode::kVerticalGyro);
  // Without a position the model cannot say the declination: never a heading from a guess.
  const KindStats& st = undeclared.stats().of(MeasurementKind::kMagnetometer);
  EXPECT_GT(st.rejected_for(RejectReason::kNoDeclination), 0u);
  EXPECT_EQ(st.used, 0u);
  EXPECT_EQ(undeclared.solution().mode, NavMode::kVerticalGyro);
}

TEST(MagneticDeclination, GpsTimeAsDecimalYear) {
  // 2025-01-01T00:00:00 UTC is GPS week 2347, 3 days in (+18 leap seconds, ignored here).
  const std::int64_t gps_ns = (2347LL * 7 * 86400 + 3 * 86400) * 1'000'000'000LL;
  EXPECT_NEAR(geo::decimal_year_from_gps_ns(gps_ns), 2025.0, 0.005);
}

TEST(BaroHeight, IsaPressureAltitudeMatchesTheStandardTable) {
  // ICAO standard atmosphere (Doc 7488) table values: pressure at geopotential altitude.
  EXPECT_NEAR(pressure_altitude_m(101325.0), 0.0, 1e-9);
  EXPECT_NEAR(pressure_altitude_m(89874.6), 1000.0, 0.5);
  EXPECT_NEAR(pressure_altitude_m(79495.2), 2000.0, 0.5);
  EXPECT_NEAR(pressure_altitude_m(54019.9), 5000.0, 1.0);
  EXPECT_NEAR(pressure_altitude_m(107477.7), -500.0, 0.5);
}

// The static pressure at an ISA pressure altitude (the inverse of pressure_altitude_m).
double isa_pressure_pa(double altitude_m) {
  return 101325.0 * std::pow(1.0 - altitude_m * 0.0065 / 288.15, 1.0 / 0.190263);
}

// Height error after 40 s without position aiding, standing still with a 0.02 m/s^2 vertical
// accelerometer bias and no zero-velocity updates (the bias alone gives 0.5 a t^2 = 16 m).
double height_error_after_drift(bool with_baro) {
  FilterOptions o;
  o.zero_velocity_updates = false;
  o.baro.enabled = with_baro;
  o.baro.height_std_m = 0.5;
  const Eigen::Vector3d rpy(0.0, 0.0, 30.0 * kDeg);
  test::LineTrajectory traj({0.9, 0.2, 50.0}, Eigen::Vector3d::Zero(), rpy, 100.0);
  traj.accel_bias_mps2 = Eigen::Vector3d(0.0, 0.0, 0.02);
  Engine e{o};
  ExternalHeading heading;
  heading.header.valid = ExternalHeading::kValidHeading;
  heading.heading_rad = rpy.z();
  heading.std_rad = 0.5 * kDeg;
  ExternalPosition fix;
  fix.header.valid = ExternalPosition::kValidX | ExternalPosition::kValidY | ExternalPosition::kValidZ;
  fix.frame = PositionFrame::kLlh;
  fix.value = {0.9, 0.2, 50.0};
  fix.std_m = {0.1, 0.1, 0.1};
  Pressure p;
  p.header.valid = Pressure::kValidPressure;
  p.pressure_pa = isa_pressure_pa(50.0 - 12.0);  // any weather: only the changes count
  for (int k = 0; k < 4200; ++k) {
    e.process(traj.next());
    const std::int64_t t = traj.truth().time_ns;
    if (k == 150) {
      heading.header.time_ns = t;
      e.process(heading);
    }
    if (k == 160) {
      fix.header.time_ns = t;
      e.process(fix);
    }
    if (k > 160 && k % 10 == 0) {
      p.header.time_ns = t;
      e.process(p);
    }
  }
  return std::abs(e.solution().height_m - 50.0);
}

TEST(BaroControl, HoldsTheHeightTheAccelerometerBiasWouldDrift) {
  const double without = height_error_after_drift(false);
  const double with = height_error_after_drift(true);
  std::printf("height error after 40 s: %.2f m without the barometer, %.2f m with\n", without, with);
  EXPECT_GT(without, 5.0);
  EXPECT_LT(with, 0.5);
}

}  // namespace
}  // namespace navfuse::filter
