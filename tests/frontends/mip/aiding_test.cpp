// External aiding (0x13) as a CV7 answers it: frame configurations, vehicle-frame measurements
// computed by hand from p_vehicle = R p_sensor + t (digest §5.2), per-axis valid bits, the
// uncertainty rule (<= 0 on a valid axis -> NACK 0x03, L783) and the other reply codes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/bytes/byte_writer.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/mip/aiding.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/writer.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

constexpr double kPi = rot::kPi;

std::vector<std::uint8_t> frame_euler(std::uint8_t id, Eigen::Vector3d t, Eigen::Vector3d rpy) {
  std::vector<std::uint8_t> d;
  bytes::BeWriter w(d);
  w.u8(1);
  w.u8(id);
  w.u8(1);
  w.u8(1);
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(t[i]));
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(rpy[i]));
  return d;
}

std::vector<std::uint8_t> frame_quat(std::uint8_t id, Eigen::Vector3d t, Eigen::Quaterniond q) {
  std::vector<std::uint8_t> d;
  bytes::BeWriter w(d);
  w.u8(1);
  w.u8(id);
  w.u8(2);
  w.u8(0);
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(t[i]));
  w.f32(static_cast<float>(q.w()));
  w.f32(static_cast<float>(q.x()));
  w.f32(static_cast<float>(q.y()));
  w.f32(static_cast<float>(q.z()));
  return d;
}

std::vector<std::uint8_t> vec_meas(std::uint64_t ns, std::uint8_t frame, Eigen::Vector3d v, Eigen::Vector3d s,
                                   std::uint16_t valid) {
  std::vector<std::uint8_t> d;
  bytes::BeWriter w(d);
  test::aiding_head(w, ns, frame);
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(v[i]));
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(s[i]));
  w.u16(valid);
  return d;
}

std::vector<std::uint8_t> scalar_meas(std::uint64_t ns, std::uint8_t frame, double v, double s, std::uint16_t valid) {
  std::vector<std::uint8_t> d;
  bytes::BeWriter w(d);
  test::aiding_head(w, ns, frame);
  w.f32(static_cast<float>(v));
  w.f32(static_cast<float>(s));
  w.u16(valid);
  return d;
}

AidingResult send(AidingCommandHandler& h, std::uint8_t desc, const std::vector<std::uint8_t>& data,
                  std::uint8_t desc_set = 0x13) {
  const auto pkt = make_packet(desc_set, desc, data);
  AidingResult r;
  h.handle_packet(pkt, r);
  return r;
}

// The reply's (cmd, code) pairs, read back from the reply bytes.
std::vector<std::pair<int, int>> acks(const AidingResult& r) {
  std::vector<std::pair<int, int>> out;
  if (r.reply.size() < kWrapperSize) return out;
  FieldWalker walk(std::span<const std::uint8_t>(r.reply).subspan(kHeaderSize, r.reply[kLengthOffset]));
  FieldView f;
  while (walk.next(f))
    if (f.desc == kAckNackDescriptor) out.emplace_back(f.data[0], f.data[1]);
  return out;
}

