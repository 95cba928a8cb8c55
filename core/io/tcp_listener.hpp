// TCP listener transport: a server socket that accepts several clients, for outputs that many
// consumers tap (e.g. FusionEngine poses to a logger and a display) and for command links.
//
//  - write() sends to every connected client and never waits. A client whose backlog (kernel
//    socket buffer full, plus up to queue_bytes queued here) cannot take the message is
//    disconnected and counted in clients_dropped: one stalled consumer must neither block the
//    navigation process nor receive a stream with holes in it.
//  - read_from() returns bytes from one client at a time with that client's PeerId, so a
//    command can be answered with write_to(peer, reply). Clients are served round-robin.
//  - New clients are accepted inside read(), write() and accept_pending(), so a write-only
//    output needs no extra calls. Clients beyond max_clients are accepted and closed at once.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/io/transport.hpp"
#include "core/io/unique_fd.hpp"
#include "core/io/write_queue.hpp"

namespace navfuse::io {

struct TcpListenerOptions {
  std::string host;          // address to bind; "" = all IPv4 interfaces
  std::uint16_t port = 0;    // 0 = an ephemeral port (see local_port())
  std::size_t max_clients = 16;
  std::size_t queue_bytes = 262144;  // per client, beyond the kernel's socket buffer
};

class TcpListener : public Transport {
 public:
  // Binds and listens now; throws TransportError if that fails (e.g. port in use).
  explicit TcpListener(TcpListenerOptions options);

  std::ptrdiff_t read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  std::ptrdiff_t read_from(std::span<std::uint8_t> buffer, int timeout_ms, PeerId& from) override;
  // Returns data.size() if at least one client took the message, else 0.
  std::ptrdiff_t write(std::span<const std::uint8_t> data) override;
  std::ptrdiff_t write_to(PeerId peer, std::span<const std::uint8_t> data) override;
  bool is_open() const override { return static_cast<bool>(listen_fd_); }
  // Disconnects every client and binds the same port again.
  bool reopen() override;
  std::string describe() const override;

  // The bound port (useful after binding port 0).
  std::uint16_t local_port() const { return local_port_; }
  std::size_t client_count() const { return clients_.size(); }
  // Accepts every connection waiting in the backlog, without blocking.
  void accept_pending();

 private:
  struct Client {
    PeerId id;
    UniqueFd fd;
    WriteQueue queue;
    std::string name;  // "127.0.0.1:40312", for messages
  };

  void listen_now();  // throws TransportError
  void drop(std::size_t index, const std::string& why);
  // Sends to one client; returns false if the client had to be dropped.
  bool send_to(std::size_t index, std::span<const std::uint8_t> data);
  std::string uri_text() const;

  TcpListenerOptions options_;
  UniqueFd listen_fd_;
  std::uint16_t local_port_ = 0;
  std::vector<Client> clients_;
  PeerId next_id_ = 1;
  std::size_t next_reader_ = 0;  // round-robin start for read_from()
};

}  // namespace navfuse::io
