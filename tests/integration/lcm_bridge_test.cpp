// The LCM side of the nav process with real LCM traffic (loopback multicast, ttl=0): the
// publisher's messages arrive with the solution's values (NAVFUSE_IMU: its bias-compensated IMU,
// with each pose and only then), aiding published on NAVFUSE_AID_*
// arrives as core measurements, and the LCM thread publishes what is posted and measures the
// arrival-to-publication latency.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/aid/aid_message.hpp"
#include "apps/lcm/lcm_aiding_subscriber.hpp"
#include "apps/lcm/lcm_channels.hpp"
#include "apps/lcm/lcm_publisher.hpp"
#include "apps/run/lcm_service.hpp"
#include "apps/run/status_reporter.hpp"
#include "core/rotation/rotation.hpp"
#include "tests/integration/lcm_receiver.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

using apps::kAidHeadingChannel;
using apps::kAidPositionChannel;
using apps::kAidSpeedChannel;
using apps::kAidVelocityChannel;

constexpr int kTimeoutMs = 3000;

NavSolution sample_solution() {
  NavSolution s;
  s.header.time_ns = 1'400'000'000'123'456'789;
  s.header.time_source = TimeSource::kGps;
  s.header.valid = NavSolution::kValidPosition | NavSolution::kValidAttitude;
  s.mode = NavMode::kNavigation;
  s.gnss_fix = GnssFixType::kRtkFixed;
  s.status_flags = NavSolution::kStatusWheelAiding;
  s.lat_rad = 37.5 * rot::kDegToRad;
  s.lon_rad = -122.25 * rot::kDegToRad;
  s.height_m = 12.5;
  s.vel_ned_mps = {1.0, -2.0, 0.5};
  s.rpy_rad = Eigen::Vector3d(1.0, -2.0, 90.0) * rot::kDegToRad;
  s.q_nb = rot::quat_from_rpy(s.rpy_rad);
  s.gyro_bias_rps = Eigen::Vector3d(0.01, 0.02, 0.03) * rot::kDegToRad;
  return s;
}

class LcmBridgeTest : public ::testing::Test {
 protected:
  std::string url_ = private_lcm_url(1);
  lcm::LCM tx_{url_};
  lcm::LCM rx_{url_};
};

