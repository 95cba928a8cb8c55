// `navfuse run --corrections`: RTK corrections from a caster the test runs (NTRIP 2.0 with
// chunked data, NTRIP 1.0, raw TCP) reach the receiver's serial port, a pseudo-terminal here,
// byte for byte; a caster that refuses (unknown mountpoint) is reported with its reason and
// nothing reaches the receiver.
#include <gtest/gtest.h>
#include <signal.h>

#include <nlohmann/json.hpp>

#include "tests/integration/child_process.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/test_paths.hpp"
#include "tests/integration/tiny_caster.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 10000;
constexpr const char* kMount = kCasterMount;

class CorrectionsTest : public ScratchDirTest {};

class RunCorrectionsTest : public CorrectionsTest, public ::testing::WithParamInterface<Protocol> {};

TEST_P(RunCorrectionsTest, ReachTheReceiversPortUnchanged) {
  const std::vector<std::uint8_t> data = correction_bytes(6000);
  TinyCaster caster(GetParam(), data);
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\n");
  const std::string summary = (dir_ / "summary.json").string();
  PtyDevice receiver((dir_ / "ttyRX").string());
  // Input 1 is the receiver; input 0 is another device (a TCP port nobody feeds).
  ChildProcess nav({navfuse_binary(), "run", "--config", config, "--in",
                    "vn:tcp-listen://127.0.0.1:" + std::to_string(free_port(SOCK_STREAM)), "--in",
                    "vn:serial:" + receiver.link() + "?baud=115200", "--corrections",
                    caster_source(GetParam(), caster.port(), kMount), "--corrections-to", "1", "--summary-json", summary},
                   (dir_ / "nav.log").string());
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  receiver.release_slave();
  const std::vector<std::uint8_t> got = receive(receiver, data.size(), kTimeoutMs);
  EXPECT_EQ(got.size(), data.size()) << nav.output();
  EXPECT_TRUE(got == data) << "the corrections changed on the way";
  if (GetParam() == Protocol::kNtrip2) {
    EXPECT_NE(caster.request().find("Ntrip-Version: Ntrip/2.0\r\n"), std::string::npos) << caster.request();
  }
  if (GetParam() == Protocol::kNtrip1) {
    EXPECT_TRUE(caster.request().starts_with(std::string("GET /") + kMount + " HTTP/1.0\r\n")) << caster.request();
  }
  nav.send(SIGTERM);
  ASSERT_EQ(nav.wait_exit(kTimeoutMs).value_or(-1), 0) << nav.output();
  const auto j = nlohmann::json::parse(read_text_file(summary));
  EXPECT_EQ(j["corrections"]["bytes_forwarded"].get<std::size_t>(), data.size()) << j.dump();
  // The password never appears in what navfuse prints or writes.
  EXPECT_EQ(nav.output().find("s3cret"), std::string::npos) << nav.output();
  EXPECT_EQ(j.dump().find("s3cret"), std::string::npos) << j.dump();
}

INSTANTIATE_TEST_SUITE_P(Sources, RunCorrectionsTest,
                         ::testing::Values(Protocol::kNtrip2, Protocol::kNtrip1, Protocol::kRawTcp),
                         [](const auto& info) { return protocol_name(info.param); });

TEST_F(CorrectionsTest, UnknownMountpointIsReportedAndNothingIsForwarded) {
  TinyCaster caster(Protocol::kNtrip2, correction_bytes(100));
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\n");
  PtyDevice receiver((dir_ / "ttyRX").string());
  ChildProcess nav({navfuse_binary(), "run", "--config", config, "--in", "vn:serial:" + receiver.link(), "--corrections",
                    caster_source(Protocol::kNtrip2, caster.port(), "NO_SUCH_MOUNT")},
                   (dir_ / "nav.log").string());
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  receiver.release_slave();
  EXPECT_TRUE(nav.wait_for_output("no mountpoint 'NO_SUCH_MOUNT'", kTimeoutMs)) << nav.output();
  EXPECT_TRUE(receive(receiver, 1, 500).empty());
  nav.send(SIGTERM);
  EXPECT_EQ(nav.wait_exit(kTimeoutMs).value_or(-1), 0) << nav.output();
}

}  // namespace
}  // namespace navfuse::test
