// The real FusionEngine capture in ../shared/captures (Point One's example log): framed without
// loss, decoded to the values Point One's own Python client reads from it, and re-encoded to
// identical bytes. Skips when the shared folder is absent.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rotation/rotation.hpp"
#include "frontends/fusionengine/decoder.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::fusionengine {
namespace {

using rot::kDegToRad;

std::optional<std::vector<std::uint8_t>> load_capture() {
  return test::read_file(std::string(NAVFUSE_SHARED_DIR) + "/captures/fe_example_data.p1log");
}

TEST(FeCapture, FramesDecodeAndCount) {
  const auto bytes = load_capture();
  if (!bytes) GTEST_SKIP() << "capture not present";
  ASSERT_EQ(bytes->size(), 468u);
  FusionEngineDecoder decoder;
  test::CollectingSink sink(true);
  decoder.feed(*bytes, sink);
  decoder.finish(sink);
  const auto& c = decoder.counters();
  EXPECT_EQ(c.bytes, 468u);
  EXPECT_EQ(c.frames, 4u);  // Pose, GNSSInfo, GNSSSatellite, Pose
  EXPECT_EQ(c.bad_frames, 0u);
  EXPECT_EQ(c.skipped_bytes, 0u);
  EXPECT_EQ(c.unknown_frames, 0u);
  // The GNSSInfo frame is message version 0, whose layout predates the spec's version 1
  // (spec L3081): reported, not misread.
  EXPECT_EQ(c.decode_errors, 1u);
  ASSERT_EQ(sink.records.size(), 4u);
  EXPECT_EQ(sink.records[0].name, "Pose");
  EXPECT_EQ(sink.records[1].name, "GNSSInfo");
  EXPECT_EQ(sink.records[2].name, "GNSSSatellite");
  EXPECT_EQ(sink.records[3].name, "Pose");
  EXPECT_EQ(sink.count(MeasurementKind::kDeviceSolution), 2u);
  EXPECT_EQ(sink.measurements.size(), 2u);
}

TEST(FeCapture, PoseValuesMatchPointOnesClient) {
  const auto bytes = load_capture();
  if (!bytes) GTEST_SKIP() << "capture not present";
  FusionEngineDecoder decoder;
  test::CollectingSink sink(true);
  decoder.feed(*bytes, sink);
  decoder.finish(sink);
  const auto sols = sink.all<NavSolution>();
  ASSERT_EQ(sols.size(), 2u);

  // Values printed by fusion-engine-client 1.28 for the first Pose: GPS time 1282677727.2 s,
  // RTKFixed, lla (37.795137, -122.402754, 40.8), std 0.1 m, ypr (190, 2.1, 0.1) deg,
  // body velocity (-2.3, -0.01, 0.3) m/s.
  const NavSolution& s = sols[0];
  EXPECT_EQ(s.header.time_source, TimeSource::kGps);
  EXPECT_EQ(s.header.time_ns, 1'282'677'727'200'000'000);
  EXPECT_EQ(s.mode, NavMode::kNavigation);
  EXPECT_EQ(s.gnss_fix, GnssFixType::kRtkFixed);
  EXPECT_NEAR(s.lat_rad, 37.795137 * kDegToRad, 1e-12);
  EXPECT_NEAR(s.lon_rad, -122.402754 * kDegToRad, 1e-12);
  EXPECT_NEAR(s.height_m, 40.8, 1e-9);
  EXPECT_FLOAT_EQ(static_cast<float>(s.pos_std_ned_m.x()), 0.1f);
  // Version 0 Pose predates the undulation field: not valid (adapt_to_version).
  EXPECT_EQ(s.header.valid & NavSolution::kValidUndulation, 0u);
  // Digest §9: roll_NED = roll, pitch_NED = -pitch, heading = 90 - yaw (wrapped).
  EXPECT_NEAR(s.rpy_rad.x(), 0.1 * kDegToRad, 1e-9);
  EXPECT_NEAR(s.rpy_rad.y(), -2.1 * kDegToRad, 1e-9);
  EXPECT_NEAR(s.rpy_rad.z(), -100.0 * kDegToRad, 1e-9);
  // NED velocity = C_nb(roll, pitch, heading) * FRD body velocity, built from those angles.
  const Eigen::Matrix3d c_nb = rot::dcm_from_rpy(Eigen::Vector3d(0.1, -2.1, -100.0) * kDegToRad);
  const Eigen::Vector3d expected = c_nb * Eigen::Vector3d(-2.3, 0.01, -0.3);
  EXPECT_NEAR((s.vel_ned_mps - expected).norm(), 0.0, 1e-9);

  const NavSolution& t = sols[1];
  EXPECT_EQ(t.header.time_ns, 1'282'677'727'400'000'000);
  EXPECT_EQ(t.gnss_fix, GnssFixType::kRtkFloat);
  EXPECT_NEAR(t.rpy_rad.z(), 53.0 * kDegToRad, 1e-9);  // 90 - 37

  // GNSSSatellite: two satellites, GPS 4 at az 34.5 el 56.2, Galileo 9 at az 79.4 el 16.1.
  EXPECT_EQ(std::get<std::uint64_t>(*sink.field(2, "num_satellites")), 2u);
  EXPECT_EQ(std::get<std::uint64_t>(*sink.field(2, "sat0_prn")), 4u);
  EXPECT_EQ(std::get<std::uint64_t>(*sink.field(2, "sat1_system")), 4u);
  EXPECT_FLOAT_EQ(static_cast<float>(std::get<double>(*sink.field(2, "sat0_azimuth_deg"))), 34.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(std::get<double>(*sink.field(2, "sat1_elevation_deg"))), 16.1f);
}

TEST(FeCapture, FramesOfSpecLayoutsReencodeToIdenticalBytes) {
  const auto bytes = load_capture();
  if (!bytes) GTEST_SKIP() << "capture not present";
  const auto frames = test::frames_of(*bytes);
  ASSERT_EQ(frames.size(), 4u);
  int identical = 0;
  for (const auto& f : frames) {
    // GNSSInfo version 0 (frame 2) has non-zero bytes where version 1 has reserved ones: it has
    // another layout, so only the other three can come back byte for byte.
    if (f.header.message_type == to_u16(MessageType::kGnssInfo)) {
      EXPECT_EQ(f.header.message_version, 0);
      continue;
    }
    const auto again = test::reencode(f.view());
    ASSERT_TRUE(again);
    EXPECT_EQ(*again, f.bytes);
    identical += *again == f.bytes ? 1 : 0;
  }
  EXPECT_EQ(identical, 3);
}

}  // namespace
}  // namespace navfuse::frontends::fusionengine
