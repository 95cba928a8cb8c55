// Socket addresses: name resolution for the tcp/udp transports and printing for messages.
#pragma once

#include <sys/socket.h>

#include <cstdint>
#include <string>
#include <vector>

namespace navfuse::io {

struct SocketAddress {
  sockaddr_storage storage{};
  socklen_t length = 0;

  const sockaddr* get() const { return reinterpret_cast<const sockaddr*>(&storage); }
  sockaddr* get() { return reinterpret_cast<sockaddr*>(&storage); }
  int family() const { return storage.ss_family; }
  std::uint16_t port() const;
  bool operator==(const SocketAddress& other) const;
};

// Resolves HOST:PORT with getaddrinfo(3) (numeric port). `passive` with an empty host gives the
// wildcard address for bind(2); an empty host without `passive` is an error. `socktype` is
// SOCK_STREAM or SOCK_DGRAM. Throws TransportError naming `uri_text` when nothing resolves.
// Note: resolving a name may consult DNS; numeric addresses and /etc/hosts names do not.
std::vector<SocketAddress> resolve(const std::string& host, std::uint16_t port, int socktype,
                                   bool passive, const std::string& uri_text);

// "127.0.0.1:5000" / "[::1]:5000".
std::string to_string(const SocketAddress& address);

}  // namespace navfuse::io
