// A correction source for one client at a time, on a loopback port the test owns: an NTRIP 2.0
// caster (chunked data), an NTRIP 1.0 caster, or a raw TCP source. With `require_gga`, a
// network-RTK (VRS) caster: it answers the request, then sends no data until the client has
// reported its position in a valid NMEA GGA sentence (2.0: the Ntrip-GGA header or a line sent
// upstream; 1.0 and raw TCP: a line), and keeps every GGA it is sent, with its arrival time.
#pragma once

#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "tests/integration/pty_device.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {

enum class Protocol { kNtrip2, kNtrip1, kRawTcp };

inline constexpr const char* kCasterMount = "RTCM3_TEST";
// base64("navfuse:s3cret"), worked out apart from navfuse (RFC 4648).
inline constexpr const char* kCasterAuthorization = "Authorization: Basic bmF2ZnVzZTpzM2NyZXQ=\r\n";

// Bytes standing in for an RTCM stream: every byte value, in an order that is not a pattern a
// forwarder could get right by accident (a linear congruential sequence).
inline std::vector<std::uint8_t> correction_bytes(std::size_t n) {
  std::vector<std::uint8_t> v(n);
  std::uint32_t x = 12345;
  for (auto& b : v) {
    x = x * 1103515245u + 12345u;
    b = static_cast<std::uint8_t>(x >> 16);
  }
  return v;
}

