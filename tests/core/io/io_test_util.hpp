// Helpers shared by the transport tests: bounded reads and raw loopback sockets.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "core/io/transport.hpp"
#include "core/io/unique_fd.hpp"

namespace navfuse::io::test {

inline std::span<const std::uint8_t> bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// Reads from `t` until `n` bytes arrived or `timeout_ms` passed; returns what arrived.
inline std::string read_n(Transport& t, std::size_t n, int timeout_ms = 3000,
                          PeerId* from = nullptr) {
  const Deadline deadline(timeout_ms);
  std::string out;
  std::uint8_t buf[4096];
  while (out.size() < n && !deadline.expired()) {
    PeerId peer = kNoPeer;
    const std::ptrdiff_t got = t.read_from(std::span(buf, std::min(sizeof buf, n - out.size())),
                                           deadline.remaining_ms(), peer);
    if (got == kEndOfStream) break;
    if (got > 0) {
      out.append(reinterpret_cast<const char*>(buf), static_cast<std::size_t>(got));
      if (from) *from = peer;
    }
  }
  return out;
}

// Reads `n` bytes from a raw descriptor (poll + read), bounded by `timeout_ms`.
inline std::string read_fd(int fd, std::size_t n, int timeout_ms = 3000) {
  const Deadline deadline(timeout_ms);
  std::string out;
  char buf[4096];
  while (out.size() < n && !deadline.expired()) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, deadline.remaining_ms()) <= 0) continue;
    const ssize_t got = ::read(fd, buf, std::min(sizeof buf, n - out.size()));
    if (got <= 0) break;
    out.append(buf, static_cast<std::size_t>(got));
  }
  return out;
}

inline sockaddr_in loopback(std::uint16_t port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return a;
}

// A blocking TCP connection to 127.0.0.1:port; `rcvbuf` > 0 shrinks the receive buffer first
// (before connect, so the advertised window is small too).
inline UniqueFd connect_loopback(std::uint16_t port, int rcvbuf = 0) {
  UniqueFd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (rcvbuf > 0) ::setsockopt(fd.get(), SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
  const sockaddr_in a = loopback(port);
  if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) fd.reset();
  return fd;
}

// A port on 127.0.0.1 that nothing listens on (bound, then released).
inline std::uint16_t unused_port() {
  UniqueFd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  sockaddr_in a = loopback(0);
  ::bind(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  ::getsockname(fd.get(), reinterpret_cast<sockaddr*>(&a), &len);
  return ntohs(a.sin_port);
}

}  // namespace navfuse::io::test
