// The --fe-out link of `navfuse run` as a Point One client sees it, end to end through the real
// binary over TCP: every frame on the link, command responses included, is numbered by one
// sequence counter (spec L190); a MessageRequest for VersionInfo is answered with the build's
// version; CalibrationStatus and SystemStatus arrive about once per second of data; a
// ResetRequest and a SetConfig that changes the GNSS lever arm are announced by RESET and
// CONFIG_CHANGE EventNotifications (spec L2615-2642) besides their CommandResponses; sensor
// inputs a client sends on the link (VehicleSpeedInput, spec §3.5) are fused as from an input.
// The demo VN-300 log is written into a FIFO once the client is connected, so that the client
// sees the stream from its first frame; a UDP input that never ends keeps the process running.
#include <gtest/gtest.h>
#include <signal.h>

#include <fcntl.h>
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/io/unique_fd.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/messages_sensor.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/fe_client.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

namespace fe = frontends::fusionengine;

constexpr int kTimeoutMs = 30000;

std::string demo(const char* name) { return (std::filesystem::path(NAVFUSE_SOURCE_DIR) / "data/demo" / name).string(); }

// Waits until `done(snapshot)` or the timeout; returns the last snapshot.
template <class Done>
FeClient::Received wait_for(FeClient& client, Done done) {
  const io::Deadline deadline(kTimeoutMs);
  FeClient::Received r = client.snapshot();
  while (!done(r) && !deadline.expired()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    r = client.snapshot();
  }
  return r;
}

