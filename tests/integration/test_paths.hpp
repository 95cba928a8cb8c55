// Where the integration tests find the navfuse binary and put their scratch files, and ports
// that do not collide with other test processes running at the same time on this machine.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/unique_fd.hpp"

namespace navfuse::test {

inline std::string navfuse_binary() { return NAVFUSE_BINARY; }

// A fresh directory for the current test (removed by the fixture that made it).
inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::temp_directory_path() /
             ("navfuse_it_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A fixture whose tests each get a fresh scratch_dir() in dir_, removed afterwards.
class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_dir(); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

inline std::string write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

// An LCM multicast URL private to this process and `salt`: loopback only (ttl=0), on a port
// derived from the pid, so concurrent test runs (other build trees, other tests) never hear
// each other.
inline std::string private_lcm_url(int salt) {
  const int port = 20000 + static_cast<int>((static_cast<unsigned>(::getpid()) * 16u + static_cast<unsigned>(salt)) % 40000u);
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

// A port the kernel just handed out for `type` (SOCK_STREAM / SOCK_DGRAM) on loopback, free
// again when this returns: for a child process to bind.
inline std::uint16_t free_port(int type) {
  const int fd = ::socket(AF_INET, type | SOCK_CLOEXEC, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  ::close(fd);
  return ntohs(a.sin_port);
}

// A TCP connection to 127.0.0.1:port, retried up to timeout_ms while the listener comes up;
// an empty fd when none was made.
inline io::UniqueFd connect_loopback(std::uint16_t port, int timeout_ms) {
  const io::Deadline deadline(timeout_ms);
  while (!deadline.expired()) {
    io::UniqueFd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return fd;
    ::usleep(20'000);
  }
  return io::UniqueFd();
}

// The cells of the last non-empty line of a CSV file (no quoting: navfuse's CSVs have none).
inline std::vector<std::string> last_csv_row(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  std::vector<std::string> cells;
  std::stringstream ss(last);
  for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
  return cells;
}

}  // namespace navfuse::test
