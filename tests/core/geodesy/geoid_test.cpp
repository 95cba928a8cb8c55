// EGM96 undulation from Debian's proj-data grid against the sample output printed in NGA's
// EGM96 interpolation program documentation (INTPT.DAT / OUTINTPT.DAT of the F477 package).
// NGA interpolates the 15' grid with a bicubic spline; ours is bilinear, so agreement is to
// a few decimetres, not millimetres.
#include "core/geodesy/geoid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace navfuse::geo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(Geoid, MissingGridIsInvalidNotAGuess) {
  std::string error;
  EXPECT_FALSE(GeoidGrid::load("/nonexistent/egm96_15.gtx", &error).has_value());
  EXPECT_NE(error.find("/nonexistent/egm96_15.gtx"), std::string::npos);
}

TEST(Geoid, Egm96PublishedValues) {
  if (!std::filesystem::exists(GeoidGrid::kDefaultPath)) GTEST_SKIP() << "proj-data not installed";
  ASSERT_NE(GeoidGrid::egm96(), nullptr);
  struct Case { double lat_deg, lon_deg, n_m; };
  for (const Case& c : {Case{38.6281550, 269.7791550, -31.628}, Case{-14.6212170, 305.0211140, -2.969},
                        Case{46.8743190, 102.4487290, -43.575}, Case{-23.6174460, 133.8747120, 15.871},
                        Case{38.6254730, 359.9995000, 50.066}, Case{-0.4667440, 0.0023000, 17.329}}) {
    const auto n = egm96_undulation_m(c.lat_deg * kDeg, c.lon_deg * kDeg);
    ASSERT_TRUE(n.has_value()) << c.lat_deg;
    EXPECT_NEAR(*n, c.n_m, 0.3) << c.lat_deg << "," << c.lon_deg;
  }
}

TEST(Geoid, LongitudeWrapsAndPolesAreCovered) {
  if (!GeoidGrid::egm96()) GTEST_SKIP() << "proj-data not installed";
  const auto a = egm96_undulation_m(10 * kDeg, -170 * kDeg);
  const auto b = egm96_undulation_m(10 * kDeg, 190 * kDeg);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(*a, *b, 1e-9);
  EXPECT_TRUE(egm96_undulation_m(90 * kDeg, 0).has_value());
  EXPECT_TRUE(egm96_undulation_m(-90 * kDeg, 0).has_value());
  EXPECT_TRUE(egm96_undulation_m(0, 179.99 * kDeg).has_value());  // between the last and first column
  EXPECT_FALSE(egm96_undulation_m(std::nan(""), 0).has_value());
}

}  // namespace
}  // namespace navfuse::geo