TEST_F(LcmBridgeTest, PublisherMessagesArriveWithTheSolutionValues) {
  ASSERT_TRUE(tx_.good() && rx_.good()) << url_;
  LcmReceiver<navfuse::pose_t> poses(rx_, apps::kPoseChannel);
  LcmReceiver<navfuse::imu_t> imus(rx_, apps::kImuChannel);
  LcmReceiver<navfuse::gnss_t> fixes(rx_, apps::kGnssChannel);
  LcmReceiver<navfuse::status_t> statuses(rx_, apps::kStatusChannel);

  apps::LcmPublisher publisher(tx_);
  // Level, heading east: body x is east, body y south, body z down.
  NavSolution s = sample_solution();
  s.rpy_rad = Eigen::Vector3d(0.0, 0.0, 90.0 * rot::kDegToRad);
  s.q_nb = rot::quat_from_rpy(s.rpy_rad);
  s.angular_rate_rps = {0.01, -0.02, 0.2};
  s.linear_accel_mps2 = {0.5, 0.25, 0.0};
  s.gravity_ned_mps2 = {0.0, 0.0, 9.8};
  // Not a pose epoch: nothing goes out.
  EXPECT_FALSE(publisher.publish_epoch(apps::OutputEpoch{.solution = s}));
  EXPECT_EQ(publisher.published(), 0u);
  ASSERT_TRUE(publisher.publish_epoch(apps::OutputEpoch{.solution = s, .pose_due = true}));
  EXPECT_EQ(publisher.published(), 2u) << "NAVFUSE_POSE and NAVFUSE_IMU";

  GnssPosition fix;
  fix.header.time_ns = s.header.time_ns;
  fix.lat_rad = s.lat_rad;
  fix.lon_rad = s.lon_rad;
  fix.height_m = 10;
  fix.cov_ned_m2 = Eigen::Vector3d(4, 9, 16).asDiagonal();
  fix.fix = GnssFixType::kFix3D;
  fix.num_sats = 14;
  GnssVelocity vel;
  vel.header.valid = GnssVelocity::kValidVelocity;
  vel.vel_ned_mps = {3, 4, 0};
  vel.cov_ned_m2ps2 = Eigen::Vector3d(0.01, 0.01, 0.04).asDiagonal();
  ASSERT_TRUE(publisher.publish_gnss(fix, &vel));

  navfuse::status_t status{};
  status.mode_name = "navigation";
  status.num_inputs = 1;
  status.inputs.resize(1);
  status.inputs[0].name = "vn:serial:/dev/ttyUSB0";
  status.latency_p99_us = 250.0f;
  ASSERT_TRUE(publisher.publish_status(status));

  ASSERT_TRUE(handle_until(rx_, [&] {
    return !poses.messages.empty() && !imus.messages.empty() && !fixes.messages.empty() && !statuses.messages.empty();
  }, kTimeoutMs));

  const navfuse::pose_t& p = poses.messages[0];
  EXPECT_EQ(p.time_gps_ns, s.header.time_ns);
  EXPECT_EQ(p.mode, static_cast<int>(NavMode::kNavigation));
  EXPECT_EQ(p.gnss_fix, static_cast<int>(GnssFixType::kRtkFixed));
  EXPECT_EQ(p.status_flags, static_cast<std::int32_t>(NavSolution::kStatusWheelAiding));
  EXPECT_NEAR(p.lat_deg, 37.5, 1e-12);
  EXPECT_NEAR(p.lon_deg, -122.25, 1e-12);
  EXPECT_DOUBLE_EQ(p.height_m, 12.5);
  EXPECT_FLOAT_EQ(p.vel_ned_mps[1], -2.0f);
  EXPECT_NEAR(p.rpy_deg[2], 90.0f, 1e-4);
  EXPECT_NEAR(p.rpy_deg[0], 0.0f, 1e-4);
  EXPECT_NEAR(p.q_nb_wxyz[0], s.q_nb.w(), 1e-15);
  EXPECT_NEAR(p.gyro_bias_dps[2], 0.03f, 1e-7);

  ASSERT_EQ(imus.messages.size(), 1u);
  const navfuse::imu_t& i = imus.messages[0];
  EXPECT_EQ(i.time_gps_ns, s.header.time_ns);
  EXPECT_FLOAT_EQ(i.gyro_radps[0], 0.01f);  // the solution's (bias-compensated) rate
  EXPECT_FLOAT_EQ(i.gyro_radps[2], 0.2f);
  // Specific force = acceleration - gravity; level, gravity is +z (down) in the body too.
  EXPECT_NEAR(i.accel_mps2[0], 0.5f, 1e-6);
  EXPECT_NEAR(i.accel_mps2[1], 0.25f, 1e-6);
  EXPECT_NEAR(i.accel_mps2[2], -9.8f, 1e-6);
  EXPECT_FLOAT_EQ(i.dt_s, 0.0f);

  const navfuse::gnss_t& g = fixes.messages[0];
  EXPECT_EQ(g.num_sats, 14);
  EXPECT_EQ(g.fix, static_cast<int>(GnssFixType::kFix3D));
  EXPECT_FLOAT_EQ(g.pos_std_ned_m[2], 4.0f);
  EXPECT_EQ(g.has_velocity, 1);
  EXPECT_FLOAT_EQ(g.vel_ned_mps[1], 4.0f);
  EXPECT_FLOAT_EQ(g.vel_std_ned_mps[2], 0.2f);

  ASSERT_EQ(statuses.messages[0].num_inputs, 1);
  EXPECT_EQ(statuses.messages[0].inputs[0].name, "vn:serial:/dev/ttyUSB0");
  EXPECT_FLOAT_EQ(statuses.messages[0].latency_p99_us, 250.0f);
  EXPECT_EQ(publisher.failures(), 0u);
}

