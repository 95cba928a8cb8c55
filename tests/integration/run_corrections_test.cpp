// `navfuse run --corrections`: RTK corrections from a caster the test runs (NTRIP 2.0 with
// chunked data, NTRIP 1.0, raw TCP) reach the receiver's serial port, a pseudo-terminal here,
// byte for byte; a caster that refuses (unknown mountpoint) is reported with its reason and
// nothing reaches the receiver.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>

#include <atomic>
#include <cstdio>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/integration/child_process.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 10000;
constexpr const char* kMount = "RTCM3_TEST";
// base64("navfuse:s3cret"), worked out apart from navfuse (RFC 4648).
constexpr const char* kAuthorization = "Authorization: Basic bmF2ZnVzZTpzM2NyZXQ=\r\n";

enum class Protocol { kNtrip2, kNtrip1, kRawTcp };

// Bytes standing in for an RTCM stream: every byte value, in an order that is not a pattern a
// forwarder could get right by accident (a linear congruential sequence).
std::vector<std::uint8_t> correction_bytes(std::size_t n) {
  std::vector<std::uint8_t> v(n);
  std::uint32_t x = 12345;
  for (auto& b : v) {
    x = x * 1103515245u + 12345u;
    b = static_cast<std::uint8_t>(x >> 16);
  }
  return v;
}

bool send_all(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::send(fd, p, size, MSG_NOSIGNAL);
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// A caster for one client: reads the request, answers as `protocol` does, then sends `data` in
// pieces of a few sizes (NTRIP 2.0: each piece one HTTP chunk), a little apart in time.
class TinyCaster {
 public:
  TinyCaster(Protocol protocol, std::vector<std::uint8_t> data) : protocol_(protocol), data_(std::move(data)) {
    listener_.reset(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const int one = 1;
    ::setsockopt(listener_.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    ::bind(listener_.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a);
    ::listen(listener_.get(), 4);
    socklen_t len = sizeof a;
    ::getsockname(listener_.get(), reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] { serve(); });
  }
  ~TinyCaster() {
    stop_ = true;
    thread_.join();
  }
  std::uint16_t port() const { return port_; }
  std::string request() {
    std::lock_guard lock(mutex_);
    return request_;
  }

 private:
  void serve() {
    while (!stop_) {
      pollfd p{listener_.get(), POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      io::UniqueFd client(::accept4(listener_.get(), nullptr, nullptr, SOCK_CLOEXEC));
      if (client) answer(client.get());
    }
  }

  void answer(int fd) {
    std::string request;
    const io::Deadline deadline(kTimeoutMs);
    while (protocol_ != Protocol::kRawTcp && request.find("\r\n\r\n") == std::string::npos && !deadline.expired()) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      char buf[1024];
      const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
      if (n <= 0) return;
      request.append(buf, static_cast<std::size_t>(n));
    }
    {
      std::lock_guard lock(mutex_);
      request_ = request;
    }
    const bool right_mount = request.starts_with(std::string("GET /") + kMount + " ");
    const bool authorized = request.find(kAuthorization) != std::string::npos;
    if (protocol_ != Protocol::kRawTcp && (!right_mount || !authorized)) {
      const std::string no = !right_mount ? "SOURCETABLE 200 OK\r\nContent-Type: text/plain\r\n\r\nENDSOURCETABLE\r\n"
                                          : "HTTP/1.1 401 Unauthorized\r\n\r\n";
      send_all(fd, no.data(), no.size());
      return;
    }
    if (protocol_ == Protocol::kNtrip1) {
      send_all(fd, "ICY 200 OK\r\n", 12);
    } else if (protocol_ == Protocol::kNtrip2) {
      const std::string ok = "HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nContent-Type: gnss/data\r\n"
                             "Transfer-Encoding: chunked\r\n\r\n";
      send_all(fd, ok.data(), ok.size());
    }
    constexpr std::size_t kPieces[] = {1, 17, 300, 1024, 5, 700};
    std::size_t at = 0;
    for (std::size_t k = 0; at < data_.size() && !stop_; ++k) {
      const std::size_t n = std::min(kPieces[k % std::size(kPieces)], data_.size() - at);
      if (protocol_ == Protocol::kNtrip2) {
        char size[32];
        const int len = std::snprintf(size, sizeof size, "%zx\r\n", n);
        send_all(fd, size, static_cast<std::size_t>(len));
      }
      send_all(fd, data_.data() + at, n);
      if (protocol_ == Protocol::kNtrip2) send_all(fd, "\r\n", 2);
      at += n;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (protocol_ == Protocol::kNtrip2) send_all(fd, "0\r\n\r\n", 5);
    // Stay connected, as a caster does, until the test ends.
    while (!stop_) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }

  Protocol protocol_;
  std::vector<std::uint8_t> data_;
  io::UniqueFd listener_;
  std::uint16_t port_ = 0;
  std::mutex mutex_;
  std::string request_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

// What the receiver got on its port within timeout_ms, up to `want` bytes.
std::vector<std::uint8_t> receive(PtyDevice& device, std::size_t want, int timeout_ms) {
  std::vector<std::uint8_t> got;
  const io::Deadline deadline(timeout_ms);
  while (got.size() < want && !deadline.expired()) {
    pollfd p{device.master(), POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    std::uint8_t buf[4096];
    const ssize_t n = ::read(device.master(), buf, sizeof buf);
    if (n > 0) got.insert(got.end(), buf, buf + n);
  }
  return got;
}

class CorrectionsTest : public ScratchDirTest {
 protected:

  std::string source(Protocol protocol, std::uint16_t port, const std::string& mount) const {
    const std::string at = "127.0.0.1:" + std::to_string(port);
    switch (protocol) {
      case Protocol::kNtrip2: return "ntrip://navfuse:s3cret@" + at + "/" + mount;
      case Protocol::kNtrip1: return "ntrip://navfuse:s3cret@" + at + "/" + mount + "?version=1";
      case Protocol::kRawTcp: return "tcp://" + at;
    }
    return "";
  }
};

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
                    source(GetParam(), caster.port(), kMount), "--corrections-to", "1", "--summary-json", summary},
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
                         [](const auto& info) {
                           switch (info.param) {
                             case Protocol::kNtrip2: return std::string("Ntrip2");
                             case Protocol::kNtrip1: return std::string("Ntrip1");
                             case Protocol::kRawTcp: return std::string("RawTcp");
                           }
                           return std::string();
                         });

TEST_F(CorrectionsTest, UnknownMountpointIsReportedAndNothingIsForwarded) {
  TinyCaster caster(Protocol::kNtrip2, correction_bytes(100));
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\n");
  PtyDevice receiver((dir_ / "ttyRX").string());
  ChildProcess nav({navfuse_binary(), "run", "--config", config, "--in", "vn:serial:" + receiver.link(), "--corrections",
                    source(Protocol::kNtrip2, caster.port(), "NO_SUCH_MOUNT")},
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