TEST(MipAiding, FrameConfigsGiveHandComputedVehicleFrameMeasurements) {
  AidingCommandHandler h;
  // Frame 1: sensor yawed +90 deg, at (1, 2, 3) m. R = Rz(90) = [0 -1 0; 1 0 0; 0 0 1].
  auto r = send(h, 0x01, frame_euler(1, {1, 2, 3}, {0, 0, kPi / 2}));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x01, 0}}));
  // Frame 2: quaternion, 180 deg about z: R = diag(-1, -1, 1).
  r = send(h, 0x01, frame_quat(2, {0, 0, -0.4}, Eigen::Quaterniond(0, 0, 0, 1)));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x01, 0}}));

  // Body velocity in frame 1, x valid only: v_vehicle = R (2, 0, 0) = (0, 2, 0); only the
  // vehicle y axis is independent of the invalid sensor axes (row 1 of R = [1 0 0]).
  r = send(h, 0x2A, vec_meas(5'000'000'000, 1, {2, 0, 0}, {0.1, 0.1, 0.1}, 0x1));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x2A, 0}}));
  ASSERT_EQ(r.measurements.size(), 1u);
  const auto& v = std::get<ExternalVelocity>(r.measurements[0]);
  EXPECT_EQ(v.frame, VelocityFrame::kVehicle);
  EXPECT_EQ(v.header.valid, ExternalVelocity::kValidY);
  EXPECT_NEAR(v.value_mps.y(), 2.0, 1e-6);
  EXPECT_NEAR(v.std_mps.y(), 0.1, 1e-7);
  EXPECT_NEAR(v.lever_arm_m.x(), 1.0, 1e-7);
  EXPECT_NEAR(v.lever_arm_m.z(), 3.0, 1e-7);
  EXPECT_EQ(v.header.time_ns, 5'000'000'000);
  EXPECT_EQ(v.header.time_source, TimeSource::kGps);

  // All three axes valid in frame 1: (1, 2, 3) -> (-2, 1, 3).
  r = send(h, 0x2A, vec_meas(1, 1, {1, 2, 3}, {0.1, 0.2, 0.3}, 0x7));
  ASSERT_EQ(r.measurements.size(), 1u);
  const auto& v3 = std::get<ExternalVelocity>(r.measurements[0]);
  EXPECT_EQ(v3.header.valid, 0x7u);
  EXPECT_NEAR(v3.value_mps.x(), -2.0, 1e-6);
  EXPECT_NEAR(v3.value_mps.y(), 1.0, 1e-6);
  EXPECT_NEAR(v3.value_mps.z(), 3.0, 1e-6);
  EXPECT_NEAR(v3.std_mps.x(), 0.2, 1e-6);  // sensor y's sigma lands on vehicle x
  EXPECT_NEAR(v3.std_mps.y(), 0.1, 1e-6);

  // Heading of the frame-1 x axis 1.0 rad: the vehicle's is 1.0 - pi/2.
  r = send(h, 0x31, scalar_meas(2, 1, 1.0, 0.05, 1));
  ASSERT_EQ(r.measurements.size(), 1u);
  EXPECT_NEAR(std::get<ExternalHeading>(r.measurements[0]).heading_rad, 1.0 - kPi / 2, 1e-6);

  // Magnetic field in frame 2: (0.2, 0.1, 0.4) -> (-0.2, -0.1, 0.4).
  r = send(h, 0x32, vec_meas(3, 2, {0.2, 0.1, 0.4}, {0.03, 0.03, 0.03}, 0x7));
  ASSERT_EQ(r.measurements.size(), 1u);
  const auto& m = std::get<Magnetometer>(r.measurements[0]);
  EXPECT_EQ(m.frame, SensorFrame::kVehicle);
  EXPECT_NEAR(m.field_gauss.x(), -0.2, 1e-6);
  EXPECT_NEAR(m.field_gauss.y(), -0.1, 1e-6);
  EXPECT_NEAR(m.field_gauss.z(), 0.4, 1e-6);

  // LLH position from frame 2's antenna: degrees -> radians, lever arm = translation.
  r = send(h, 0x22, test::llh_meas(4, 2, 45.0, -122.5, 100.0, {1, 1, 2}, 0x7));
  ASSERT_EQ(r.measurements.size(), 1u);
  const auto& p = std::get<ExternalPosition>(r.measurements[0]);
  EXPECT_NEAR(p.value.x(), 45.0 * kPi / 180, 1e-15);
  EXPECT_NEAR(p.value.y(), -122.5 * kPi / 180, 1e-15);
  EXPECT_NEAR(p.lever_arm_m.z(), -0.4, 1e-7);

  // Height only (lat/lon invalid, L765): one valid axis.
  r = send(h, 0x22, test::llh_meas(4, 0, 0, 0, 55.0, {0, 0, 2}, 0x4));
  ASSERT_EQ(r.measurements.size(), 1u);
  EXPECT_EQ(std::get<ExternalPosition>(r.measurements[0]).header.valid, ExternalPosition::kValidZ);

  // Pressure 1013.25 mbar = 101325 Pa.
  r = send(h, 0x33, scalar_meas(5, 0, 1013.25, 0.5, 1));
  ASSERT_EQ(r.measurements.size(), 1u);
  EXPECT_NEAR(std::get<Pressure>(r.measurements[0]).pressure_pa, 101325.0, 1e-2);
}

TEST(MipAiding, NackCodes) {
  AidingCommandHandler h;
  send(h, 0x01, frame_euler(1, {0, 0, 0}, {0, 0, 0}));
  // Uncertainty 0 on a valid axis: invalid parameter (L783), nothing passed on.
  auto r = send(h, 0x2A, vec_meas(1, 1, {3.745, 0, 0}, {0.12, 0.0, 0.12}, 0x3));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x2A, 3}}));
  EXPECT_TRUE(r.measurements.empty());
  // Negative uncertainty on a valid axis.
  r = send(h, 0x31, scalar_meas(1, 0, 0.5, -0.1, 1));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x31, 3}}));
  // Uncertainty 0 on an invalid axis is fine (the axis is ignored, L7830).
  r = send(h, 0x2A, vec_meas(1, 1, {3.745, 0, 0}, {0.12, 0.0, 0.0}, 0x1));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x2A, 0}}));
  // Unknown (unconfigured) frame id 3, and an id beyond the limit of 4.
  r = send(h, 0x29, vec_meas(1, 3, {1, 1, 1}, {1, 1, 1}, 0x7));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 3}}));
  r = send(h, 0x29, vec_meas(1, 9, {1, 1, 1}, {1, 1, 1}, 0x7));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 3}}));
  // Configuring frame 0 (the device) or 5 is refused.
  r = send(h, 0x01, frame_euler(0, {0, 0, 0}, {0, 0, 0}));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x01, 3}}));
  r = send(h, 0x01, frame_euler(5, {0, 0, 0}, {0, 0, 0}));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x01, 3}}));
  // NaN value on a valid axis.
  r = send(h, 0x29, vec_meas(1, 0, {std::nan(""), 1, 1}, {1, 1, 1}, 0x7));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 3}}));
  // Unknown descriptor.
  r = send(h, 0x40, {1, 2, 3});
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x40, 1}}));
  // Truncated measurement.
  r = send(h, 0x29, {2, 1, 0, 0});
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 3}}));
  // A command sent to the aiding handler in another set: unknown descriptor set.
  r = send(h, 0x29, vec_meas(1, 0, {1, 1, 1}, {1, 1, 1}, 0x7), 0x0D);
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 6}}));
  // Bad checksum.
  auto pkt = make_packet(0x13, 0x29, vec_meas(1, 0, {1, 1, 1}, {1, 1, 1}, 0x7));
  pkt.back() ^= 0xFF;
  h.handle_packet(pkt, r);
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 2}}));
  EXPECT_TRUE(r.measurements.empty());
}