inline bool send_all(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::send(fd, p, size, MSG_NOSIGNAL);
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// NMEA 0183 GGA sentence, without its line end: "$..GGA," ... "*" and two upper-case hex digits,
// the XOR of the characters between '$' and '*'.
inline bool valid_gga(const std::string& line) {
  if (line.size() < 10 || line[0] != '$' || line.compare(3, 4, "GGA,") != 0) return false;
  const std::size_t star = line.rfind('*');
  if (star == std::string::npos || star + 3 != line.size()) return false;
  unsigned x = 0;
  for (std::size_t i = 1; i < star; ++i) x ^= static_cast<unsigned char>(line[i]);
  char hex[3];
  std::snprintf(hex, sizeof hex, "%02X", x);
  return line.compare(star + 1, 2, hex) == 0;
}

class TinyCaster {
 public:
  struct Gga {
    std::string sentence;  // without CR LF
    std::chrono::steady_clock::time_point received;
    bool in_header = false;  // NTRIP 2.0 Ntrip-GGA
  };

  TinyCaster(Protocol protocol, std::vector<std::uint8_t> data, bool require_gga = false)
      : protocol_(protocol), data_(std::move(data)), require_gga_(require_gga) {
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
  std::vector<Gga> ggas() {
    std::lock_guard lock(mutex_);
    return ggas_;
  }
  // Upstream lines that were not valid GGA sentences.
  std::vector<std::string> bad_lines() {
    std::lock_guard lock(mutex_);
    return bad_lines_;
  }
  // Data bytes sent to the client before it had sent a valid GGA (require_gga only; must stay 0).
  std::size_t sent_before_gga() const { return sent_before_gga_; }

 private:
  void serve() {
    while (!stop_) {
      pollfd p{listener_.get(), POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      io::UniqueFd client(::accept4(listener_.get(), nullptr, nullptr, SOCK_CLOEXEC));
      if (client) answer(client.get());
    }
  }

  // Reads what the client sent within timeout_ms into upstream_ and takes each complete line.
  void read_upstream(int fd, int timeout_ms) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return;
    char buf[1024];
    const ssize_t n = ::recv(fd, buf, sizeof buf, MSG_DONTWAIT);
    if (n > 0) upstream_.append(buf, static_cast<std::size_t>(n));
    take_lines();
  }

  void take_lines() {
    for (auto end = upstream_.find("\r\n"); end != std::string::npos; end = upstream_.find("\r\n")) {
      std::string line = upstream_.substr(0, end);
      upstream_.erase(0, end + 2);
      take_gga(std::move(line), false);
    }
  }

  void take_gga(std::string line, bool in_header) {
    std::lock_guard lock(mutex_);
    if (valid_gga(line)) {
      ggas_.push_back({std::move(line), std::chrono::steady_clock::now(), in_header});
    } else {
      bad_lines_.push_back(std::move(line));
    }
  }

  bool have_gga() {
    std::lock_guard lock(mutex_);
    return !ggas_.empty();
  }

  void send_data(int fd, const std::uint8_t* data, std::size_t n) {
    if (require_gga_ && !have_gga()) sent_before_gga_ += n;
    send_all(fd, data, n);
  }

  void answer(int fd) {
    std::string request;
    const io::Deadline deadline(10000);
    while (protocol_ != Protocol::kRawTcp && request.find("\r\n\r\n") == std::string::npos && !deadline.expired()) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      char buf[1024];
      const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
      if (n <= 0) return;
      request.append(buf, static_cast<std::size_t>(n));
    }
    const auto head_end = request.find("\r\n\r\n");
    if (head_end != std::string::npos) {
      upstream_ = request.substr(head_end + 4);  // NTRIP 1.0: the GGA may follow the request at once
      request.resize(head_end + 4);
    }
    {
      std::lock_guard lock(mutex_);
      request_ = request;
    }
    const bool right_mount = request.starts_with(std::string("GET /") + kCasterMount + " ");
    const bool authorized = request.find(kCasterAuthorization) != std::string::npos;
    if (protocol_ != Protocol::kRawTcp && (!right_mount || !authorized)) {
      const std::string no = !right_mount ? "SOURCETABLE 200 OK\r\nContent-Type: text/plain\r\n\r\nENDSOURCETABLE\r\n"
                                          : "HTTP/1.1 401 Unauthorized\r\n\r\n";
      send_all(fd, no.data(), no.size());
      return;
    }
    if (protocol_ == Protocol::kNtrip2) {
      constexpr std::string_view kHeader = "\r\nNtrip-GGA: ";
      if (const auto at = request.find(kHeader); at != std::string::npos) {
        const auto start = at + kHeader.size();
        take_gga(request.substr(start, request.find("\r\n", start) - start), true);
      }
    }
    if (protocol_ == Protocol::kNtrip1) {
      send_all(fd, "ICY 200 OK\r\n", 12);
    } else if (protocol_ == Protocol::kNtrip2) {
      const std::string ok = "HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nContent-Type: gnss/data\r\n"
                             "Transfer-Encoding: chunked\r\n\r\n";
      send_all(fd, ok.data(), ok.size());
    }
    take_lines();
    // A VRS is computed for where the rover is: nothing until it has said so.
    while (require_gga_ && !have_gga() && !stop_) read_upstream(fd, 50);
    constexpr std::size_t kPieces[] = {1, 17, 300, 1024, 5, 700};
    std::size_t at = 0;
    for (std::size_t k = 0; at < data_.size() && !stop_; ++k) {
      const std::size_t n = std::min(kPieces[k % std::size(kPieces)], data_.size() - at);
      if (protocol_ == Protocol::kNtrip2) {
        char size[32];
        const int len = std::snprintf(size, sizeof size, "%zx\r\n", n);
        send_all(fd, size, static_cast<std::size_t>(len));
      }
      send_data(fd, data_.data() + at, n);
      if (protocol_ == Protocol::kNtrip2) send_all(fd, "\r\n", 2);
      at += n;
      read_upstream(fd, 5);
    }
    if (protocol_ == Protocol::kNtrip2) send_all(fd, "0\r\n\r\n", 5);
    // Stay connected, as a caster does, until the test ends, taking the client's GGA updates.
    while (!stop_) read_upstream(fd, 20);
  }

  Protocol protocol_;
  std::vector<std::uint8_t> data_;
  bool require_gga_;
  io::UniqueFd listener_;
  std::uint16_t port_ = 0;
  std::mutex mutex_;
  std::string request_;
  std::vector<Gga> ggas_;
  std::vector<std::string> bad_lines_;
  std::string upstream_;  // caster thread: client bytes not yet a whole line
  std::atomic<std::size_t> sent_before_gga_{0};
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

// What the receiver got on its port within timeout_ms, up to `want` bytes.
inline std::vector<std::uint8_t> receive(PtyDevice& device, std::size_t want, int timeout_ms) {
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

// The --corrections URI of a TinyCaster (`options`: the query, without '?').
inline std::string caster_source(Protocol protocol, std::uint16_t port, const std::string& mount,
                                 const std::string& options = "") {
  const std::string at = "127.0.0.1:" + std::to_string(port);
  std::string query = protocol == Protocol::kNtrip1 ? "version=1" : "";
  if (!options.empty()) query += (query.empty() ? "" : "&") + options;
  const std::string q = query.empty() ? "" : "?" + query;
  if (protocol == Protocol::kRawTcp) return "tcp://" + at + q;
  return "ntrip://navfuse:s3cret@" + at + "/" + mount + q;
}

inline std::string protocol_name(Protocol p) {
  switch (p) {
    case Protocol::kNtrip2: return "Ntrip2";
    case Protocol::kNtrip1: return "Ntrip1";
    case Protocol::kRawTcp: return "RawTcp";
  }
  return "";
}

}  // namespace navfuse::test
