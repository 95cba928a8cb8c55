// The nav process's other ways in, end to end through the real binary:
//  - MIP 0x13 external aiding sent on the --mip-out TCP connection is answered as a CV7 answers
//    it (ACK per command) and reaches the filter on the IMU's time axis; a filter command the
//    engine takes (speed lever arm 0x0D,0x61, aiding control 0x0D,0x50) is ACKed;
//  - a measurement stamped on another device's clock (a Point One wheel-speed input on P1
//    time, beside a VN-300 on GPS time) is rejected as "time_base", never fused.
// The VN-300 input is the bundled demo log; a UDP input that never ends keeps the process
// running until SIGTERM, and carries the FusionEngine messages.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>

#include <fcntl.h>
#include <sys/stat.h>

#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/io/unique_fd.hpp"
#include "frontends/fusionengine/encoder.hpp"
#include "frontends/mip/commands.hpp"
#include "frontends/mip/decoder.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/writer.hpp"
#include "tests/frontends/mip/test_util.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 20000;

std::string demo(const char* name) { return (std::filesystem::path(NAVFUSE_SOURCE_DIR) / "data/demo" / name).string(); }

// The last row of the demo truth: GPS time and position where the drive ends (stationary).
struct TruthEnd {
  double time_gps_s = 0, lat_deg = 0, lon_deg = 0, height_m = 0;
};
TruthEnd truth_end() {
  const auto row = last_csv_row(demo("truth.csv"));
  return {std::stod(row.at(0)), std::stod(row.at(1)), std::stod(row.at(2)), std::stod(row.at(3))};
}

class RunAidingTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_dir(); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Starts `navfuse run` on the demo VN-300 log plus a UDP input; returns once the log has been
  // read to its end.
  std::unique_ptr<ChildProcess> start(std::uint16_t udp_port, const std::vector<std::string>& extra) {
    std::vector<std::string> argv{navfuse_binary(), "run", "--config", demo("vn300.yaml"), "--in",
                                  "vn:file:" + demo("vn300.vnb"), "--in", "fe:udp-listen://127.0.0.1:" + std::to_string(udp_port),
                                  "--summary-json", summary_path()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    auto nav = std::make_unique<ChildProcess>(argv, (dir_ / "nav.log").string());
    EXPECT_TRUE(nav->wait_for_output("vn300.vnb' ended", kTimeoutMs)) << nav->output();
    return nav;
  }
  nlohmann::json stop(ChildProcess& nav) {
    nav.send(SIGTERM);
    const auto code = nav.wait_exit(kTimeoutMs);
    EXPECT_TRUE(code.has_value() && *code == 0) << nav.output();
    return nlohmann::json::parse(read_text_file(summary_path()));
  }
  std::string summary_path() const { return (dir_ / "summary.json").string(); }
  std::filesystem::path dir_;
};

void send_udp(std::uint16_t port, const std::vector<std::uint8_t>& bytes) {
  io::UniqueFd fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::sendto(fd.get(), bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&a), sizeof a),
            static_cast<ssize_t>(bytes.size()));
}

// A (0x13,0x22) LLH position aiding command at the drive's end position, all axes valid.
std::vector<std::uint8_t> llh_aiding(std::uint8_t timebase, std::uint64_t ns, const TruthEnd& p, double std_m) {
  return frontends::mip::make_packet(
      0x13, 0x22,
      frontends::mip::test::llh_meas(ns, 0, p.lat_deg, p.lon_deg, p.height_m, Eigen::Vector3d::Constant(std_m), 0x7, timebase));
}

// The newest solution time in the 0x82 stream, through the MIP front-end's own decoder.
struct SolutionTimeSink final : frontends::DecodeSink {
  std::int64_t latest_ns = 0;
  void on_measurement(const Measurement& m) override {
    if (kind_of(m) == MeasurementKind::kDeviceSolution) latest_ns = std::max(latest_ns, header_of(m).time_ns);
  }
};