TEST_F(LcmBridgeTest, StatusCarriesPerKindInnovationStatistics) {
  ASSERT_TRUE(tx_.good() && rx_.good()) << url_;
  LcmReceiver<navfuse::status_t> statuses(rx_, apps::kStatusChannel);
  // Filter statistics by hand: 8 GNSS positions tried (NIS 4, 4, 5, 5, 6, 6, 7, 30: sum 67, per
  // dimension sum 67 / 3), 7 fused, 1 above the gate plus 2 late; 4 wheel speeds tried, all fused
  // (NIS sum 2.0). GNSS velocity never tried: not listed.
  filter::FilterStats stats;
  auto& pos = stats.of(MeasurementKind::kGnssPosition);
  pos.innovation = {.count = 8, .above_gate = 1, .nis_sum = 67.0, .nis_per_dim_sum = 67.0 / 3.0};
  pos.used = 7;
  pos.rejected[static_cast<std::size_t>(filter::RejectReason::kChi2Gate)] = 1;
  pos.rejected[static_cast<std::size_t>(filter::RejectReason::kTooLate)] = 2;
  auto& wheel = stats.of(MeasurementKind::kWheelSpeed);
  wheel.innovation = {.count = 4, .above_gate = 0, .nis_sum = 2.0, .nis_per_dim_sum = 2.0};
  wheel.used = 4;
  stats.of(MeasurementKind::kGnssVelocity).rejected[static_cast<std::size_t>(filter::RejectReason::kNotAligned)] = 3;

  const NavSolution solution = sample_solution();
  const std::vector<apps::InputSnapshot> inputs;
  apps::StatusReporter reporter;
  apps::LcmPublisher publisher(tx_);
  ASSERT_TRUE(publisher.publish_status(reporter.make({.solution = solution, .filter = stats, .inputs = inputs,
                                                      .rejected_queue_full = 0, .rejected_time_base = 0,
                                                      .output_drops = 0, .latency = {}},
                                                     1'000'000'000)));
  ASSERT_TRUE(handle_until(rx_, [&] { return !statuses.messages.empty(); }, kTimeoutMs));

  const navfuse::status_t& s = statuses.messages[0];
  ASSERT_EQ(s.num_innovations, 2);
  // kind, count, accepted, rejected, mean NIS, per dimension, fraction above the gate
  const navfuse::innovation_t want[] = {{"gnss_position", 8, 7, 3, 67.0f / 8.0f, 67.0f / 24.0f, 0.125f},
                                        {"wheel_speed", 4, 4, 0, 0.5f, 0.5f, 0.0f}};
  for (std::size_t k = 0; k < 2; ++k) {
    const navfuse::innovation_t& got = s.innovations[k];
    EXPECT_EQ(got.kind, want[k].kind);
    EXPECT_EQ(got.count, want[k].count);
    EXPECT_EQ(got.accepted, want[k].accepted);
    EXPECT_EQ(got.rejected, want[k].rejected);
    EXPECT_FLOAT_EQ(got.mean_nis, want[k].mean_nis);
    EXPECT_FLOAT_EQ(got.mean_nis_per_dim, want[k].mean_nis_per_dim);
    EXPECT_FLOAT_EQ(got.fraction_above_gate, want[k].fraction_above_gate);
  }
  // The fields that were there before keep their meaning.
  EXPECT_EQ(s.mode_name, "navigation");
  EXPECT_EQ(s.num_rejections, 3);  // gnss_position chi2_gate and too_late, gnss_velocity not_aligned
}

TEST_F(LcmBridgeTest, AidingChannelsBecomeMeasurements) {
  std::vector<Measurement> received;
  apps::LcmAidingSubscriber subscriber(rx_, [&](const Measurement& m) { received.push_back(m); });

  navfuse::aid_position_t pos{};
  pos.time_gps_ns = 1000;
  pos.frame = navfuse::aid_position_t::FRAME_LLH;
  pos.value[0] = 45.0;
  pos.value[1] = 7.0;
  pos.value[2] = 300.0;
  pos.std_m[0] = pos.std_m[1] = pos.std_m[2] = 0.5f;
  pos.valid_mask = 7;
  navfuse::aid_velocity_t vel{};
  vel.time_gps_ns = 2000;
  vel.frame = navfuse::aid_velocity_t::FRAME_VEHICLE;
  vel.value_mps[0] = 3.0f;
  vel.std_mps[0] = vel.std_mps[1] = vel.std_mps[2] = 0.1f;
  vel.valid_mask = 1;
  navfuse::aid_heading_t heading{};
  heading.time_gps_ns = 3000;
  heading.heading_deg = 90.0f;
  heading.std_deg = 1.0f;
  heading.valid = 1;
  navfuse::aid_speed_t speed{};
  speed.time_gps_ns = 4000;
  speed.speed_mps = -1.5f;
  speed.std_mps = 0.05f;
  speed.valid = 1;
  ASSERT_EQ(tx_.publish(kAidPositionChannel, &pos), 0);
  ASSERT_EQ(tx_.publish(kAidVelocityChannel, &vel), 0);
  ASSERT_EQ(tx_.publish(kAidHeadingChannel, &heading), 0);
  ASSERT_EQ(tx_.publish(kAidSpeedChannel, &speed), 0);

  ASSERT_TRUE(handle_until(rx_, [&] { return received.size() == 4; }, kTimeoutMs)) << received.size();
  EXPECT_EQ(subscriber.received(), 4u);
  const auto& p = std::get<ExternalPosition>(received[0]);
  EXPECT_EQ(p.header.time_ns, 1000);
  EXPECT_NEAR(p.value.x(), 45.0 * rot::kDegToRad, 1e-12);
  EXPECT_EQ(p.header.valid, 7u);
  EXPECT_EQ(std::get<ExternalVelocity>(received[1]).frame, VelocityFrame::kVehicle);
  EXPECT_NEAR(std::get<ExternalHeading>(received[2]).heading_rad, rot::kPi / 2, 1e-6);
  EXPECT_FLOAT_EQ(static_cast<float>(std::get<VehicleSpeed>(received[3]).speed_mps), -1.5f);
}

TEST_F(LcmBridgeTest, ServicePublishesPostsAndQueuesAiding) {
  LcmReceiver<navfuse::pose_t> poses(rx_, apps::kPoseChannel);
  LcmReceiver<navfuse::status_t> statuses(rx_, apps::kStatusChannel);
  apps::MeasurementQueue queue(16);
  apps::LatencyTracker latency;
  apps::LcmService service(url_, queue, latency);
  service.start();

  apps::OutputEpoch epoch{.solution = sample_solution()};
  for (int i = 0; i < 10; ++i) {
    epoch.pose_due = i % 2 == 0;  // five pose epochs among ten
    epoch.arrival_ns = apps::monotonic_ns();
    ASSERT_TRUE(service.post_epoch(epoch));
  }
  navfuse::status_t status{};
  status.mode_name = "ahrs";
  service.post_status(status);
  ASSERT_TRUE(handle_until(rx_, [&] { return poses.messages.size() == 5 && !statuses.messages.empty(); }, kTimeoutMs));
  EXPECT_EQ(statuses.messages[0].mode_name, "ahrs");

  // Aiding published by someone else reaches the filter queue, stamped as LCM aiding.
  navfuse::aid_heading_t heading{};
  heading.time_gps_ns = 42;
  heading.heading_deg = 10.0f;
  heading.std_deg = 2.0f;
  heading.valid = 1;
  ASSERT_EQ(tx_.publish(kAidHeadingChannel, &heading), 0);
  apps::ArrivedMeasurement item;
  ASSERT_TRUE(queue.pop_wait(item, std::chrono::milliseconds(kTimeoutMs)));
  EXPECT_EQ(item.source, apps::kSourceLcmAiding);
  EXPECT_EQ(header_of(item.measurement).time_ns, 42);
  EXPECT_EQ(service.aiding_received(), 1u);

  service.stop();
  const apps::LatencySummary l = latency.take_window();
  EXPECT_EQ(l.samples, 5u);
  EXPECT_GT(l.p50_us, 0.0);
  EXPECT_LE(l.p50_us, l.p99_us);
  EXPECT_EQ(service.dropped(), 0u);
}

}  // namespace
}  // namespace navfuse::test