TEST(MipAiding, SeveralCommandsInOnePacketAnsweredInOrder) {
  AidingCommandHandler h;
  std::vector<std::uint8_t> pkt;
  PacketWriter w(pkt, 0x13);
  w.raw_field(0x01, frame_euler(2, {0.5, 0, 0}, {0, 0, 0}));
  w.raw_field(0x2A, vec_meas(1, 2, {1, 0, 0}, {0.1, 0.1, 0.1}, 0x1));
  w.raw_field(0x2A, vec_meas(1, 2, {1, 0, 0}, {0.0, 0.1, 0.1}, 0x1));  // bad sigma
  {
    std::vector<std::uint8_t> rd = {2, 2, 1};  // read frame 2 as Euler
    w.raw_field(0x01, rd);
  }
  w.finish();
  AidingResult r;
  h.handle_packet(pkt, r);
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x01, 0}, {0x2A, 0}, {0x2A, 3}, {0x01, 0}}));
  EXPECT_EQ(r.measurements.size(), 1u);
  // The read response (0x81) follows the last ACK: frame 2, Euler, translation x 0.5.
  std::vector<ReplyEntry> entries;
  ASSERT_TRUE(parse_reply(std::span<const std::uint8_t>(r.reply).subspan(kHeaderSize, r.reply[kLengthOffset]), entries));
  ASSERT_EQ(entries.size(), 4u);
  ASSERT_TRUE(entries[3].response_desc.has_value());
  EXPECT_EQ(*entries[3].response_desc, 0x81);
  EXPECT_EQ(entries[3].response_data[0], 2);
  EXPECT_EQ(entries[3].response_data[1], 1);
}

TEST(MipAiding, SuppressAckModeMutesOnlyAcceptedMeasurements) {
  AidingCommandHandler h;
  auto r = send(h, 0x1F, {1, 0});  // echo control write SUPPRESS_ACK
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x1F, 0}}));
  r = send(h, 0x29, vec_meas(1, 0, {1, 1, 1}, {1, 1, 1}, 0x7));
  EXPECT_TRUE(r.reply.empty());
  EXPECT_EQ(r.measurements.size(), 1u);
  r = send(h, 0x29, vec_meas(1, 0, {1, 1, 1}, {0, 1, 1}, 0x7));
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x29, 3}}));
}

TEST(MipAiding, DigestBodyVelocityExampleDecodes) {
  // §11.4 body-velocity vector: Time{1, 1, 158000}, frame 2, (3.745, 0, 0), sigma 0.12, valid X|Y.
  // Frame 2 must be configured first (L795 "must be > 0"); identity mounting.
  AidingCommandHandler h;
  send(h, 0x01, frame_euler(2, {0, 0, 0}, {0, 0, 0}));
  AidingResult r;
  h.handle_packet(test::hex("75651327272A0101000000000002693002406FAE1400000000000000003DF5C28F3DF5C28F3DF5C28F000301C7"), r);
  EXPECT_EQ(acks(r), (std::vector<std::pair<int, int>>{{0x2A, 0}}));
  ASSERT_EQ(r.measurements.size(), 1u);
  const auto& v = std::get<ExternalVelocity>(r.measurements[0]);
  EXPECT_EQ(v.header.valid, 0x3u);
  EXPECT_NEAR(v.value_mps.x(), 3.745, 1e-6);
  EXPECT_EQ(v.header.time_ns, 158000);  // timebase 1 without a clock mapping: device time
  EXPECT_EQ(v.header.time_source, TimeSource::kDeviceMonotonic);
}

}  // namespace
}  // namespace navfuse::frontends::mip
