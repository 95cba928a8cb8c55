// EGM96 undulation from Debian's proj-data grid against the sample output printed in NGA's
// EGM96 interpolation program documentation (INTPT.DAT / OUTINTPT.DAT of the F477 package).
// NGA interpolates the 15' grid with a bicubic spline; ours is bilinear, so agreement is to
// a few decimetres, not millimetres.
#include "core/geodesy/geoid.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

namespace navfuse::geo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(Geoid, MissingGridIsInvalidNotAGuess) {
  std::string error;
  EXPECT_FALSE(GeoidGrid::load("/nonexistent/egm96_15.gtx", &error).has_value());
  EXPECT_NE(error.find("/nonexistent/egm96_15.gtx"), std::string::npos);
}

// A GTX file as the format describes it (big-endian header and nodes), written by the test.
void write_gtx(const std::filesystem::path& path, double lat0, double lon0, double dlat, double dlon, std::int32_t rows,
               std::int32_t cols, const std::vector<float>& nodes, std::size_t cut_bytes = 0) {
  std::vector<char> bytes;
  auto put = [&](auto v) {
    auto u = std::bit_cast<std::conditional_t<sizeof(v) == 8, std::uint64_t, std::uint32_t>>(v);
    for (int i = sizeof(v) - 1; i >= 0; --i) bytes.push_back(static_cast<char>((u >> (8 * i)) & 0xFF));
  };
  for (double d : {lat0, lon0, dlat, dlon}) put(d);
  put(rows);
  put(cols);
  for (float f : nodes) put(f);
  bytes.resize(bytes.size() - cut_bytes);
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

TEST(Geoid, SmallGridInterpolatesItsNodes) {
  const auto path = std::filesystem::temp_directory_path() / "geoid_test_small_grid.gtx";
  // 3 rows (lat 10, 11, 12 deg) x 4 columns (lon 20 .. 23 deg), south row first.
  write_gtx(path, 10, 20, 1, 1, 3, 4, {1.0f, 2.0f, 4.0f, 0.0f, 3.0f, 5.0f, 6.0f, 0.0f, 7.0f, 8.0f, 9.0f, -88.8888f});
  const auto g = GeoidGrid::load(path.string());
  std::filesystem::remove(path);  // the grid keeps what it loaded
  ASSERT_TRUE(g.has_value());
  // Bilinear by hand at (10.25, 20.5): south edge 1.5, north edge 4, 0.25 of the way north.
  const auto between = g->undulation_m(10.25 * kDeg, 20.5 * kDeg);
  const auto node = g->undulation_m(11 * kDeg, 21 * kDeg);
  ASSERT_TRUE(between && node);
  EXPECT_NEAR(*between, 1.5 + 0.25 * (4.0 - 1.5), 1e-9);
  EXPECT_NEAR(*node, 5.0, 1e-9);
  EXPECT_FALSE(g->undulation_m(11.5 * kDeg, 22.5 * kDeg).has_value());  // next to the no-data node
  EXPECT_FALSE(g->undulation_m(9.9 * kDeg, 20.5 * kDeg).has_value());   // south of the grid
}

TEST(Geoid, MalformedGridsAreRefusedWithTheReason) {
  const auto path = std::filesystem::temp_directory_path() / "geoid_test_malformed_grid.gtx";
  std::string error;
  write_gtx(path, 10, 20, 1, 1, 2, 3, {1, 2, 3, 4, 5, 6}, /*cut_bytes=*/1);
  EXPECT_FALSE(GeoidGrid::load(path.string(), &error).has_value());
  EXPECT_NE(error.find("GTX size does not match its header"), std::string::npos) << error;
  write_gtx(path, 10, 20, 1, 1, 2, 3, {}, /*cut_bytes=*/4);  // not even a whole header
  EXPECT_FALSE(GeoidGrid::load(path.string(), &error).has_value());
  EXPECT_NE(error.find("bad header"), std::string::npos) << error;
  write_gtx(path, 10, 20, -1, 1, 2, 3, {1, 2, 3, 4, 5, 6});  // negative spacing
  EXPECT_FALSE(GeoidGrid::load(path.string(), &error).has_value());
  EXPECT_NE(error.find("bad header"), std::string::npos) << error;
  std::filesystem::remove(path);
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