// Writes the demo VN-300 log into the FIFO `writer`, 4 KiB (~0.2 s of drive) every 10 ms, until
// done or `stop`.
std::thread feed_demo_log(io::UniqueFd& writer, std::atomic<bool>& stop) {
  return std::thread([&writer, &stop, log = read_text_file(demo("vn300.vnb"))] {
    constexpr std::size_t kChunk = 4 * 1024;
    for (std::size_t done = 0; done < log.size() && !stop;) {
      const ssize_t n = ::write(writer.get(), log.data() + done, std::min(kChunk, log.size() - done));
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
}

// `navfuse run` on the demo VN-300 log through a FIFO, with --fe-out on TCP and a client
// connected to it before the log is fed (from a second thread, 4 KiB every 10 ms).
class RunFeLinkTest : public ScratchDirTest {
 protected:
  void start(const std::vector<std::string>& extra = {}) {
    const std::string fifo = (dir_ / "vn.fifo").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const std::uint16_t fe_port = free_port(SOCK_STREAM);
    std::vector<std::string> argv{navfuse_binary(), "run", "--config", demo("vn300.yaml"), "--in", "vn:file:" + fifo,
                                  "--in", "fe:udp-listen://127.0.0.1:" + std::to_string(free_port(SOCK_DGRAM)),
                                  "--fe-out", "tcp-listen://127.0.0.1:" + std::to_string(fe_port)};
    argv.insert(argv.end(), extra.begin(), extra.end());
    nav_ = std::make_unique<ChildProcess>(argv, (dir_ / "nav.log").string());
    writer_ = io::UniqueFd(::open(fifo.c_str(), O_WRONLY | O_CLOEXEC));
    ASSERT_TRUE(static_cast<bool>(writer_));
    ASSERT_TRUE(nav_->wait_for_output("running", kTimeoutMs)) << nav_->output();
    ASSERT_TRUE(client_.connect(fe_port, kTimeoutMs));
    feed_ = feed_demo_log(writer_, stop_feed_);
  }
  void TearDown() override {
    stop_feed_ = true;
    if (feed_.joinable()) feed_.join();
    ScratchDirTest::TearDown();
  }
  // Stops feeding, ends the input and the process (SIGTERM): it exits cleanly.
  void stop() {
    stop_feed_ = true;
    if (feed_.joinable()) feed_.join();
    writer_ = io::UniqueFd();
    nav_->send(SIGTERM);
    EXPECT_EQ(nav_->wait_exit(kTimeoutMs), std::optional<int>(0)) << nav_->output();
  }

  std::unique_ptr<ChildProcess> nav_;
  io::UniqueFd writer_;
  FeClient client_;
  std::atomic<bool> stop_feed_{false};
  std::thread feed_;
};

TEST_F(RunFeLinkTest, OneSequenceCounterVersionStatusAndEvents) {
  start();
  if (HasFatalFailure()) return;
  FeClient& client = client_;

  // Two seconds of data: the 1 s status messages have started.
  auto r = wait_for(client, [](const FeClient::Received& s) { return s.count(fe::MessageType::kSystemStatus) >= 2; });
  ASSERT_GE(r.count(fe::MessageType::kSystemStatus), 2u) << nav_->output();
  EXPECT_GE(r.count(fe::MessageType::kCalibrationStatus), 2u);

  fe::MessageRequestMessage version;
  version.message_type = fe::to_u16(fe::MessageType::kVersionInfo);
  client.send(version);
  fe::SetConfigMessage set;
  set.config_type = fe::to_u16(fe::ConfigType::kGnssLeverArm);
  set.value = fe::pack_config(fe::Point3f{{0.25f, 0.0f, 0.5f}});
  const std::uint32_t set_sequence = client.send(set);
  fe::ResetRequestMessage reset;
  reset.reset_mask = fe::reset::kResetCalibrationData;
  const std::uint32_t reset_sequence = client.send(reset);
  r = wait_for(client, [](const FeClient::Received& s) {
    return s.count(fe::MessageType::kEventNotification) >= 2 && s.count(fe::MessageType::kVersionInfo) >= 1 &&
           s.responses.size() >= 2;
  });
  stop();

  // One counter: consecutive from the first frame this client saw to the last.
  ASSERT_GT(r.sequences.size(), 100u);
  std::size_t gaps = 0;
  for (std::size_t i = 1; i < r.sequences.size(); ++i) gaps += r.sequences[i] != r.sequences[i - 1] + 1 ? 1 : 0;
  EXPECT_EQ(gaps, 0u) << "of " << r.sequences.size() << " frames";

  ASSERT_EQ(r.responses.size(), 2u);
  EXPECT_EQ(r.responses[0].source_sequence, set_sequence);
  EXPECT_EQ(r.responses[1].source_sequence, reset_sequence);
  for (const auto& resp : r.responses) EXPECT_EQ(resp.response, static_cast<std::uint8_t>(fe::Response::kOk));

  std::string firmware;
  std::vector<std::uint8_t> event_types;
  std::uint64_t reset_flags = 0;
  for (const auto& o : r.others) {
    if (o.type == fe::to_u16(fe::MessageType::kVersionInfo)) {
      firmware.assign(o.payload.begin() + 16, o.payload.begin() + 16 + o.payload[8]);
    } else if (o.type == fe::to_u16(fe::MessageType::kEventNotification)) {
      event_types.push_back(o.payload[0]);
      if (o.payload[0] == 0x01) std::memcpy(&reset_flags, o.payload.data() + 12, 8);
    } else if (o.type == fe::to_u16(fe::MessageType::kSystemStatus)) {
      ASSERT_EQ(o.payload.size(), 128u);
      EXPECT_EQ(o.payload[8] | (o.payload[9] << 8), 0x7FFF);  // no temperature measured
    } else if (o.type == fe::to_u16(fe::MessageType::kCalibrationStatus)) {
      ASSERT_EQ(o.payload.size(), 92u);
    }
  }
  EXPECT_EQ(firmware.rfind(std::string("navfuse ") + NAVFUSE_TEST_PROJECT_VERSION, 0), 0u) << firmware;
  // Both commands are answered before the next epoch goes out, so the events are in command order.
  EXPECT_EQ(event_types, (std::vector<std::uint8_t>{0x02, 0x01}));  // CONFIG_CHANGE, RESET
  EXPECT_EQ(reset_flags, std::uint64_t{fe::reset::kResetCalibrationData});
}

// A VehicleSpeedInput of `speed_mps` (2^-10 m/s LSB, spec L2264-2287) stamped `time_source`.
fe::VehicleSpeedInputMessage speed_input(double speed_mps, fe::SystemTimeSource time_source, std::int64_t time_ns) {
  fe::VehicleSpeedInputMessage m;
  m.details.time_source = static_cast<std::uint8_t>(time_source);
  if (time_source != fe::SystemTimeSource::kInvalid) m.details.measurement_time = fe::Timestamp::from_ns(time_ns);
  m.speed = static_cast<std::int32_t>(std::lround(speed_mps * 1024.0));
  return m;
}

TEST_F(RunFeLinkTest, SensorInputsOnTheLinkAreFused) {
  const std::string summary = (dir_ / "summary.json").string();
  start({"--summary-json", summary});
  if (HasFatalFailure()) return;
  FeClient& client = client_;

  // The drive ends parked (the truth's last rows): wait for the Pose stream to get there, so the
  // speeds belong to the filter's present.
  const auto end_ns = static_cast<std::int64_t>(std::llround(std::stod(last_csv_row(demo("truth.csv")).at(0)) * 1e9));
  auto r = wait_for(client, [&](const FeClient::Received& s) {
    return !s.pose_times_ns.empty() && s.pose_times_ns.back() >= end_ns - 50'000'000;
  });
  ASSERT_FALSE(r.pose_times_ns.empty()) << nav_->output();
  ASSERT_GE(r.pose_times_ns.back(), end_ns - 50'000'000) << "the filter did not reach the end of the drive";

  // Standing still: 10 zero speeds in GPS time over the last 0.3 s, 10 timestamped on arrival
  // (time source Invalid, spec L298), and 5 of 8 m/s that the parked vehicle contradicts.
  constexpr int kGpsTimed = 10, kOnArrival = 10, kWrong = 5;
  for (int i = 0; i < kGpsTimed; ++i) {
    client.send(speed_input(0.0, fe::SystemTimeSource::kGpsTime, end_ns - 300'000'000 + i * 20'000'000LL));
  }
  for (int i = 0; i < kOnArrival; ++i) client.send(speed_input(0.0, fe::SystemTimeSource::kInvalid, 0));
  for (int i = 0; i < kWrong; ++i) client.send(speed_input(8.0, fe::SystemTimeSource::kInvalid, 0));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));  // the link and the filter take them in
  stop();

  const auto j = nlohmann::json::parse(read_text_file(summary));
  const auto& speed = j["measurements"]["vehicle_speed"];
  EXPECT_EQ(speed["decoded"].get<int>(), kGpsTimed + kOnArrival + kWrong) << j.dump();
  EXPECT_EQ(speed["used"].get<int>(), kGpsTimed + kOnArrival) << j.dump();
  int rejected = 0;
  for (const auto& [reason, n] : speed["rejected"].items()) rejected += n.get<int>();
  EXPECT_EQ(rejected, kWrong) << j.dump();
  EXPECT_FALSE(speed["rejected"].contains("time_base")) << j.dump();
}

}  // namespace
}  // namespace navfuse::test
