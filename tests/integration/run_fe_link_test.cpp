// The --fe-out link of `navfuse run` as a Point One client sees it, end to end through the real
// binary over TCP: every frame on the link, command responses included, is numbered by one
// sequence counter (spec L190); a MessageRequest for VersionInfo is answered with the build's
// version; CalibrationStatus and SystemStatus arrive about once per second of data; a
// ResetRequest and a SetConfig that changes the GNSS lever arm are announced by RESET and
// CONFIG_CHANGE EventNotifications (spec L2615-2642) besides their CommandResponses.
// The demo VN-300 log is written into a FIFO once the client is connected, so that the client
// sees the stream from its first frame; a UDP input that never ends keeps the process running.
#include <gtest/gtest.h>
#include <signal.h>

#include <fcntl.h>
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <thread>

#include "core/io/unique_fd.hpp"
#include "frontends/fusionengine/config_types.hpp"
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

using RunFeLinkTest = ScratchDirTest;

TEST_F(RunFeLinkTest, OneSequenceCounterVersionStatusAndEvents) {
  const std::string fifo = (dir_ / "vn.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::uint16_t fe_port = free_port(SOCK_STREAM);
  ChildProcess nav({navfuse_binary(), "run", "--config", demo("vn300.yaml"), "--in", "vn:file:" + fifo, "--in",
                    "fe:udp-listen://127.0.0.1:" + std::to_string(free_port(SOCK_DGRAM)), "--fe-out",
                    "tcp-listen://127.0.0.1:" + std::to_string(fe_port)},
                   (dir_ / "nav.log").string());
  io::UniqueFd writer(::open(fifo.c_str(), O_WRONLY | O_CLOEXEC));
  ASSERT_TRUE(static_cast<bool>(writer));
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  FeClient client;
  ASSERT_TRUE(client.connect(fe_port, kTimeoutMs));
  std::atomic<bool> stop_feed{false};
  std::thread feed([&writer, &stop_feed, log = read_text_file(demo("vn300.vnb"))] {
    constexpr std::size_t kChunk = 4 * 1024;
    for (std::size_t done = 0; done < log.size() && !stop_feed;) {
      const ssize_t n = ::write(writer.get(), log.data() + done, std::min(kChunk, log.size() - done));
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });

  // Two seconds of data: the 1 s status messages have started.
  auto r = wait_for(client, [](const FeClient::Received& s) { return s.count(fe::MessageType::kSystemStatus) >= 2; });
  ASSERT_GE(r.count(fe::MessageType::kSystemStatus), 2u) << nav.output();
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
  stop_feed = true;
  feed.join();
  writer = io::UniqueFd();
  nav.send(SIGTERM);
  EXPECT_EQ(nav.wait_exit(kTimeoutMs), std::optional<int>(0)) << nav.output();

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

}  // namespace
}  // namespace navfuse::test
