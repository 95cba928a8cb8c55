// Geodesy against published WGS-84 values (NIMA TR8350.2 Tables 3.1, 3.3, 3.4) and hand-computed
// closed forms, plus round trips to 1e-9 rad / 1e-4 m.
#include "core/geodesy/geodesy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geodesy/gravity.hpp"
#include "core/geodesy/wgs84.hpp"

namespace navfuse::geo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(Wgs84, DerivedConstantsMatchTr8350) {
  // TR8350.2 Table 3.3: b = 6356752.3142 m, e^2 = 6.69437999014e-3.
  EXPECT_NEAR(wgs84::kSemiMinorAxis_m, 6356752.3142, 1e-4);
  EXPECT_NEAR(wgs84::kEccentricitySq, 6.69437999014e-3, 1e-14);
}

TEST(Geodesy, KnownEcefPoints) {
  const auto eq = ecef_from_llh({0, 0, 0});
  EXPECT_NEAR(eq.x(), 6378137.0, 1e-6);
  EXPECT_NEAR(eq.y(), 0.0, 1e-6);
  EXPECT_NEAR(eq.z(), 0.0, 1e-6);
  const auto pole = ecef_from_llh({90 * kDeg, 0, 100.0});
  EXPECT_NEAR(pole.z(), 6356752.3142 + 100.0, 1e-3);
  EXPECT_NEAR(std::hypot(pole.x(), pole.y()), 0.0, 1e-6);
  // Hand computation at 45N 45E, h = 1000 m: N = a / sqrt(1 - e^2/2),
  // x = y = (N + h) cos(45) cos(45) = (N + h)/2, z = (N (1 - e^2) + h) sin(45).
  const double n = wgs84::kSemiMajorAxis_m / std::sqrt(1.0 - wgs84::kEccentricitySq / 2.0);
  const auto p = ecef_from_llh({45 * kDeg, 45 * kDeg, 1000.0});
  EXPECT_NEAR(p.x(), (n + 1000.0) / 2.0, 1e-6);
  EXPECT_NEAR(p.y(), (n + 1000.0) / 2.0, 1e-6);
  EXPECT_NEAR(p.z(), (n * (1 - wgs84::kEccentricitySq) + 1000.0) * std::sqrt(0.5), 1e-6);
}

TEST(Geodesy, RoundTripEverywhere) {
  for (double lat = -89.5; lat <= 89.5; lat += 7.3) {
    for (double lon = -179.0; lon <= 180.0; lon += 23.7) {
      for (double h : {-400.0, 0.0, 1234.5, 35786e3}) {
        const Llh in{lat * kDeg, lon * kDeg, h};
        const Llh out = llh_from_ecef(ecef_from_llh(in));
        EXPECT_NEAR(out.lat_rad, in.lat_rad, 1e-9);
        EXPECT_NEAR(out.lon_rad, in.lon_rad, 1e-9);
        EXPECT_NEAR(out.height_m, in.height_m, 1e-4);
      }
    }
  }
}

TEST(Geodesy, NedFrameAxes) {
  // At 0N 0E: north = +z_ecef, east = +y_ecef, down = -x_ecef.
  const Eigen::Matrix3d c = rot_ecef_from_ned(0, 0);
  EXPECT_TRUE(c.col(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(c.col(1).isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(c.col(2).isApprox(Eigen::Vector3d(-1, 0, 0)));
  EXPECT_NEAR((c.transpose() * c - Eigen::Matrix3d::Identity()).norm(), 0, 1e-15);
}

TEST(Geodesy, NedOffsetRoundTrip) {
  const Llh ref{37.4 * kDeg, -122.1 * kDeg, 30.0};
  const Eigen::Vector3d d(1234.5, -678.9, 12.3);
  const Llh moved = llh_offset(ref, d);
  EXPECT_NEAR((ned_offset_m(ref, moved) - d).norm(), 0.0, 1e-6);
  // 1 km north moves latitude by 1000 / (R_N + h) to first order.
  const Llh north = llh_offset(ref, {1000, 0, 0});
  EXPECT_NEAR(north.lat_rad - ref.lat_rad, 1000.0 / (radii_of_curvature(ref.lat_rad).meridian_m + 30.0), 1e-9);
}

TEST(Geodesy, RadiiOfCurvature) {
  // Equator: R_N = a (1 - e^2), R_E = a. Pole: both a / sqrt(1 - e^2) (Groves eqs. 2.105-2.106).
  const Radii eq = radii_of_curvature(0);
  EXPECT_NEAR(eq.meridian_m, 6378137.0 * (1 - wgs84::kEccentricitySq), 1e-6);
  EXPECT_NEAR(eq.meridian_m, 6335439.327, 1e-3);
  EXPECT_NEAR(eq.prime_vertical_m, 6378137.0, 1e-9);
  const Radii pole = radii_of_curvature(90 * kDeg);
  EXPECT_NEAR(pole.meridian_m, 6399593.626, 1e-3);
  EXPECT_NEAR(pole.prime_vertical_m, 6399593.626, 1e-3);
}

TEST(Geodesy, EarthAndTransportRates) {
  const Eigen::Vector3d w0 = earth_rate_ned(0);
  EXPECT_NEAR(w0.x(), 7.292115e-5, 1e-15);
  EXPECT_NEAR(w0.z(), 0.0, 1e-15);
  const Eigen::Vector3d w90 = earth_rate_ned(90 * kDeg);
  EXPECT_NEAR(w90.z(), -7.292115e-5, 1e-15);
  // 10 m/s east at the equator on the ellipsoid: rate about north = 10 / a.
  const Eigen::Vector3d t = transport_rate_ned(0, 0, {0, 10, 0});
  EXPECT_NEAR(t.x(), 10.0 / 6378137.0, 1e-15);
  EXPECT_NEAR(t.y(), 0.0, 1e-15);
  // 10 m/s north: rate about east = -10 / R_N.
  EXPECT_NEAR(transport_rate_ned(0, 0, {10, 0, 0}).y(), -10.0 / 6335439.327, 1e-12);
}

TEST(Gravity, NormalGravityEquatorAndPole) {
  // TR8350.2 Table 3.4: gamma_e = 9.7803253359, gamma_p = 9.8321849378 m/s^2.
  EXPECT_NEAR(normal_gravity_ned(0, 0).z(), 9.7803253359, 1e-8);
  EXPECT_NEAR(normal_gravity_ned(90 * kDeg, 0).z(), 9.8321849378, 1e-8);
  EXPECT_NEAR(normal_gravity_surface_mps2(0), 9.7803253359, 1e-10);
  EXPECT_NEAR(normal_gravity_surface_mps2(90 * kDeg), 9.8321849378, 1e-10);
  for (double lat = -80; lat <= 80; lat += 10) {
    EXPECT_NEAR(normal_gravity_ned(lat * kDeg, 0).z(), normal_gravity_surface_mps2(lat * kDeg), 1e-8) << lat;
    EXPECT_NEAR(normal_gravity_ned(lat * kDeg, 0).x(), 0.0, 1e-9);
  }
  // Free-air gradient ~ -3.086e-6 s^-2 (TR8350.2 eq. 4-3, first-order term) at 1 km.
  const double dg = normal_gravity_ned(45 * kDeg, 1000).z() - normal_gravity_ned(45 * kDeg, 0).z();
  EXPECT_NEAR(dg, -3.086e-3, 2e-5);
}

}  // namespace
}  // namespace navfuse::geo