TEST_F(RunAidingTest, MipAidingOnTheOutputLinkIsAcknowledgedAndFused) {
  // The VN-300 log comes through a FIFO, written once the MIP client is connected, so the test
  // sees the filter's 0x82 stream reach the end of the drive before it aids: aiding belongs to
  // the present of a live filter, not to data still queued behind it.
  const std::string fifo = (dir_ / "vn.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::uint16_t mip_port = free_port(SOCK_STREAM);
  ChildProcess nav({navfuse_binary(), "run", "--config", demo("vn300.yaml"), "--in", "vn:file:" + fifo, "--in",
                    "fe:udp-listen://127.0.0.1:" + std::to_string(free_port(SOCK_DGRAM)), "--mip-out",
                    "tcp-listen://127.0.0.1:" + std::to_string(mip_port), "--summary-json", summary_path()},
                   (dir_ / "nav.log").string());
  io::UniqueFd writer(::open(fifo.c_str(), O_WRONLY | O_CLOEXEC));  // meets the process's open()
  ASSERT_TRUE(static_cast<bool>(writer));
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  io::UniqueFd link = connect_loopback(mip_port, kTimeoutMs);
  ASSERT_TRUE(static_cast<bool>(link));
  // Written from a second thread while this one keeps the link drained (a client that stops
  // reading is a slow consumer, whose data the process drops rather than wait for), at about
  // 40 times real time: a FIFO is a live input, so a burst beyond what the filter takes in is
  // dropped at the input queue like a device outpacing it.
  std::thread feed([&writer, log = read_text_file(demo("vn300.vnb"))] {
    constexpr std::size_t kChunk = 8 * 1024;  // ~0.45 s of drive, every 10 ms
    for (std::size_t done = 0; done < log.size();) {
      const ssize_t n = ::write(writer.get(), log.data() + done, std::min(kChunk, log.size() - done));
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    writer = io::UniqueFd();
  });

  const TruthEnd end = truth_end();
  const auto end_ns = static_cast<std::int64_t>(std::llround(end.time_gps_s * 1e9));
  frontends::mip::Framer framer;
  frontends::mip::MipDecoder decoder;
  SolutionTimeSink solutions;
  std::vector<frontends::mip::ReplyEntry> acks;
  const std::int64_t& filter_ns = solutions.latest_ns;
  // Reads the link until `done()`: 0x82 times and 0x13 replies (interleaved in any order).
  auto read_until = [&](auto done) {
    const io::Deadline deadline(kTimeoutMs);
    while (!done() && !deadline.expired()) {
      pollfd p{link.get(), POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      std::uint8_t buf[4096];
      const ssize_t n = ::read(link.get(), buf, sizeof buf);
      if (n <= 0) return;
      framer.feed(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), [&](const frontends::mip::PacketView& pkt) {
        if (pkt.desc_set == 0x82) decoder.on_packet(pkt, solutions);
        std::vector<frontends::mip::ReplyEntry> entries;
        if ((pkt.desc_set == 0x13 || pkt.desc_set == 0x0D) && frontends::mip::parse_reply(pkt.payload, entries)) {
          acks.insert(acks.end(), entries.begin(), entries.end());
        }
      });
    }
  };
  read_until([&] { return filter_ns >= end_ns - 50'000'000; });
  feed.join();
  ASSERT_GE(filter_ns, end_ns - 50'000'000) << "the filter did not reach the end of the drive";

  // The drive ends parked at the truth's last position; aid there 0.3 s before the last IMU
  // sample (GPS time, timebase 2) and at the time of arrival (timebase 3).
  const auto gps_ns = static_cast<std::uint64_t>(std::llround((end.time_gps_s - 0.3) * 1e9));
  std::vector<std::uint8_t> commands = llh_aiding(2, gps_ns, end, 2.0);
  const auto arrival = llh_aiding(3, 0, end, 2.0);
  commands.insert(commands.end(), arrival.begin(), arrival.end());
  ASSERT_EQ(::write(link.get(), commands.data(), commands.size()), static_cast<ssize_t>(commands.size()));

  // Two replies, each an ACK (code 0) of 0x22 in set 0x13.
  read_until([&] { return acks.size() >= 2; });
  ASSERT_EQ(acks.size(), 2u);
  for (const auto& a : acks) {
    EXPECT_EQ(a.cmd_desc, 0x22);
    EXPECT_EQ(a.code, frontends::mip::ReplyCode::kAck);
  }

  // (0x0D,0x61) write, source 1, lever arm (0, 0.5, 0) m; (0x0D,0x50) write source 3 off.
  acks.clear();
  const std::vector<std::uint8_t> arm{0x01, 0x01, 0, 0, 0, 0, 0x3F, 0x00, 0x00, 0x00, 0, 0, 0, 0};
  const std::vector<std::uint8_t> aiding_off{0x01, 0x00, 0x03, 0x00};
  auto filter_commands = frontends::mip::make_packet(0x0D, 0x61, arm);
  const auto off = frontends::mip::make_packet(0x0D, 0x50, aiding_off);
  filter_commands.insert(filter_commands.end(), off.begin(), off.end());
  ASSERT_EQ(::write(link.get(), filter_commands.data(), filter_commands.size()),
            static_cast<ssize_t>(filter_commands.size()));
  read_until([&] { return acks.size() >= 2; });
  ASSERT_EQ(acks.size(), 2u);
  EXPECT_EQ(acks[0].cmd_desc, 0x61);
  EXPECT_EQ(acks[0].code, frontends::mip::ReplyCode::kAck);
  EXPECT_EQ(acks[1].cmd_desc, 0x50);
  EXPECT_EQ(acks[1].code, frontends::mip::ReplyCode::kAck);

  const auto j = stop(nav);
  const auto& ext = j["measurements"]["external_position"];
  EXPECT_EQ(ext["decoded"].get<int>(), 2) << j.dump();
  EXPECT_EQ(ext["used"].get<int>(), 2) << j.dump();  // both on the IMU's time axis, both consistent
  EXPECT_FALSE(ext["rejected"].contains("time_base")) << j.dump();
  EXPECT_EQ(j["measurements"]["imu"]["used"].get<int>(), 38000) << j.dump();  // nothing dropped on the way
}

TEST_F(RunAidingTest, WheelSpeedOnAnotherDevicesClockIsRejectedAsTimeBase) {
  const std::uint16_t udp_port = free_port(SOCK_DGRAM);
  auto nav = start(udp_port, {"--quiet"});
  // Twenty FusionEngine VehicleSpeedInput messages stamped on P1 time (the sending device's own
  // clock): the VN-300's IMU is on GPS time, and no mapping between the two clocks exists.
  frontends::fusionengine::FusionEngineEncoder encoder({.sensor_inputs = true});
  constexpr int kSpeeds = 20;
  for (int i = 0; i < kSpeeds; ++i) {
    VehicleSpeed v;
    v.header = {1'000'000'000 + i * 20'000'000LL, TimeSource::kDeviceMonotonic, 0, VehicleSpeed::kValidSpeed};
    v.speed_mps = 5.0;
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(encoder.encode(v, bytes));
    send_udp(udp_port, bytes);
  }
  ::poll(nullptr, 0, 1000);  // the reader takes them in (milliseconds) before SIGTERM

  const auto j = stop(*nav);
  const auto& speed = j["measurements"]["vehicle_speed"];
  EXPECT_EQ(speed["decoded"].get<int>(), kSpeeds) << j.dump();
  EXPECT_EQ(speed["used"].get<int>(), 0) << j.dump();
  EXPECT_EQ(speed["rejected"]["time_base"].get<int>(), kSpeeds) << j.dump();
  EXPECT_GT(j["measurements"]["imu"]["used"].get<int>(), 30000) << j.dump();
}

}  // namespace
}  // namespace navfuse::test
