// UDP transport. One datagram per read() and per write(): datagram boundaries are kept, so a
// device that sends one message per datagram is framed by the network.
//
//  - Sender (udp://HOST:PORT): write() sends to HOST:PORT; read() returns datagrams arriving at
//    the socket's own (ephemeral) port, i.e. replies.
//  - Listener (udp://:PORT, udp-listen://[HOST]:PORT): binds and receives from anyone;
//    read_from() names the sender as a PeerId, write_to(peer) answers it and write() answers
//    the most recent sender (dropped if nobody has sent yet). The last 64 senders are
//    remembered.
// UDP has no connection to lose: reconnects stays 0. A datagram larger than the read buffer is
// truncated (counted as an error); size read buffers for the largest message (<= 65507 bytes).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/io/socket_address.hpp"
#include "core/io/transport.hpp"
#include "core/io/unique_fd.hpp"

namespace navfuse::io {

struct UdpOptions {
  std::string host;        // sender: destination; listener: address to bind ("" = all IPv4)
  std::uint16_t port = 0;  // listener: 0 = ephemeral (see local_port())
  bool listen = false;
};

class UdpSocket : public Transport {
 public:
  // Creates (and for a listener binds) the socket; throws TransportError on failure.
  explicit UdpSocket(UdpOptions options);

  std::ptrdiff_t read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  std::ptrdiff_t read_from(std::span<std::uint8_t> buffer, int timeout_ms, PeerId& from) override;
  std::ptrdiff_t write(std::span<const std::uint8_t> data) override;
  std::ptrdiff_t write_to(PeerId peer, std::span<const std::uint8_t> data) override;
  bool is_open() const override { return static_cast<bool>(fd_); }
  bool reopen() override;
  std::string describe() const override;

  std::uint16_t local_port() const { return local_port_; }

 private:
  struct Peer {
    PeerId id;
    SocketAddress address;
  };

  void open_socket();  // throws TransportError
  std::ptrdiff_t send(const SocketAddress& to, std::span<const std::uint8_t> data);
  PeerId remember(const SocketAddress& sender);
  std::string uri_text() const;

  UdpOptions options_;
  UniqueFd fd_;
  SocketAddress destination_;  // sender mode
  std::uint16_t local_port_ = 0;
  std::vector<Peer> peers_;    // most recent last
  PeerId next_id_ = 1;
};

}  // namespace navfuse::io
